// The parts of the `vct` module, each added by its own file (module.cpp calls them).
#pragma once

#include <pybind11/pybind11.h>

namespace vct::python {

void bindSession(pybind11::module_& m);   // vct.Session (session.cpp)
void bindRegistry(pybind11::module_& m);  // vct.methods(), vct.settings(), vct.aovs() (registry.cpp)
void bindMetrics(pybind11::module_& m);   // vct.metrics (metrics.cpp)

}  // namespace vct::python
