// peakResidentBytes against the kernel's own record of the same counter (/proc/self/status,
// VmHWM) and against an allocation that must raise it.
#include "core/memory_usage.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vct {
namespace {

// A "VmHWM:" / "VmRSS:" line of /proc/self/status, in bytes (the file gives kB).
size_t procStatusBytes(const std::string& key) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key + ":", 0) == 0) {
            std::istringstream fields(line.substr(key.size() + 1));
            size_t kb = 0;
            fields >> kb;
            return kb * 1024;
        }
    return 0;
}

TEST(MemoryUsage, PeakIsTheKernelsHighWaterMarkAndRisesWithTouchedMemory) {
    const size_t hwm = procStatusBytes("VmHWM");
    ASSERT_GT(hwm, 0u) << "/proc/self/status has no VmHWM";
    const size_t before = peakResidentBytes();
    EXPECT_NEAR(double(before), double(hwm), 4.0 * 1024 * 1024);

    // Touch enough to go 64 MiB past the old peak from where the resident set is now.
    const size_t extra = size_t(64) << 20, resident = procStatusBytes("VmRSS");
    const size_t need = (before > resident ? before - resident : 0) + extra;
    ASSERT_LT(need, size_t(2) << 30) << "the test process already holds gigabytes it has since freed";
    std::vector<unsigned char> block(need, 1);
    size_t sum = 0;
    for (size_t i = 0; i < block.size(); i += 4096) sum += block[i];
    EXPECT_EQ(sum, (need + 4095) / 4096);
    const size_t after = peakResidentBytes();
    EXPECT_GE(after, before + extra - (size_t(4) << 20));
    EXPECT_NEAR(double(after), double(procStatusBytes("VmHWM")), 4.0 * 1024 * 1024);
}

}  // namespace
}  // namespace vct
