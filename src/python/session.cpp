// vct.Session: one scene, loaded once, and the RenderSession that keeps its G-buffers,
// shadow maps and voxel grids between calls. Each call reads its arguments with the GIL
// held, then releases the GIL and holds the session's lock and the process-wide GL scope
// (gl_scope.h) while the renderer runs; the results become Python objects after both are
// released, so no thread ever waits for the GIL while it holds the GL lock.
#include "python/bindings.h"
#include "python/convert.h"
#include "python/gl_scope.h"
#include "python/render_arguments.h"

#include "eval/comparison.h"
#include "methods/registry.h"
#include "render/render_spec.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"

#include <pybind11/stl.h>

#include <memory>
#include <mutex>

namespace py = pybind11;

namespace vct::python {

namespace {

RenderSpec renderSpec(const std::string& ao, const std::string& gi, const py::object& aovs, const py::object& size,
                      const py::object& camera, float radius, int spp, uint64_t seed, int voxelRes,
                      const std::string& backend, float sky, const py::object& params) {
    RenderSpec spec;
    readSize(size, spec);
    spec.camera = readCamera(camera);
    spec.ao = ao;
    spec.gi = gi;
    spec.radius = radius;
    spec.spp = spp;
    spec.seed = seed;
    spec.voxelRes = voxelRes;
    spec.backend = backend;
    spec.aovs = readAovs(aovs);
    spec.params = readParams(params);
    spec.sky = sky;
    return spec;
}

// Each entry may carry its parameters in brackets, as --methods does: "gtao[gtao.preset=low]".
std::vector<MethodVariant> variants(const py::object& methods, const std::string& kind,
                                    const std::vector<const Method*>& byDefault) {
    std::vector<std::string> names;
    if (methods.is_none()) {
        for (const Method* m : byDefault) names.push_back(m->name);
    } else if (py::isinstance<py::str>(methods)) {
        names.push_back(methods.cast<std::string>());
    } else {
        try {
            names = methods.cast<std::vector<std::string>>();
        } catch (const py::cast_error&) {
            throw py::type_error(kind == "ao" ? "methods: expected a list of names" : "gi: expected a list of names");
        }
    }
    std::vector<MethodVariant> out;
    for (const std::string& name : names)
        for (MethodVariant& v : parseMethodList(name, kind)) out.push_back(std::move(v));
    return out;
}

}  // namespace

class Session {
public:
    Session(const std::string& path, const std::string& glDevice) {
        const GlDevice device = parseGlDevice(glDevice);
        {
            py::gil_scoped_release nogil;
            mScene = std::make_unique<Scene>(loadScene(path));
            GlScope gl(device);
            mSession = std::make_unique<RenderSession>(*mScene);
        }
        for (const std::string& w : mScene->warnings)
            if (PyErr_WarnEx(PyExc_UserWarning, (path + ": " + w).c_str(), 1) < 0) {
                closeGl();  // warnings turned into errors: no destructor will run
                throw py::error_already_set();
            }
    }

    ~Session() { closeGl(); }

    const Scene& scene() const { return *mScene; }

    py::dict render(const std::string& ao, const std::string& gi, const py::object& aovs, const py::object& size,
                    const py::object& camera, float radius, int spp, uint64_t seed, int voxelRes,
                    const std::string& backend, float sky, const py::object& params) {
        const RenderSpec spec =
            renderSpec(ao, gi, aovs, size, camera, radius, spp, seed, voxelRes, backend, sky, params);
        RenderRequest request;
        RenderResult result;
        nlohmann::json stats;
        {
            py::gil_scoped_release nogil;
            std::lock_guard<std::mutex> lock(mMutex);
            request = makeRenderRequest(spec, *mScene);
            GlScope gl;
            result = mSession->render(request);
            checkRenderResult(result);
            stats = statsJson(result, request, *mScene);
        }
        py::dict out;
        for (const auto& name : request.aovs) out[py::str(name)] = toArray(result.aovs.at(name));
        out["stats"] = toPython(stats);
        return out;
    }

    py::object compare(const py::object& methods, const py::object& gi, int refSpp, int runs, const py::object& size,
                       const py::object& camera, float radius, uint64_t seed, int voxelRes, const std::string& backend,
                       float sky, const py::object& params, const py::object& outputDir, bool full, bool dataframe) {
        const RenderSpec spec = renderSpec(kNoMethod, kNoMethod, py::none(), size, camera, radius, 64, seed, voxelRes,
                                           backend, sky, params);
        ComparisonSettings s;
        s.variants = variants(methods, "ao", scoredMethods(MethodKind::AO));
        for (MethodVariant& v : variants(gi, "gi", {})) s.variants.push_back(std::move(v));
        s.referenceSpp = refSpp;
        s.timingRuns = runs;
        if (!outputDir.is_none()) s.outputDir = py::str(outputDir).cast<std::string>();
        nlohmann::json doc;
        {
            py::gil_scoped_release nogil;
            std::lock_guard<std::mutex> lock(mMutex);
            s.base = makeRenderRequest(spec, *mScene);
            checkComparisonSettings(s);
            GlScope gl;
            doc = runComparison(*mScene, s);
        }
        py::object records = toPython(doc["records"]);
        if (dataframe) records = py::module_::import("vct").attr("to_dataframe")(records);
        if (!full) return records;
        py::dict whole = toPython(doc);
        whole["records"] = records;
        return std::move(whole);
    }

