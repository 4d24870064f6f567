#include "reference/GBufferRenderer.h"

#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"

namespace sb {

namespace {
constexpr GLint kViewProjLocation =
    8; // shaders/reference/gbuffer.vert (0..3 and 4 are the instance uniforms)

/// The state render() changes, captured so it can be put back: a technique calls the renderer in the
/// middle of its frame and must find its own state unchanged afterwards.
struct SavedState {
    GLint drawFbo = 0, readFbo = 0, program = 0, depthFunc = GL_LESS, readBuffer = GL_BACK;
    GLint packAlignment = 4, packBuffer = 0, vertexArray = 0;
    GLint viewport[4] = {0, 0, 0, 0};
    GLboolean depthTest = GL_TRUE, depthMask = GL_TRUE, polygonOffset = GL_FALSE, cull = GL_FALSE;
    GLboolean blend = GL_FALSE, scissor = GL_FALSE, stencil = GL_FALSE;
    GLboolean colorMask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};

    SavedState() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
        glGetBooleanv(GL_COLOR_WRITEMASK, colorMask);
        depthTest = glIsEnabled(GL_DEPTH_TEST);
        polygonOffset = glIsEnabled(GL_POLYGON_OFFSET_FILL);
        cull = glIsEnabled(GL_CULL_FACE);
        blend = glIsEnabled(GL_BLEND);
        scissor = glIsEnabled(GL_SCISSOR_TEST);
        stencil = glIsEnabled(GL_STENCIL_TEST);
        // The read buffer belongs to the bound read framebuffer; query it there.
        glGetIntegerv(GL_READ_BUFFER, &readBuffer);
    }

    static void setEnabled(GLenum cap, GLboolean on) {
        if (on)
            glEnable(cap);
        else
            glDisable(cap);
    }

    void restore() const {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFbo));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo));
        glReadBuffer(GLenum(readBuffer));
        glUseProgram(GLuint(program));
        glDepthFunc(GLenum(depthFunc));
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer));
        glBindVertexArray(GLuint(vertexArray));
        glDepthMask(depthMask);
        glColorMask(colorMask[0], colorMask[1], colorMask[2], colorMask[3]);
        setEnabled(GL_DEPTH_TEST, depthTest);
        setEnabled(GL_POLYGON_OFFSET_FILL, polygonOffset);
        setEnabled(GL_CULL_FACE, cull);
        setEnabled(GL_BLEND, blend);
        setEnabled(GL_SCISSOR_TEST, scissor);
        setEnabled(GL_STENCIL_TEST, stencil);
    }
};

/// The rasterisation of the harness's frame state (bench/lib/harness/Harness.cpp setFrameState) that every
/// lighting pass draws with: a sample here must be the very pixel the technique shades.
void setLightingPassState() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}
} // namespace

GBufferRenderer::GBufferRenderer(int width, int height)
    : mTarget("G-buffer", width, height, {GL_RGBA32F, GL_R32UI}) {}

void GBufferRenderer::setScene(const Scene& scene) {
    mScene = &scene;
    mMeshes.reset();
}

GBuffer GBufferRenderer::render(Submitter& submitter, ProgramCache& programs, const glm::mat4& viewProj) {
    SavedState saved;
    draw(submitter, programs, viewProj);
    GBuffer out = readBack();
    saved.restore();
    return out;
}

void GBufferRenderer::draw(Submitter& submitter, ProgramCache& programs, const glm::mat4& viewProj) {
    const Program& program =
        programs.get({"reference/gbuffer.vert", "reference/gbuffer.frag", ""}, submitter.defines());
    mTarget.bind();
    setLightingPassState();
    const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
    const GLuint zeroId[] = {0u, 0u, 0u, 0u};
    glClearNamedFramebufferfv(mTarget.fbo(), GL_COLOR, 0, zero);
    glClearNamedFramebufferuiv(mTarget.fbo(), GL_COLOR, 1, zeroId);
    glClearNamedFramebufferfi(mTarget.fbo(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    program.use();
    glUniformMatrix4fv(kViewProjLocation, 1, GL_FALSE, glm::value_ptr(viewProj));
    mStats = {};
    if (submitter.mode() == SubmitMode::Immediate || submitter.mode() == SubmitMode::DisplayList) {
        drawIndexedPerInstance(submitter.mode());
        return;
    }
    // The caller's counters keep running; this render's share is the difference.
    const SubmitStats before = submitter.stats();
    submitter.draw(DrawSet::All);
    const SubmitStats& after = submitter.stats();
    mStats = after - before;
}

void GBufferRenderer::drawIndexedPerInstance(SubmitMode mode) {
    if (!mScene)
        throw Error(std::string("G-buffer: ") + submitModeName(mode) +
                    " submission needs GBufferRenderer::setScene (gl_PrimitiveID restarts inside its "
                    "glBegin/glEnd streams)");
    if (!mMeshes) {
        mMeshes = std::make_unique<MeshBuffers>();
        mMeshes->upload(*mScene);
    }
    // The same per-instance uniforms (locations 0 and 4 of common/instance.glsl) and the same vertex
    // order as Submitter::emitImmediate (the mesh's index list), so the triangles and their
    // rasterisation are those of the technique's immediate or display-list draws.
    for (const Instance& inst : mScene->instances) {
        glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
        glUniform4f(4, inst.color.r, inst.color.g, inst.color.b, float(inst.objectId));
        glBindVertexArray(mMeshes->vao(inst.mesh));
        glDrawElements(GL_TRIANGLES, mMeshes->indexCount(inst.mesh), GL_UNSIGNED_INT, nullptr);
        mStats.drawCalls += 1;
        mStats.triangles += mScene->meshes[inst.mesh].triangleCount();
        mStats.instances += 1;
        mStats.glCalls += 4; // two uniforms, bind, draw
    }
}

GBuffer GBufferRenderer::readBack() const {
    GBuffer g;
    g.width = width();
    g.height = height();
    g.position.resize(g.size());
    g.primitive.resize(g.size());
    mTarget.read(GL_COLOR_ATTACHMENT0, GL_RGBA, GL_FLOAT, g.position.data());
    mTarget.read(GL_COLOR_ATTACHMENT1, GL_RED_INTEGER, GL_UNSIGNED_INT, g.primitive.data());
    g.splitBackFaces();
    return g;
}

} // namespace sb
