#include "techniques/occluder/OccluderGL.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"
#include "scenes/ShadowPlaneChooser.h"
#include "scenes/ShadowWork.h"
#include "techniques/occluder/OccluderMeshCache.h"
#include "techniques/occluder/OccluderTextures.h"
#include "techniques/occluder/ReceiverSections.h"

namespace sb {

namespace {
constexpr GLuint kWorldPlaneBinding = 5, kCandidateBinding = 6; // shaders/occluder/lit.frag
// shaders/occluder/scene.vert
constexpr GLuint kPlaneBinding = 2, kInstanceBinding = 3, kMatrixBinding = 4, kSectionBinding = 7;

/// An automatic occluder texture's texels at options.resolution, its border whitened: baked once per
/// mesh, plane, options and renderer in a process (OccluderMeshCache.h). The bake's programs are asked
/// for either way, so the program cache sees what a bake would have compiled.
OccluderMeshCache::Texels bakedLayer(const CompileContext& ctx, const Mesh& mesh, const ShadowPlane& plane,
                                     const OccluderBakeOptions& options) {
    OccluderTextures::requestPrograms(ctx.programs);
    return OccluderMeshCache::texels(mesh, OccluderPlan::bakeKey(plane, options, ctx.context.renderer), [&] {
        const GLuint texture = OccluderTextures::bake(ctx.programs, mesh, plane, options);
        int w = 0, h = 0;
        std::vector<uint8_t> texels = OccluderTextures::readBack(texture, w, h);
        glDeleteTextures(1, &texture);
        return OccluderPlan::finishBake(texels, w, h, options.resolution);
    });
}
/// A texture file's texels, resampled to `resolution` (read each time: the file may change).
OccluderMeshCache::Texels loadedLayer(const std::string& path, int resolution) {
    const GLuint texture = OccluderTextures::load(path);
    int w = 0, h = 0;
    std::vector<uint8_t> texels = OccluderTextures::readBack(texture, w, h);
    glDeleteTextures(1, &texture);
    return std::make_shared<const std::vector<uint8_t>>(OccluderPlan::resample(texels, w, h, resolution));
}

} // namespace

OccluderGL::OccluderGL() : GlTechnique(Occluder::declaration()) {}

OccluderGL::~OccluderGL() {
    release();
}

void OccluderGL::release() {
    if (mTextures) glDeleteTextures(1, &mTextures);
    if (mPlaneBuffer) glDeleteBuffers(1, &mPlaneBuffer);
    if (mInstanceBuffer) glDeleteBuffers(1, &mInstanceBuffer);
    if (mMatrixBuffer) glDeleteBuffers(1, &mMatrixBuffer);
    if (mWorldPlaneBuffer) glDeleteBuffers(1, &mWorldPlaneBuffer);
    if (mCandidateBuffer) glDeleteBuffers(1, &mCandidateBuffer);
    if (mSectionBuffer) glDeleteBuffers(1, &mSectionBuffer);
    mTextures = mPlaneBuffer = mInstanceBuffer = mMatrixBuffer = mWorldPlaneBuffer = mCandidateBuffer = 0;
    mSectionBuffer = 0;
    mResolution = mLayers = 0;
}

void OccluderGL::setScene(const Scene& scene) {
    mutableInfo().effects = mPlan.setScene(scene, properties());
}

void OccluderGL::uploadWorldPlanes() {
    std::vector<OccluderPlan::GpuPlane> world;
    std::vector<glm::uvec2> table;
    mPlan.worldPlanes(world, table);
    if (!mWorldPlaneBuffer) glCreateBuffers(1, &mWorldPlaneBuffer);
    if (!mCandidateBuffer) glCreateBuffers(1, &mCandidateBuffer);
    const OccluderPlan::GpuPlane none{};
    glNamedBufferData(mWorldPlaneBuffer,
                      GLsizeiptr(std::max<size_t>(1, world.size()) * sizeof(OccluderPlan::GpuPlane)),
                      world.empty() ? &none : world.data(), GL_STATIC_DRAW);
    const glm::uvec2 zero(0);
    glNamedBufferData(mCandidateBuffer, GLsizeiptr(std::max<size_t>(1, table.size()) * sizeof(glm::uvec2)),
                      table.empty() ? &zero : table.data(), GL_STATIC_DRAW);
    mWorldPlanes = world.size();
}

void OccluderGL::buildTextures(const CompileContext& ctx) {
    const int resolution = int(properties().getInt(Occluder::kResolution));
    const std::vector<OccluderPlan::Texels> layers = mPlan.layers(
        ctx.scene, properties(),
        [&](const Mesh& mesh, const ShadowPlane& plane, const OccluderBakeOptions& options) {
            return bakedLayer(ctx, mesh, plane, options);
        },
        loadedLayer);
    if (mTextures) glDeleteTextures(1, &mTextures);
    mLayers = std::max<int>(1, int(layers.size()));
    mResolution = resolution;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mTextures);
    glTextureStorage3D(mTextures, 1, GL_R8, resolution, resolution, mLayers);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (size_t l = 0; l < layers.size(); ++l)
        glTextureSubImage3D(mTextures, 0, 0, 0, GLint(l), resolution, resolution, 1, GL_RED, GL_UNSIGNED_BYTE,
                            layers[l]->data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Bilinear magnification (section 5: "enabling bilinear filtering ... minimizes the artifacts");
    // clamping happens in the shader, as Appendix B does.
    glTextureParameteri(mTextures, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(mTextures, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(mTextures, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mTextures, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void OccluderGL::sceneChanged(const Scene& scene, uint32_t changes) {
    if (mPlan.sceneChanged(scene, changes)) uploadWorldPlanes();
}

void OccluderGL::compile(const CompileContext& ctx) {
    GLint components = 0;
    glGetIntegerv(GL_MAX_VERTEX_OUTPUT_COMPONENTS, &components);
    mPlan.checkVertexComponents(components, ctx.context.renderer);
    buildTextures(ctx);
    if (!mPlaneBuffer) glCreateBuffers(1, &mPlaneBuffer);
    if (!mInstanceBuffer) glCreateBuffers(1, &mInstanceBuffer);
    if (mPlan.textureMatrix()) {
        if (!mMatrixBuffer) glCreateBuffers(1, &mMatrixBuffer);
        glNamedBufferData(mMatrixBuffer,
                          GLsizeiptr(std::max<size_t>(1, mPlan.matrices().size()) * sizeof(glm::vec4)),
                          nullptr, GL_DYNAMIC_DRAW);
    }
    const std::vector<OccluderPlan::GpuPlane>& planes = mPlan.planes();
    const OccluderPlan::GpuPlane none{};
    glNamedBufferData(mPlaneBuffer,
                      GLsizeiptr(std::max<size_t>(1, planes.size()) * sizeof(OccluderPlan::GpuPlane)),
                      planes.empty() ? &none : planes.data(), GL_STATIC_DRAW);
    glNamedBufferData(mInstanceBuffer,
                      GLsizeiptr(std::max<size_t>(1, mPlan.instanceData().size()) * sizeof(glm::vec4)),
                      nullptr, GL_DYNAMIC_DRAW);
    uploadInstances();
    const std::vector<glm::uvec4>& sections = mPlan.sectionTable();
    if (!sections.empty()) {
        if (!mSectionBuffer) glCreateBuffers(1, &mSectionBuffer);
        glNamedBufferData(mSectionBuffer, GLsizeiptr(sections.size() * sizeof(glm::uvec4)), sections.data(),
                          GL_STATIC_DRAW);
    }
    if (mPlan.receiveAll()) uploadWorldPlanes();
    mProgram =
        &ctx.programs.get({"occluder/scene.vert", "occluder/lit.frag", ""}, mPlan.defines(ctx.defines()));
    setPermutationKey(mProgram->key());
}

void OccluderGL::uploadInstances() {
    const std::vector<glm::vec4>& data = mPlan.instanceData();
    if (!data.empty())
        glNamedBufferSubData(mInstanceBuffer, 0, GLsizeiptr(data.size() * sizeof(glm::vec4)), data.data());
}

void OccluderGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    if (mPlan.perInstance()) {
        mPlan.updateLightSpace();
        uploadInstances();
    }
    if (mPlan.textureMatrix()) {
        mPlan.updateMatrices();
        const std::vector<glm::vec4>& matrices = mPlan.matrices();
        if (!matrices.empty())
            glNamedBufferSubData(mMatrixBuffer, 0, GLsizeiptr(matrices.size() * sizeof(glm::vec4)),
                                 matrices.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMatrixBinding, mMatrixBuffer);
    }
    mProgram->use();
    glBindTextureUnit(0, mTextures);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPlaneBinding, mPlaneBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, mInstanceBuffer);
    if (!mPlan.sectionTable().empty())
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSectionBinding, mSectionBuffer);
    if (mPlan.receiveAll()) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorldPlaneBinding, mWorldPlaneBuffer);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCandidateBinding, mCandidateBuffer);
    }
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
    glBindTextureUnit(0, 0);
    mCounters = mPlan.counters(ctx.scene, ctx.submitter.stats(), mResolution, mLayers);
}

} // namespace sb
