#include "support/filter_precision.h"

#include "gl/context.h"

namespace vcttest {

bool filtersInFloat() { return vct::GlContext::shared().info().softwareRenderer; }

double filterTolerance(double inFloat, double onHardware) { return filtersInFloat() ? inFloat : onHardware; }

}  // namespace vcttest
