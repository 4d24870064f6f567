#pragma once
// osmesa: Mesa's off-screen API (libOSMesa, llvmpipe), the last-resort headless backend. OSMesa needs a
// client-memory colour buffer to make a context current; a small dummy one is used since everything
// renders into FBOs. While an OSMesa context is current, epoxy's GL pointers are redirected to libOSMesa
// (EpoxyOsMesaBridge; epoxy itself only knows GLX and EGL).
#include <vector>

#include "gl/Context.h"

struct osmesa_context;

namespace sb {

class OsMesaContext : public Context {
public:
    /// Throws sb::Error("osmesa: <reason>", ExitCode::Unsupported).
    explicit OsMesaContext(const ContextOptions& options);
    ~OsMesaContext() override;
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;
    Backend backend() const override { return Backend::OsMesa; }
    void makeCurrent() override;

private:
    static constexpr int kDummySize = 16; ///< side of the unused default colour buffer
    osmesa_context* mContext = nullptr;
    std::vector<unsigned char> mDummyBuffer;
};

} // namespace sb