    py::dict passRunCounts() {
        std::map<std::string, int> counts;
        {
            py::gil_scoped_release nogil;
            std::lock_guard<std::mutex> lock(mMutex);
            counts = mSession->passRunCounts();
        }
        return py::cast(counts);
    }

private:
    // GL objects die with the context current; the GIL is held when Python drops us.
    void closeGl() noexcept {
        if (!mSession) return;
        std::unique_ptr<py::gil_scoped_release> nogil;
        if (PyGILState_Check()) nogil = std::make_unique<py::gil_scoped_release>();
        try {
            GlScope gl;
            mSession.reset();
        } catch (const std::exception&) {
            // The context cannot be made current here: leak the GL objects rather than
            // delete them on a thread without it.
            (void)mSession.release();
        }
    }

    std::unique_ptr<Scene> mScene;
    std::unique_ptr<RenderSession> mSession;
    std::mutex mMutex;  // one call at a time on this session's caches
};

void bindSession(py::module_& m) {
    py::class_<Session>(m, "Session", R"doc(One glTF scene, loaded once, rendered many times.

The session keeps what renders of the same scene share: the G-buffer per camera and
size, the shadow maps and the voxel grids per resolution, so rendering several methods
of one view rasterizes once and voxelizes once (see pass_run_counts()).

Calls release the GIL while the renderer works. All sessions share one GL context;
calls from several threads are safe and run one at a time.)doc")
        .def(py::init<const std::string&, const std::string&>(), py::arg("scene_path"), py::arg("gl_device") = "auto",
             R"doc(Loads a glTF 2.0 scene (.gltf or .glb) and uploads it to the GPU.

gl_device: "auto", "surfaceless" (Mesa, no GPU) or "device" (an EGL device); the
process's first session chooses, later ones share its context ($VCT_GL_DEVICE applies
to "auto"). Raises RuntimeError for an unreadable or invalid scene, naming the file and
element; warnings about the scene are issued as UserWarning.)doc")
        .def_property_readonly("scene_path", [](const Session& s) { return s.scene().path; },
                               "the scene's file")
        .def_property_readonly("cameras", [](const Session& s) {
            std::vector<std::string> names;
            for (const Camera& c : s.scene().cameras) names.push_back(c.name);
            return names;
        }, "names of the scene's cameras, in index order (camera= takes a name or an index)")
        .def("render", &Session::render, py::arg("ao") = "none", py::arg("gi") = "none", py::arg("aovs") = py::none(),
             py::arg("size") = 256, py::arg("camera") = py::none(), py::arg("radius") = 1.f, py::arg("spp") = 64,
             py::arg("seed") = 0, py::arg("voxel_res") = 128, py::arg("backend") = "gl", py::arg("sky") = 1.f,
             py::arg("params") = py::none(),
             R"doc(Renders one view; the arguments are `vct render`'s options, with its defaults.

ao, gi: an AO and a GI method of vct.methods(), or "none".
aovs: an AOV name or a list of them (vct.aovs(); default ["beauty"]).
size: W or (W, H), each side in [1, 16384].
camera: None (the file's first camera, else a framing of the scene), a camera's name
    or index, or dict(eye=(x, y, z), target=(x, y, z), fov=degrees).
radius: the AO radius in world units, shared by every AO method.
spp: the reference's samples per pixel. seed: seed of every random choice.
voxel_res: voxels along the grid's longest axis. backend: "gl" or "vdb".
sky: uniform sky radiance.
params: {key: value} or ["KEY=VALUE", ...], the --param keys of vct.settings().

Returns a dict: each requested AOV as a float32 NumPy array, top row first, HxW for
one channel and HxWx3 otherwise, and "stats": what `vct render --stats` writes
(passes with their times, total_ms, frame_ms, the pass plan, the methods' statistics).
Raises ValueError for what the command line rejects with exit code 2 (an unknown
method, AOV or parameter, a value out of range), with the same message, and
RuntimeError for GL and internal failures.)doc")
        .def("compare", &Session::compare, py::arg("methods") = py::none(), py::arg("gi") = py::none(),
             py::arg("ref_spp") = 256, py::arg("runs") = 3, py::arg("size") = 256, py::arg("camera") = py::none(),
             py::arg("radius") = 1.f, py::arg("seed") = 0, py::arg("voxel_res") = 128, py::arg("backend") = "gl",
             py::arg("sky") = 1.f, py::arg("params") = py::none(), py::arg("output_dir") = py::none(),
             py::arg("full") = false, py::arg("dataframe") = false,
             R"doc(Scores methods against the ray-traced reference on one view, as `vct compare` does.

methods: AO methods (default: every registered one but the reference), each with
    optional parameters in brackets, e.g. "gtao[gtao.preset=low;blur=0]".
gi: GI methods scored on indirect radiance against the path tracer (default none).
ref_spp: the reference's samples per pixel. runs: timed runs after one warm-up
    (time_ms, the cold cost including the method's own voxelization or BVH, and frame_ms,
    the same runs less what the next frame of a static scene reuses, are their medians).
size, camera, radius, seed, voxel_res, backend, sky, params: as for render().
output_dir: where to write what `vct compare -o` writes (images, results.json,
    results.csv); None writes nothing.

Returns the records, one dict per variant (label, kind, method, params, time_ms,
frame_ms, frame_gpu_ms (None without GPU timer queries), passes, provenance, cost, rmse, mae, bias,
max_abs, psnr, ssim, pixels, roi_rmse, nonroi_rmse, extra);
a pandas DataFrame of them with dataframe=True; with full=True the whole results
document (scene, camera, resolution, the reference's spp and standard errors,
records). The comparison runs on its own renderer session over this session's scene.)doc")
        .def("pass_run_counts", &Session::passRunCounts,
             R"doc(How many times each shared pass (gbuffer, shadow, voxelize, ...) has run in
this session: a second method on the same view and voxel resolution adds nothing.)doc");
}

}  // namespace vct::python
