// The GL context is process-wide (GlContext::shared) and an EGL context is current on at
// most one thread at a time, while Python may call from any thread. Every call of the
// module that touches GL (opening a session, rendering, comparing, closing) holds a GlScope:
// one process-wide lock, and the context made current on the calling thread for as long as
// the scope lives. Construct it with the GIL released, so that Python threads waiting for
// the lock do not stop the others.
#pragma once

#include "gl/context.h"

#include <mutex>

namespace vct::python {

class GlScope {
public:
    explicit GlScope(GlDevice device = GlDevice::Auto);
    ~GlScope();
    GlScope(const GlScope&) = delete;
    GlScope& operator=(const GlScope&) = delete;

private:
    std::unique_lock<std::mutex> mLock;
    GlContext* mContext = nullptr;
};

// From the interpreter's exit on, the context stays current on the exiting thread: the
// process-wide program cache and the context itself are destroyed after Python, by static
// destructors that call GL on that thread. Registered with Python's atexit by the module.
void keepContextCurrentAtExit();

}  // namespace vct::python
