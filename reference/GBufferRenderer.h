#pragma once
// Renders the G-buffer (reference/GBuffer.h) the reference traces from: per pixel the world position
// and object id of the visible surface (RGBA32F) and the triangle index within its draw
// (gl_PrimitiveID, R32UI), with a DEPTH24_STENCIL8 depth buffer. It draws through the run's own
// Submitter with the same view-projection, depth test (LESS) and no polygon offset as a technique's
// lighting pass, so that every G-buffer sample is exactly one of that pass's pixels.
//
// gl_PrimitiveID counts triangles within one draw. Retained and instanced submission keep one draw per
// instance (restarting per instance of an instanced draw), but Mesa splits long glBegin/glEnd streams
// (immediate mode and display lists) into several draws, restarting gl_PrimitiveID every ~7300
// triangles on llvmpipe (tests/GBufferGLTest.cpp). For those two modes the renderer therefore draws
// the scene itself, one glDrawElements per instance in scene order (the order of those submitters),
// from the same vertices: the same clip coordinates, so the same pixels and depths.
#include <memory>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gl/ProgramCache.h"
#include "gl/TextureFramebuffer.h"
#include "reference/GBuffer.h"
#include "scenes/Scene.h"
#include "techniques/gl/MeshBuffers.h"
#include "techniques/gl/Submitter.h"

namespace sb {

class GBufferRenderer {
public:
    /// Allocates the FBO (throws sb::Error when it is incomplete). Needs a current context.
    GBufferRenderer(int width, int height);

    int width() const { return mTarget.width(); }
    int height() const { return mTarget.height(); }
    GLuint fbo() const { return mTarget.fbo(); }

    /// The scene drawn in the modes whose submitter cannot number triangles per instance (immediate,
    /// displaylist; see above). Must outlive the renderer's use; its meshes are uploaded on first need.
    void setScene(const Scene& scene);

    /// Draws DrawSet::All with shaders/reference/gbuffer.vert/.frag (plus submitter.defines()) into
    /// the FBO and reads it back (rows bottom-up). Immediate and displaylist submitters need setScene()
    /// first (throws sb::Error otherwise). Restores the GL state it changes (framebuffer
    /// bindings, viewport, program, depth and polygon-offset state, read buffer, pack state).
    GBuffer render(Submitter& submitter, ProgramCache& programs, const glm::mat4& viewProj);
    /// Draw calls, triangles and instances of the last render(), whichever path drew them (the
    /// submitter's own stats also include them on the submitter path, not on the per-instance path).
    const SubmitStats& lastStats() const { return mStats; }

private:
    void draw(Submitter& submitter, ProgramCache& programs, const glm::mat4& viewProj);
    /// One glDrawElements per instance in scene order, for modes where gl_PrimitiveID is not per instance.
    void drawIndexedPerInstance(SubmitMode mode);
    GBuffer readBack() const;

    TextureFramebuffer mTarget; ///< RGBA32F position + id, R32UI primitive, depth-stencil
    const Scene* mScene = nullptr;
    std::unique_ptr<MeshBuffers> mMeshes; ///< uploaded on first drawIndexedPerInstance()
    SubmitStats mStats;
};

} // namespace sb
