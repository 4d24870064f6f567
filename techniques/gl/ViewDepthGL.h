#pragma once
// The depth pre-pass of the camera's view on GL (techniques/ViewDepth.h says what it draws and why it
// exists): a GL_DEPTH_COMPONENT32F texture of the frame's size and its framebuffer, drawn once per frame
// with common/depth.vert and the camera's view-projection. A technique owns one and renders it where
// its first reader needs it: `cascaded` fit=sdsm's depth-range reduction (techniques/shadowmap/
// DepthRangeGL.h) reads it, and so may a lighting pass (contact shadows), the same texture of the same
// frame. Allocated at the first frame and again when the frame's size changes.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gl/ProgramCache.h"
#include "techniques/gl/GlTechnique.h"

namespace sb {

class ViewDepthGL {
public:
    ViewDepthGL() = default;
    ~ViewDepthGL() { release(); }
    ViewDepthGL(const ViewDepthGL&) = delete;
    ViewDepthGL& operator=(const ViewDepthGL&) = delete;

    /// The pre-pass's program (`submitterDefines`: the scene draw's instancing, as every depth pass).
    void compile(ProgramCache& programs, const Defines& submitterDefines);
    /// Draws this frame's view depth (every instance, culled to the camera's frustum) into texture(),
    /// allocating it at the targets' size first where needed. Leaves its own framebuffer bound: the
    /// caller binds the targets (or its next pass's framebuffer) again.
    void render(const FrameContext& ctx);

    /// The texture unit a lighting pass reads it from (shaders/common/contact_shadow.glsl's uViewDepth):
    /// above the units the family's maps take (0 and 1); and the uniform-buffer binding of the block the
    /// reading pass takes beside it (its ContactBlock: above the frame block's 0).
    static constexpr GLuint kLightingUnit = 7;
    static constexpr GLuint kLightingBlock = 1;
    /// Binds texture() to kLightingUnit and `block` (16 bytes: ContactShadows::block) to kLightingBlock
    /// for a lighting pass; unbindForLighting after it.
    void bindForLighting(const glm::vec4& block);
    static void unbindForLighting();

    /// The depth texture (GL_DEPTH_COMPONENT32F, NEAREST, the frame's size; 0 before the first render).
    GLuint texture() const { return mTexture; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    /// The camera projection of the last render: what its window depths are view depths under
    /// (ViewDepth::viewDepths).
    const glm::mat4& proj() const { return mProj; }
    /// How many times the texture was (re)allocated: a reader holding state per texture (a binding, an
    /// answer of an earlier frame) starts over when this changes.
    uint64_t allocations() const { return mAllocations; }

private:
    void allocate(int width, int height);
    void release();

    const Program* mProgram = nullptr;
    GLuint mTexture = 0, mFbo = 0;
    GLuint mBlock = 0; ///< the lighting pass's 16-byte block
    int mWidth = 0, mHeight = 0;
    glm::mat4 mProj{1.0f};
    uint64_t mAllocations = 0;
};

} // namespace sb
