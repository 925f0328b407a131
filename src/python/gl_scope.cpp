#include "python/gl_scope.h"

#include "gl/handles.h"

#include <atomic>

namespace vct::python {

namespace {

std::mutex& glMutex() {
    static std::mutex m;
    return m;
}

std::atomic<bool> gExiting{false};

}  // namespace

GlScope::GlScope(GlDevice device) : mLock(glMutex()) {
    mContext = &GlContext::shared(device);
    mContext->makeCurrent();
}

GlScope::~GlScope() {
    if (gExiting.load()) return;
    try {
        mContext->releaseCurrent();
    } catch (const std::exception&) {
        // Nothing to do in a destructor: the next scope's makeCurrent reports the failure.
    }
}

void keepContextCurrentAtExit() {
    std::lock_guard<std::mutex> lock(glMutex());
    gExiting = true;
    // Only where a context exists: creating one at exit would be work for nothing.
    if (glContextAlive()) GlContext::shared().makeCurrent();
}

}  // namespace vct::python
