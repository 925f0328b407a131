// The keyword arguments `Session.render` and `Session.compare` share, read into the
// renderer's RenderSpec (render/render_spec.h): the Python forms of the command line's
// --size, --camera/--eye/--target/--fov, --aov and --param. Only the shapes are checked
// here (TypeError); the values are checked by makeRenderRequest, as for the command line.
#pragma once

#include "render/render_spec.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace vct::python {

// 256 or (width, height).
void readSize(const pybind11::object& size, RenderSpec& spec);
// None (the file's first camera, else a framing of the scene), a camera's name or index, or
// a dict with eye and target (3 numbers each) and/or fov (degrees).
CameraRequest readCamera(const pybind11::object& camera);
// None (beauty), one name, or a list of names.
std::vector<std::string> readAovs(const pybind11::object& aovs);
// None, a dict {key: value} (bools as 1/0, numbers and strings by str()), or a list of
// "KEY=VALUE" strings: the --param arguments.
std::vector<std::string> readParams(const pybind11::object& params);

}  // namespace vct::python
