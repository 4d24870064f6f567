#include "techniques/blob/BlobGL.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "techniques/gl/FrameState.h"

namespace sb {

namespace {
constexpr GLint kPlaneLocation = 12, kAlbedoLocation = 14; // shaders/blob/blob.frag
constexpr GLuint kBlobBinding = 4;                         // shaders/blob/blob.vert

} // namespace

BlobGL::BlobGL() : GlTechnique(sb::Blob::declaration()) {}

BlobGL::~BlobGL() {
    release();
}

void BlobGL::release() {
    if (mBlobBuffer) glDeleteBuffers(1, &mBlobBuffer);
    if (mEmptyVao) glDeleteVertexArrays(1, &mEmptyVao);
    mBlobBuffer = mEmptyVao = 0;
    mCapacity = 0;
}

void BlobGL::setScene(const Scene& scene) {
    release();
    mGround = sb::Blob::groundOf(scene);
    mMeshBounds = sb::Blob::meshBounds(scene);
    mReceiver.upload(mGround ? std::vector<ReceiverPlane>{*mGround} : std::vector<ReceiverPlane>{});
    glCreateVertexArrays(1, &mEmptyVao);
    glCreateBuffers(1, &mBlobBuffer);
}

void BlobGL::compile(const CompileContext& ctx) {
    Defines lit = withLightKinds(ctx.submitter.defines(), ctx.scene);
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    mLitProgram = &ctx.programs.get({"common/scene.vert", "common/lit.frag", ""}, lit);
    mReceiver.compile(ctx.programs);
    mBlobProgram = &ctx.programs.get({"blob/blob.vert", "blob/blob.frag", ""}, {});
    setPermutationKey(mLitProgram->key() + "|" + mBlobProgram->key());
}

void BlobGL::fitAll(const Scene& scene) {
    mBlobs.clear();
    if (mGround) sb::Blob::fitAll(scene, *mGround, mMeshBounds, properties(), mBlobs);
}

void BlobGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    mLitProgram->use();
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));

    ctx.passes.begin("blobs");
    fitAll(ctx.scene);
    if (!mBlobs.empty()) {
        // Orphaning upload: a fresh store each frame, so the driver never waits on last frame's draw.
        glNamedBufferData(mBlobBuffer, GLsizeiptr(mBlobs.size() * sizeof(Blob)), mBlobs.data(),
                          GL_STREAM_DRAW);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBlobBinding, mBlobBuffer);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(ReceiverStencil::kOffsetFactor, ReceiverStencil::kOffsetUnits);
        glDepthMask(GL_FALSE);
        mReceiver.mark(0, 1, GL_KEEP); // blobs stay on the ground's visible pixels, overlapping ones multiply
        ReceiverStencil::setDarkenBlending();
        mBlobProgram->use();
        glUniform4fv(kPlaneLocation, 1, glm::value_ptr(mGround->equation()));
        glUniform3fv(kAlbedoLocation, 1, glm::value_ptr(mGround->albedo));
        glBindVertexArray(mEmptyVao);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(mBlobs.size()));
        glBindVertexArray(0);
        resetFrameState();
    }
    mCounters = sb::Blob::counters(ctx.submitter.stats(), mBlobs.size());
}

} // namespace sb
