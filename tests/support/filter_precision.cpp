#include "support/filter_precision.h"

#include "gl/context.h"

namespace vcttest {

bool filtersInFloat() {
    const std::string& r = vct::GlContext::shared().info().renderer;
    return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
}

double filterTolerance(double inFloat, double onHardware) { return filtersInFloat() ? inFloat : onHardware; }

}  // namespace vcttest
