// The two kinds of failure, never mixed:
// - UsageError: what the user got wrong (an option, a parameter, an AOV, a file name); the
//   message names the option or file, and the command line exits with 2.
// - InternalError: a contract between parts of the program broken (a pass handed a grid
//   without textures, a method asked for a resource nobody writes); the message says
//   "internal error" and names the pass, and the command line exits with 1.
// Runtime failures the user cannot fix by changing the command (an unreadable scene, a GL
// error, a device too small) stay std::runtime_error, exit 1.
#pragma once

#include <stdexcept>
#include <string>

namespace vct {

struct UsageError : std::invalid_argument {
    explicit UsageError(const std::string& what) : std::invalid_argument(what) {}
};

struct InternalError : std::logic_error {
    // `where`: the pass or function whose contract broke.
    InternalError(const std::string& where, const std::string& what)
        : std::logic_error("internal error in " + where + ": " + what), detail(what) {}
    // The message without "internal error in <where>": for a binding whose caller supplied the
    // data whose contract broke, and which reports it as the caller's error.
    std::string detail;
};

}  // namespace vct
