#include "python/convert.h"

#include <cstring>

namespace py = pybind11;

namespace vct::python {

py::object toPython(const nlohmann::json& value) {
    switch (value.type()) {
    case nlohmann::json::value_t::null: return py::none();
    case nlohmann::json::value_t::boolean: return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(value.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(value.get<uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(value.get<double>());
    case nlohmann::json::value_t::string: return py::str(value.get<std::string>());
    case nlohmann::json::value_t::array: {
        py::list list;
        for (const auto& item : value) list.append(toPython(item));
        return std::move(list);
    }
    case nlohmann::json::value_t::object: {
        py::dict dict;
        for (auto it = value.begin(); it != value.end(); ++it) dict[py::str(it.key())] = toPython(it.value());
        return std::move(dict);
    }
    default: return py::none();  // binary and discarded values: never in the renderer's documents
    }
}

py::array_t<float> toArray(const Image& image) {
    std::vector<py::ssize_t> shape{image.height, image.width};
    if (image.channels != 1) shape.push_back(image.channels);
    py::array_t<float> array(shape);
    std::memcpy(array.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return array;
}

Image toImage(const py::handle& object, const std::string& what) {
    auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!array) throw py::type_error(what + ": expected an array of numbers");
    if (array.ndim() != 2 && array.ndim() != 3)
        throw py::value_error(what + ": expected an HxW or HxWxC array, got " + std::to_string(array.ndim()) +
                              " dimensions");
    Image image(int(array.shape(1)), int(array.shape(0)), array.ndim() == 3 ? int(array.shape(2)) : 1);
    if (image.pixels.empty()) throw py::value_error(what + ": the array is empty");
    std::memcpy(image.pixels.data(), array.data(), image.pixels.size() * sizeof(float));
    return image;
}

}  // namespace vct::python
