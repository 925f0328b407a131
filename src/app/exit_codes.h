// How a failure that reaches the command line is reported: its exit status and the line on
// stderr. Only a UsageError is the user's to fix (exit 2). Everything else exits 1: a runtime
// failure (an unreadable scene, a GL error, a device limit) says "vct: error:", the program's
// own fault says "internal error" and asks to be reported. That includes any std::logic_error
// that is not a UsageError, such as a std::invalid_argument from std::stoi inside the program,
// so a bug is never blamed on the command line.
#pragma once

#include "core/errors.h"

#include <exception>
#include <stdexcept>
#include <string>

namespace vct {

inline int exitCodeFor(const std::exception& e) { return dynamic_cast<const UsageError*>(&e) ? 2 : 1; }

// The line to print on stderr (without the newline).
inline std::string errorLineFor(const std::exception& e) {
    if (dynamic_cast<const UsageError*>(&e)) return std::string("vct: error: ") + e.what();
    // InternalError's message starts with "internal error in <where>: ".
    if (dynamic_cast<const InternalError*>(&e)) return std::string("vct: ") + e.what() + " (please report it)";
    if (dynamic_cast<const std::logic_error*>(&e))
        return std::string("vct: internal error: ") + e.what() + " (please report it)";
    return std::string("vct: error: ") + e.what();
}

}  // namespace vct
