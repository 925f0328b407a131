#include "core/memory_usage.h"

#include <sys/resource.h>

namespace vct {

size_t peakResidentBytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0 || usage.ru_maxrss <= 0) return 0;
    return size_t(usage.ru_maxrss) * 1024;  // Linux reports kibibytes
}

}  // namespace vct
