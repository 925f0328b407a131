// The benches' entry point: whatever a bench's body throws (a bad --param, an unreadable
// scene, a device limit) ends as one line naming the bench and an exit status, 2 for a
// UsageError (the command line's to fix) and 1 otherwise (app/exit_codes.h), never as an
// uncaught exception.
#pragma once

#include "app/exit_codes.h"

#include <cstdio>
#include <exception>

namespace vct {

inline int benchMain(const char* name, int (*body)(int, char**), int argc, char** argv) {
    try {
        return body(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", name, e.what());
        return exitCodeFor(e);
    }
}

}  // namespace vct
