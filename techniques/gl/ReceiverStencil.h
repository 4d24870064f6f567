#pragma once
// The slides' receiver marking for the planar ad-hoc techniques (`planar`, `blob`): the rectangles of
// the receiver planes (scenes/ReceiverPlane.h) drawn into the stencil where they are visible, so that
// what is drawn onto a receiver afterwards with a stencil test lands on it and nowhere else.
// The rectangle lies in the receiver's own plane; glPolygonOffset pulls it towards the eye so it wins
// the depth test against the receiver it lies on and loses against anything in front of it.
#include <vector>

#include <epoxy/gl.h>

#include "gl/ProgramCache.h"
#include "scenes/ReceiverPlane.h"

namespace sb {

class ReceiverStencil {
public:
    /// glPolygonOffset(factor, units) for geometry drawn in a receiver's plane: factor for the depth
    /// slope, units for the rounding of two triangulations of the same plane.
    static constexpr float kOffsetFactor = -1.0f, kOffsetUnits = -4.0f;

    ReceiverStencil() = default;
    ~ReceiverStencil();
    ReceiverStencil(const ReceiverStencil&) = delete;
    ReceiverStencil& operator=(const ReceiverStencil&) = delete;

    /// Uploads the rectangles (4 corners each, triangle fans).
    void upload(const std::vector<ReceiverPlane>& planes);
    const Program& compile(ProgramCache& programs);
    /// Sets stencil = `ref` where receiver `plane` is visible (depth test LEQUAL, colour writes off),
    /// then leaves the stencil test at EQUAL `ref` with colour writes on, the depth test off and the
    /// stencil op `passOp` for what is drawn next (GL_ZERO: each pixel once; GL_KEEP: any number of
    /// times). Expects GL_STENCIL_TEST and GL_POLYGON_OFFSET_FILL enabled by the caller.
    void mark(size_t plane, int ref, GLenum passOp) const;
    /// The blending `planar` and `blob` draw shadows with: colour = dst - src (their fragment shaders
    /// output the removed light's term), visibility = dst * src (1 - alpha in that light's channel).
    static void setDarkenBlending();

private:
    void release();
    GLuint mVao = 0, mVbo = 0;
    const Program* mProgram = nullptr;
};

} // namespace sb
