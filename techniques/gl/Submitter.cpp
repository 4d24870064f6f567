#include "techniques/gl/Submitter.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "techniques/gl/DisplayListSubmitter.h"
#include "techniques/gl/ImmediateSubmitter.h"
#include "techniques/gl/InstancedSubmitter.h"
#include "techniques/gl/RetainedSubmitter.h"

namespace sb {

std::unique_ptr<Submitter> Submitter::create(SubmitMode mode) {
    switch (mode) {
    case SubmitMode::Immediate:
        return std::make_unique<ImmediateSubmitter>();
    case SubmitMode::DisplayList:
        return std::make_unique<DisplayListSubmitter>();
    case SubmitMode::Retained:
        return std::make_unique<RetainedSubmitter>();
    case SubmitMode::Instanced:
        return std::make_unique<InstancedSubmitter>();
    }
    return nullptr;
}

InstanceMask Submitter::narrowToScope(InstanceMask keep) {
    mScoped.resize(mScope.size());
    for (size_t i = 0; i < mScope.size(); ++i) mScoped[i] = mScope[i] && keptBy(keep, i) ? 1 : 0;
    return mScoped;
}

void Submitter::setCullView(const CullView* view) {
    // GL's window y runs up: the matrix alone says which winding is front.
    mBackFaceCulled = mBackFaceCuller.setView(view, false);
    setCullFace(false);
    // GL_CW only while a mirroring view culls: the front face also picks two-sided stencil's faces
    // (volume's marks), which expect the default.
    const bool clockwise = mBackFaceCulled && !mBackFaceCuller.frontCounterClockwise();
    if (clockwise != mFrontClockwise) {
        glFrontFace(clockwise ? GL_CW : GL_CCW);
        mFrontClockwise = clockwise;
        mStats.glCalls += 1;
    }
}

void Submitter::setCullFace(bool on) {
    if (on == mCullFaceOn) return;
    mCullFaceOn = on;
    if (on)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    mStats.glCalls += 1;
}

void Submitter::setInstanceUniforms(const Instance& inst) {
    // Fixed locations (layout(location=...) in common/instance.glsl): no glGetUniformLocation per draw.
    glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
    glUniform4f(4, inst.color.r, inst.color.g, inst.color.b, shadowSignedId(inst));
}

void Submitter::emitImmediate(const Mesh& mesh) {
    glBegin(GL_TRIANGLES);
    for (uint32_t idx : mesh.indices) {
        glVertexAttrib3fv(1, &mesh.normals[idx].x);
        glVertexAttrib3fv(0, &mesh.positions[idx].x);
    }
    glEnd();
}

} // namespace sb
