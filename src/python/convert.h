// Values between the renderer and Python: JSON documents (stats, comparison results) as
// dicts and lists, images as NumPy float32 arrays (HxW for one channel, HxWxC otherwise,
// top row first as the renderer stores them). Call with the GIL held.
#pragma once

#include "image/image.h"

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace vct::python {

pybind11::object toPython(const nlohmann::json& value);

pybind11::array_t<float> toArray(const Image& image);

// An HxW or HxWxC array of numbers (bools and integers are converted to float) as an Image;
// `what` names the argument in the ValueError for any other shape.
Image toImage(const pybind11::handle& array, const std::string& what);

}  // namespace vct::python
