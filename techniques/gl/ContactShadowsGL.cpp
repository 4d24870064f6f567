#include "techniques/gl/ContactShadowsGL.h"

#include "techniques/ContactShadows.h"

namespace sb {

void ContactShadowsGL::compile(const PropertySet& p, ProgramCache& programs,
                               const Defines& submitterDefines) {
    mEnabled = ContactShadows::enabled(p);
    mBlock = ContactShadows::block(p);
    if (mEnabled) mViewDepth.compile(programs, submitterDefines);
}

std::function<void()> ContactShadowsGL::prePass(const FrameContext& ctx) {
    if (!mEnabled) return {};
    return [this, &ctx] { mViewDepth.render(ctx); };
}

void ContactShadowsGL::bind() {
    if (mEnabled) mViewDepth.bindForLighting(mBlock);
}

void ContactShadowsGL::unbind() const {
    if (mEnabled) ViewDepthGL::unbindForLighting();
}

} // namespace sb
