// vct.metrics: the error metrics and the ROI of src/eval on NumPy arrays, the functions
// compare() scores with, so a notebook's numbers match the comparison's.
#include "python/bindings.h"
#include "python/convert.h"

#include "core/errors.h"
#include "eval/metrics.h"
#include "eval/roi.h"

#include <optional>

namespace py = pybind11;

namespace vct::python {

namespace {

// src/eval checks its images as a contract between parts of the program (InternalError): a NaN
// there is a broken estimator. Here the arrays are the caller's, so the same checks are the
// caller's error and raise ValueError with the check's message.
template <class F>
auto onCallersArrays(F&& f) {
    try {
        return f();
    } catch (const InternalError& e) {
        throw py::value_error(e.detail);
    }
}

std::optional<Image> maskOf(const py::object& mask) {
    if (mask.is_none()) return std::nullopt;
    return toImage(mask, "mask");
}

ErrorMetrics errorMetrics(const py::object& estimate, const py::object& reference, const py::object& mask,
                          int channel, double peak) {
    const Image e = toImage(estimate, "estimate"), r = toImage(reference, "reference");
    const std::optional<Image> m = maskOf(mask);
    return onCallersArrays([&] {
        py::gil_scoped_release nogil;
        return computeErrorMetrics(e, r, m ? &*m : nullptr, channel, peak);
    });
}

}  // namespace

void bindMetrics(py::module_& parent) {
    py::module_ m = parent.def_submodule("metrics",
        R"doc(Error of an estimate against a reference on NumPy arrays (HxW or HxWxC),
the functions vct compare scores with. A pixel counts where mask (HxW, or None for every pixel) is
> 0.5; channel=-1 averages over the channels, channel=k keeps channel k. NaN or Inf,
or mismatched shapes, raise ValueError.)doc");

    m.def("rmse", [](const py::object& e, const py::object& r, const py::object& mask, int channel) {
        return errorMetrics(e, r, mask, channel, 1.0).rmse;
    }, py::arg("estimate"), py::arg("reference"), py::arg("mask") = py::none(), py::arg("channel") = -1,
       "Root mean square error over the valid pixels (0 for an empty selection).");

    m.def("ssim", [](const py::object& e, const py::object& r, const py::object& mask, int channel, double peak) {
        const Image est = toImage(e, "estimate"), ref = toImage(r, "reference");
        const std::optional<Image> mk = maskOf(mask);
        return onCallersArrays([&] {
            py::gil_scoped_release nogil;
            return computeSsim(est, ref, mk ? &*mk : nullptr, channel, peak);
        });
    }, py::arg("estimate"), py::arg("reference"), py::arg("mask") = py::none(), py::arg("channel") = -1,
       py::arg("peak") = 1.0,
       R"doc(Mean SSIM (Wang et al. 2004, 11x11 Gaussian window, sigma 1.5) over windows
centred on valid pixels; the window shrinks to the valid pixels it covers. peak: the signal's range
(1 for AO). 1 means identical.)doc");

    m.def("error_metrics", [](const py::object& e, const py::object& r, const py::object& mask, int channel,
                              double peak) {
        const ErrorMetrics x = errorMetrics(e, r, mask, channel, peak);
        py::dict d;
        d["rmse"] = x.rmse;
        d["mae"] = x.mae;
        d["bias"] = x.bias;
        d["max_abs"] = x.maxAbs;
        d["psnr"] = x.psnr;
        d["ssim"] = x.ssim;
        d["pixels"] = x.pixelCount;
        return d;
    }, py::arg("estimate"), py::arg("reference"), py::arg("mask") = py::none(), py::arg("channel") = -1,
       py::arg("peak") = 1.0,
       R"doc(Every metric of a compare() record: rmse, mae, bias (mean estimate - reference),
max_abs, psnr (dB, capped at 200), ssim and pixels (the valid pixel count).)doc");

    m.def("roi", [](const py::object& aoWith, const py::object& aoWithout, const py::object& seWith,
                    const py::object& seWithout, double k) {
        const Image a = toImage(aoWith, "ao_with"), b = toImage(aoWithout, "ao_without");
        const Image sa = toImage(seWith, "stderr_with"), sb = toImage(seWithout, "stderr_without");
        const Image roi = onCallersArrays([&] {
            py::gil_scoped_release nogil;
            return deriveRoiMask(a, b, sa, sb, k);
        });
        return toArray(roi);
    }, py::arg("ao_with"), py::arg("ao_without"), py::arg("stderr_with"), py::arg("stderr_without"),
       py::arg("k") = 3.0,
       R"doc(The region of interest of an off-screen occluder: an HxW float32 mask, 1 where
two reference AO renders (with and without the occluder, each with its ao_stderr AOV)
differ by more than k of their combined standard errors, 0 elsewhere.)doc");
}

}  // namespace vct::python
