// A headless OpenGL 4.5 core context through EGL: Mesa's surfaceless platform where there
// is no GPU (llvmpipe), the EGL device platform where there is one. No window, no X.
// KHR_debug messages of type error are collected; `checkErrors(pass)` turns them into an
// exception naming the pass, so tests fail on any GL error and the CLI reports where.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace vct {

enum class GlDevice { Auto, Surfaceless, Device };

struct GlContextInfo {
    std::string renderer;
    std::string version;
    std::string vendor;
    std::string platform;  // "surfaceless" or "device"
    bool softwareRenderer = false;  // Mesa's llvmpipe or softpipe: the CPU rasterizes and filters in float
    bool gpuTimerQueries = false;   // false where GL_TIME_ELAPSED reads 0 (the software renderers)
};

class GlContext {
public:
    // Creates and makes current a context; throws std::runtime_error with the reason.
    explicit GlContext(GlDevice device = GlDevice::Auto);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    const GlContextInfo& info() const { return mInfo; }

    // Throws std::runtime_error("GL error in pass '<pass>': ...") if KHR_debug reported
    // an error since the last call; clears the list either way.
    void checkErrors(const std::string& pass);
    // Errors reported since the last check, without clearing them.
    std::vector<std::string> pendingErrors() const;

    // An EGL context is current on at most one thread at a time: a caller that renders from
    // several threads (the Python module) makes it current on its thread and releases it
    // after, under one process-wide lock. Both throw std::runtime_error when EGL refuses.
    void makeCurrent();
    void releaseCurrent();

    // The process-wide context, created on first use (tests and the CLI share one). An Auto
    // request takes $VCT_GL_DEVICE (auto, surfaceless or device) where it is set.
    static GlContext& shared(GlDevice device = GlDevice::Auto);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
    GlContextInfo mInfo;
};

GlDevice parseGlDevice(const std::string& name);  // "auto", "surfaceless", "device"

// Whether EGL's client extension string offers what opening a device display needs:
// enumeration (EGL_EXT_device_enumeration, or EGL_EXT_device_base, which NVIDIA's EGL names
// alone and which includes it) and EGL_EXT_platform_device.
bool eglCanOpenDevices(const char* clientExtensions);

}  // namespace vct
