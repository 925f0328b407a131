// Runs after every other test (ctest fixture cleanup): each program that a test compiled
// (the program cache appends its key to $VCT_PROGRAM_LOG) must be one the renderer's list
// of variants names, so the limits test (tests/gpu/program_limits_test.cpp) has inspected
// every program the suite exercised.
#include "gl/program_cache.h"
#include "render/program_list.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

TEST(ProgramLog, EveryCompiledProgramIsListed) {
    const char* path = std::getenv(vct::kProgramLogVariable);
    if (!path) GTEST_SKIP() << vct::kProgramLogVariable << " is not set (run through ctest)";
    std::ifstream in(path);
    if (!in) GTEST_SKIP() << "no program was compiled by the tests that ran (" << path << " absent)";
    std::set<std::string> listed;
    for (const vct::ProgramKey& k : vct::rendererProgramVariants()) listed.insert(k.id());
    std::set<std::string> compiled;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) compiled.insert(line);
    ASSERT_FALSE(compiled.empty()) << path << " is empty";
    for (const std::string& id : compiled)
        EXPECT_TRUE(listed.count(id)) << "compiled during the tests but missing from rendererProgramVariants(): " << id;
    std::printf("program log: %zu distinct programs compiled, all listed among %zu variants\n", compiled.size(),
                listed.size());
}
