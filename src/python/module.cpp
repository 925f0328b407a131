// The `vct` Python module: the renderer for notebooks and scripts, beside the command line
// on top of the same renderer (src/render), the registry and the research layer (src/eval).
#include "app/exit_codes.h"
#include "python/bindings.h"
#include "python/gl_scope.h"

#include <exception>
#include <new>
#include <stdexcept>

namespace py = pybind11;

namespace {

// The command line's two exit codes (app/exit_codes.h) as Python's exception types: what the
// user got wrong (UsageError, exit 2) is ValueError; everything it reports with exit 1 (a
// bad scene, a GL error, an internal error) is RuntimeError. pybind11's own mapping would
// turn a std::out_of_range into IndexError, say; its exceptions pass through.
void translate(std::exception_ptr p) {
    try {
        if (p) std::rethrow_exception(p);
    } catch (const py::error_already_set&) {
        throw;
    } catch (const py::builtin_exception&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        PyErr_SetString(vct::exitCodeFor(e) == 2 ? PyExc_ValueError : PyExc_RuntimeError, e.what());
    }
}

}  // namespace

PYBIND11_MODULE(vct, m) {
    m.doc() = R"doc(vct: voxel cone tracing, screen-space AO and a ray-traced reference, scored against
each other.

    import vct
    s = vct.Session("scenes/cornell_box.gltf")
    out = s.render(ao="gtao", gi="vct", aovs=["beauty", "ao"], size=128)
    out["ao"]        # 128x128 float32 array; out["beauty"] is 128x128x3
    out["stats"]     # what `vct render --stats` writes
    records = s.compare(methods=["gtao", "vct"], ref_spp=64, size=64)
    vct.methods()    # every method with its settings; vct.metrics.rmse(a, b), ...

Bad input raises ValueError with the command line's message; GL, scene and internal
failures raise RuntimeError.)doc";
    py::register_exception_translator(&translate);
    vct::python::bindSession(m);
    vct::python::bindRegistry(m);
    vct::python::bindMetrics(m);
    m.def("to_dataframe", [](const py::object& records) {
        return py::module_::import("pandas").attr("DataFrame")(records);
    }, py::arg("records"), "compare() records as a pandas DataFrame (needs pandas; raises ImportError without it).");
    py::module_::import("atexit").attr("register")(py::cpp_function(&vct::python::keepContextCurrentAtExit));
}
