#include "gl/context.h"

#include "core/errors.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>

namespace vct {

struct GlContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::vector<std::string> errors;
};

namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity,
                              GLsizei length, const GLchar* message, const void* user) {
    (void)source; (void)id; (void)length;
    auto* errors = static_cast<std::vector<std::string>*>(const_cast<void*>(user));
    if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH)
        errors->push_back(message ? message : "(no message)");
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

}  // namespace

bool eglCanOpenDevices(const char* clientExtensions) {
    return (hasExtension(clientExtensions, "EGL_EXT_device_enumeration") ||
            hasExtension(clientExtensions, "EGL_EXT_device_base")) &&
           hasExtension(clientExtensions, "EGL_EXT_platform_device");
}

namespace {

// The first EGL device that is not Mesa's software device, or nothing.
EGLDisplay openDeviceDisplay() {
    if (!eglCanOpenDevices(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS))) return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(16, devices, &count)) return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; ++i) {
        const char* devExts = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        if (hasExtension(devExts, "EGL_MESA_device_software")) continue;
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d != EGL_NO_DISPLAY) return d;
    }
    return EGL_NO_DISPLAY;
}

}  // namespace

namespace {
std::atomic<int> gLiveContexts{0};
}

bool glContextAlive() { return gLiveContexts.load() > 0; }

GlDevice parseGlDevice(const std::string& name) {
    if (name == "auto") return GlDevice::Auto;
    if (name == "surfaceless") return GlDevice::Surfaceless;
    if (name == "device") return GlDevice::Device;
    throw UsageError("unknown --gl-device '" + name + "' (auto, surfaceless, device)");
}

GlContext::GlContext(GlDevice device) : mImpl(std::make_unique<Impl>()) {
    EGLDisplay display = EGL_NO_DISPLAY;
    if (device != GlDevice::Surfaceless) {
        display = openDeviceDisplay();
        if (display != EGL_NO_DISPLAY) mInfo.platform = "device";
        else if (device == GlDevice::Device)
            throw std::runtime_error("--gl-device device: no hardware EGL device found");
    }
    if (display == EGL_NO_DISPLAY) {
        display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        mInfo.platform = "surfaceless";
    }
    if (display == EGL_NO_DISPLAY) throw std::runtime_error("EGL: no display (surfaceless or device)");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        throw std::runtime_error("EGL: eglInitialize failed on the " + mInfo.platform + " platform");
    mImpl->display = display;
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
    mImpl->context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (mImpl->context == EGL_NO_CONTEXT)
        throw std::runtime_error("EGL: could not create an OpenGL 4.5 core context");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, mImpl->context))
        throw std::runtime_error("EGL: eglMakeCurrent failed");

    mInfo.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    mInfo.version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    mInfo.vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
    mInfo.softwareRenderer = mInfo.renderer.find("llvmpipe") != std::string::npos ||
                             mInfo.renderer.find("softpipe") != std::string::npos;
    // llvmpipe's GL_TIME_ELAPSED queries read 0: report GPU times only on real hardware.
    mInfo.gpuTimerQueries = !mInfo.softwareRenderer;

    gLiveContexts++;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debugCallback, &mImpl->errors);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

GlContext::~GlContext() {
    if (mImpl->context != EGL_NO_CONTEXT) gLiveContexts--;
    if (mImpl->display != EGL_NO_DISPLAY) {
        eglMakeCurrent(mImpl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (mImpl->context != EGL_NO_CONTEXT) eglDestroyContext(mImpl->display, mImpl->context);
        eglTerminate(mImpl->display);
    }
}

void GlContext::checkErrors(const std::string& pass) {
    glFinish();
    if (mImpl->errors.empty()) return;
    std::string msg = "GL error in pass '" + pass + "': " + mImpl->errors.front();
    if (mImpl->errors.size() > 1) msg += " (and " + std::to_string(mImpl->errors.size() - 1) + " more)";
    mImpl->errors.clear();
    throw std::runtime_error(msg);
}

std::vector<std::string> GlContext::pendingErrors() const { return mImpl->errors; }

void GlContext::makeCurrent() {
    if (eglGetCurrentContext() == mImpl->context) return;
    if (!eglMakeCurrent(mImpl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, mImpl->context))
        throw std::runtime_error("EGL: eglMakeCurrent failed (is the context current on another thread?)");
}

void GlContext::releaseCurrent() {
    if (eglGetCurrentContext() != mImpl->context) return;
    if (!eglMakeCurrent(mImpl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT))
        throw std::runtime_error("EGL: eglMakeCurrent could not release the context");
}

GlContext& GlContext::shared(GlDevice device) {
    static std::unique_ptr<GlContext> instance;
    static std::mutex m;
    std::lock_guard<std::mutex> lock(m);
    // VCT_GL_DEVICE=device|surfaceless chooses for every Auto request: the test suite runs
    // on a GPU's EGL device platform without a flag per test.
    const char* env = std::getenv("VCT_GL_DEVICE");
    if (device == GlDevice::Auto && env && *env) device = parseGlDevice(env);
    if (!instance) instance = std::make_unique<GlContext>(device);
    return *instance;
}

}  // namespace vct
