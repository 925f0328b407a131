// The command line's report of a failure: only the user's mistakes exit 2.
#include "app/exit_codes.h"
#include "core/errors.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>

namespace vct {
namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

TEST(ExitCodes, UsageErrorIsTheUsersToFix) {
    const UsageError e("--radius must be finite and > 0");
    EXPECT_EQ(exitCodeFor(e), 2);
    EXPECT_EQ(errorLineFor(e), "vct: error: --radius must be finite and > 0");
}

TEST(ExitCodes, InternalErrorSaysSoAndExits1) {
    const InternalError e("coneTraceAO", "radius -1 must be finite and >= 0");
    EXPECT_EQ(std::string(e.what()), "internal error in coneTraceAO: radius -1 must be finite and >= 0");
    EXPECT_EQ(exitCodeFor(e), 1);
    const std::string line = errorLineFor(e);
    EXPECT_TRUE(startsWith(line, "vct: internal error in coneTraceAO: radius -1")) << line;
    EXPECT_NE(line.find("please report"), std::string::npos) << line;
}

TEST(ExitCodes, RuntimeErrorExits1) {
    const std::runtime_error e("scenes/x.gltf: file is empty");
    EXPECT_EQ(exitCodeFor(e), 1);
    EXPECT_EQ(errorLineFor(e), "vct: error: scenes/x.gltf: file is empty");
    EXPECT_EQ(exitCodeFor(std::bad_alloc()), 1);
}

// A std::invalid_argument that is not a UsageError comes from inside the program (std::stoi,
// a forgotten conversion): a bug, not the user's mistake.
TEST(ExitCodes, BareInvalidArgumentIsInternal) {
    const std::invalid_argument e("stoi");
    EXPECT_EQ(exitCodeFor(e), 1);
    const std::string line = errorLineFor(e);
    EXPECT_TRUE(startsWith(line, "vct: internal error: stoi")) << line;
    EXPECT_EQ(exitCodeFor(std::out_of_range("map::at")), 1);
}

}  // namespace
}  // namespace vct
