#include "gl/backends/OsMesaContext.h"

// epoxy/gl.h must come before GL/osmesa.h (which includes GL/gl.h).
#include <epoxy/gl.h>

#include <GL/osmesa.h>

#include "core/Error.h"
#include "gl/backends/EpoxyOsMesaBridge.h"

namespace sb {

OsMesaContext::OsMesaContext(const ContextOptions&)
    : mDummyBuffer(static_cast<size_t>(kDummySize) * kDummySize * 4) {
    // OSMesa has no debug-context flag: KHR_debug output is enabled by DebugOutput with glEnable.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              8,
                              OSMESA_PROFILE,
                              OSMESA_COMPAT_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    mContext = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!mContext)
        throw Error("osmesa: OSMesaCreateContextAttribs(OpenGL 4.5 compatibility) failed",
                    ExitCode::Unsupported);
    makeCurrent();
}

OsMesaContext::~OsMesaContext() {
    if (OSMesaGetCurrentContext() == mContext) {
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        EpoxyOsMesaBridge::restore();
    }
    OSMesaDestroyContext(mContext);
}

void OsMesaContext::makeCurrent() {
    if (!OSMesaMakeCurrent(mContext, mDummyBuffer.data(), GL_UNSIGNED_BYTE, kDummySize, kDummySize))
        throw Error("osmesa: OSMesaMakeCurrent failed", ExitCode::Unsupported);
    EpoxyOsMesaBridge::install();
}

} // namespace sb
