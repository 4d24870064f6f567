#pragma once
// Contact shadows (techniques/ContactShadows.h) on a GL member's frame: the wiring every map member
// repeats, in one home. It owns the view depth pre-pass (techniques/gl/ViewDepthGL.h) and, when the
// member's properties turn `contact` on, gives DepthLightingFrame::run (or FilterableShadowMaps::
// renderFrame) its first pass and binds the view depth and the march's block around the lighting draw.
// With `contact` off it compiles nothing, draws nothing and binds nothing: the member's frame is the one
// without it. `cascaded` keeps its own ViewDepthGL: fit=sdsm reads the same pre-pass (CascadedGL.h).
#include <functional>

#include <glm/glm.hpp>

#include "techniques/PropertySet.h"
#include "techniques/gl/ViewDepthGL.h"

namespace sb {

class ContactShadowsGL {
public:
    /// Reads `p` (a member declaring ContactShadows::properties()) and, when on, compiles the pre-pass's
    /// program (`submitterDefines`: the scene draw's instancing).
    void compile(const PropertySet& p, ProgramCache& programs, const Defines& submitterDefines);
    bool enabled() const { return mEnabled; }
    /// The first pass of the member's frame (pass ContactShadows::kPass): renders the view depth of `ctx`'s
    /// frame. Empty when off, so that the frame has no such pass.
    std::function<void()> prePass(const FrameContext& ctx);
    /// Around the lighting draw: binds the view depth and the block (ViewDepthGL::bindForLighting) when
    /// on, and unbinds them after.
    void bind();
    void unbind() const;

private:
    bool mEnabled = false;
    glm::vec4 mBlock{0.0f};
    ViewDepthGL mViewDepth;
};

} // namespace sb
