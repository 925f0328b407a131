#include "python/render_arguments.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <climits>

namespace py = pybind11;

namespace vct::python {

namespace {

bool isInteger(const py::handle& h) { return py::isinstance<py::int_>(h) && !py::isinstance<py::bool_>(h); }

// Out-of-range Python integers keep their sign, so the range check that follows names them.
int clampedInt(const py::handle& h) {
    const long long v = h.cast<long long>();
    return int(std::clamp<long long>(v, INT_MIN, INT_MAX));
}

glm::vec3 readVec3(const py::handle& value, const std::string& what) {
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 3)
        throw py::type_error("camera " + what + ": expected 3 numbers");
    glm::vec3 v;
    py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    for (int k = 0; k < 3; ++k) {
        if (!py::isinstance<py::float_>(s[k]) && !isInteger(s[k]))
            throw py::type_error("camera " + what + ": expected 3 numbers");
        v[k] = s[k].cast<float>();
    }
    return v;
}

}  // namespace

void readSize(const py::object& size, RenderSpec& spec) {
    if (isInteger(size)) {
        spec.width = spec.height = clampedInt(size);
        return;
    }
    if (py::isinstance<py::tuple>(size) || py::isinstance<py::list>(size)) {
        py::sequence s = size;
        if (py::len(s) == 2 && isInteger(s[0]) && isInteger(s[1])) {
            spec.width = clampedInt(s[0]);
            spec.height = clampedInt(s[1]);
            return;
        }
    }
    throw py::type_error("size: expected an int or (width, height)");
}

CameraRequest readCamera(const py::object& camera) {
    CameraRequest c;
    if (camera.is_none()) return c;
    if (py::isinstance<py::str>(camera)) {
        c.nameOrIndex = camera.cast<std::string>();
        return c;
    }
    if (isInteger(camera)) {
        c.nameOrIndex = py::str(camera).cast<std::string>();
        return c;
    }
    if (!py::isinstance<py::dict>(camera))
        throw py::type_error("camera: expected None, a name, an index or dict(eye=..., target=..., fov=...)");
    py::dict d = camera;
    for (auto item : d) {
        const std::string key = py::str(item.first).cast<std::string>();
        if (key != "eye" && key != "target" && key != "fov")
            throw py::value_error("camera: unknown key '" + key + "' (eye, target, fov)");
    }
    if (d.contains("eye") != d.contains("target"))
        throw py::value_error("--eye and --target go together");
    if (d.contains("eye")) {
        c.hasEye = true;
        c.eye = readVec3(d["eye"], "eye");
        c.target = readVec3(d["target"], "target");
    }
    if (d.contains("fov")) {
        py::object fov = d["fov"];
        if (!py::isinstance<py::float_>(fov) && !isInteger(fov)) throw py::type_error("camera fov: expected a number");
        c.fovDeg = fov.cast<float>();
    }
    return c;
}

std::vector<std::string> readAovs(const py::object& aovs) {
    if (aovs.is_none()) return {};
    if (py::isinstance<py::str>(aovs)) return {aovs.cast<std::string>()};
    try {
        return aovs.cast<std::vector<std::string>>();
    } catch (const py::cast_error&) {
        throw py::type_error("aovs: expected a name or a list of names");
    }
}

std::vector<std::string> readParams(const py::object& params) {
    std::vector<std::string> out;
    if (params.is_none()) return out;
    if (py::isinstance<py::dict>(params)) {
        for (auto item : py::reinterpret_borrow<py::dict>(params)) {
            if (!py::isinstance<py::str>(item.first)) throw py::type_error("params: keys must be strings");
            const py::handle v = item.second;
            const std::string value = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "1" : "0")
                                                                   : py::str(v).cast<std::string>();
            out.push_back(item.first.cast<std::string>() + "=" + value);
        }
        return out;
    }
    if (!py::isinstance<py::str>(params)) {
        try {
            return params.cast<std::vector<std::string>>();
        } catch (const py::cast_error&) {
        }
    }
    throw py::type_error("params: expected a dict {key: value} or a list of \"KEY=VALUE\" strings");
}

}  // namespace vct::python
