#include "techniques/shadowmap/PcssGL.h"
#include "techniques/shadowmap/FlatLightsGL.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/PoissonDisk.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// shaders/shadowmap/pcss.frag: uPcssLight[LIGHT_COUNT], uPcssSearch[LIGHT_COUNT], the two kernels.
constexpr GLint kLightLocation = 12;
constexpr GLint kSearchLocation = 16;
constexpr GLint kBlockerKernelLocation = 20; // uBlockerKernel[Pcss::kMaxTaps]
constexpr GLint kFilterKernelLocation =
    kBlockerKernelLocation + Pcss::kMaxTaps;                            // uFilterKernel[Pcss::kMaxTaps]
constexpr GLint kTapsLocation = kFilterKernelLocation + Pcss::kMaxTaps; // uTaps
constexpr GLint kSearchUnit = 0, kCompareUnit = 1;
/// The filter's Poisson disk differs from the search's: two seeds.
constexpr uint64_t kFilterSeed = PoissonDisk::kSeed ^ 0x46494c544552ull;

/// Row r of a matrix (GLM is column-major).
glm::vec4 row(const glm::mat4& m, int r) {
    return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
}

/// The light size the scene gives `light` (0 when it has no extent), see PcssGL.h.
float sceneLightSize(const Light& light) {
    if (light.shape == LightShape::Point) return 0.0f;
    if (light.type == LightType::Directional)
        return 2.0f * std::tan(glm::radians(std::clamp(light.angularRadiusDeg, 0.0f, 89.0f)));
    if (light.shape == LightShape::Rect) // the disk of the same area
        return 2.0f * std::sqrt(std::max(light.size.x * light.size.y, 0.0f) / float(M_PI));
    return 2.0f * std::max(light.size.x, 0.0f); // disk and sphere: the diameter
}

/// Linear depth (PcssGL::LightParams) of the nearest corner of the casters' bounds, held within the
/// map's depth range. Both a perspective map's w and an orthographic map's depth are linear in the world
/// position, so the nearest point of a box is one of its corners.
float nearestCasterDepth(const Scene& scene, const glm::mat4& lightViewProj, const PcssGL::LightParams& lp) {
    Aabb casters = scene.computeBounds(true);
    if (casters.empty()) return lp.nearZ;
    float nearest = lp.farZ;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? casters.max.x : casters.min.x,
                               (c & 2) ? casters.max.y : casters.min.y,
                               (c & 4) ? casters.max.z : casters.min.z);
        const glm::vec4 clip = lightViewProj * glm::vec4(corner, 1.0f);
        // Perspective: w is the depth along the axis; orthographic: window depth times (far - near).
        const float z = lp.perspective ? clip.w : (0.5f * clip.z / clip.w + 0.5f) * lp.farZ;
        nearest = std::min(nearest, z);
    }
    return std::clamp(nearest, lp.nearZ, lp.farZ);
}
} // namespace

PcssGL::PcssGL() : GlTechnique(Pcss::declaration()) {}

PcssGL::~PcssGL() {
    if (mSearchSampler) glDeleteSamplers(1, &mSearchSampler);
    if (mCompareSampler) glDeleteSamplers(1, &mCompareSampler);
}

PcssGL::LightParams PcssGL::lightParams(const Scene& scene, const Light& light,
                                        const glm::mat4& lightViewProj, float sizeOverride) {
    LightParams lp;
    const glm::vec4 r0 = row(lightViewProj, 0), r1 = row(lightViewProj, 1);
    const glm::vec4 r2 = row(lightViewProj, 2), r3 = row(lightViewProj, 3);
    lp.extent = glm::vec2(2.0f / glm::length(glm::vec3(r0)), 2.0f / glm::length(glm::vec3(r1)));
    lp.perspective = glm::dot(glm::vec3(r3), glm::vec3(r3)) > 0.0f;
    if (lp.perspective) {
        // Clip z = alpha w + beta (glm::perspective): alpha = (f + n) / (f - n), beta = -2 f n / (f - n).
        const float alpha = glm::dot(glm::vec3(r2), glm::vec3(r3)) / glm::dot(glm::vec3(r3), glm::vec3(r3));
        const float beta = r2.w - alpha * r3.w;
        lp.nearZ = -beta / (alpha + 1.0f);
        lp.farZ = beta / (1.0f - alpha);
    } else {
        lp.nearZ = 0.0f; // depth from the near plane: 2 / |row 2| = far - near
        lp.farZ = 2.0f / glm::length(glm::vec3(r2));
    }
    lp.nearestCaster = nearestCasterDepth(scene, lightViewProj, lp);
    float size = sizeOverride > 0.0f ? sizeOverride : sceneLightSize(light);
    if (!(size > 0.0f)) {
        lp.defaulted = true;
        size = 2.0f * std::tan(glm::radians(kDefaultAngularRadiusDeg));
        if (light.type != LightType::Directional) {
            Aabb casters = scene.computeBounds(true);
            if (casters.empty()) casters = scene.computeBounds(false);
            size *= std::max(glm::length(casters.center() - light.position), 1e-3f);
        }
    }
    lp.size = size;
    return lp;
}

void PcssGL::setScene(const Scene& scene) {
    mLights.setScene(scene, "pcss");
    mCulling.setScene(scene);
}

void PcssGL::createSamplers() {
    if (mSearchSampler) return;
    // Outside the map lies no caster (the light camera is fitted to them): a border depth of 1 makes
    // taps that leave it find no blocker and compare lit.
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glCreateSamplers(1, &mSearchSampler);
    glCreateSamplers(1, &mCompareSampler);
    for (GLuint s : {mSearchSampler, mCompareSampler}) {
        glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
    }
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

void PcssGL::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitLightSizes(scene);
}

void PcssGL::fitLightSizes(const Scene& scene) {
    mParams.clear();
    for (size_t i = 0; i < mLights.size(); ++i)
        mParams.push_back(lightParams(scene, scene.lights[i], mLights.viewProj()[i],
                                      float(properties().getFloat(Pcss::kLightSize))));
}

void PcssGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int layers = std::max<int>(1, int(mLights.size()));
    // The texture's own sampling state is unused: both units sample through the sampler objects.
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, int(p.getInt(P::kResolution)), layers, false);
    createSamplers();
    mBlockerKernel = PoissonDisk::generate(int(p.getInt(Pcss::kBlockerTaps)));
    mFilterKernel = PoissonDisk::generate(int(p.getInt(Pcss::kFilterTaps)), kFilterSeed);
    fitLightSizes(ctx.scene);

    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"shadowmap/depth.vert", "shadowmap/depth.frag", ""}, base);
    Defines lit = ctx.defines(); // the depth pass has no shadow to apply
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(layers);
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/pcss.frag", ""}, lit);
    setPermutationKey(mDepthProgram->key() + "|" + mLightingProgram->key());
}

void PcssGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    mDepthProgram->use();
    mCulled = renderFlatDepth(mLights, ctx.submitter, mCulling, mMaps, mKeep);
}

void PcssGL::uploadLightUniforms() const {
    std::vector<glm::vec4> light;
    std::vector<glm::vec4> search;
    for (const LightParams& lp : mParams) {
        light.emplace_back(lp.size, lp.perspective ? 1.0f : 0.0f, lp.nearZ, lp.farZ);
        search.emplace_back(lp.extent, lp.nearestCaster, 0.0f);
    }
    if (!light.empty()) {
        glUniform4fv(kLightLocation, GLsizei(light.size()), glm::value_ptr(light[0]));
        glUniform4fv(kSearchLocation, GLsizei(search.size()), glm::value_ptr(search[0]));
    }
    glUniform2i(kTapsLocation, GLint(mBlockerKernel.size()), GLint(mFilterKernel.size()));
    glUniform2fv(kBlockerKernelLocation, GLsizei(mBlockerKernel.size()), glm::value_ptr(mBlockerKernel[0]));
    glUniform2fv(kFilterKernelLocation, GLsizei(mFilterKernel.size()), glm::value_ptr(mFilterKernel[0]));
}

void PcssGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLightingProgram->use();
    setFlatShadowMatrices(mLights);
    uploadLightUniforms();
    // One texture, two samplers: raw depths for the blocker search, comparison for the filter.
    glBindTextureUnit(kSearchUnit, mMaps.texture());
    glBindTextureUnit(kCompareUnit, mMaps.texture());
    glBindSampler(kSearchUnit, mSearchSampler);
    glBindSampler(kCompareUnit, mCompareSampler);
    ctx.submitter.draw(DrawSet::All);
    glBindSampler(kSearchUnit, 0);
    glBindSampler(kCompareUnit, 0);
    glBindTextureUnit(kSearchUnit, 0);
    glBindTextureUnit(kCompareUnit, 0);
}

void PcssGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); });
    double defaulted = 0.0;
    for (const LightParams& lp : mParams) defaulted += lp.defaulted ? 1.0 : 0.0;
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"shadow_map_texels", double(mMaps.size()) * mMaps.size() * double(mLights.shadowed())},
                 {"lights_unshadowed", double(mLights.size() - mLights.shadowed())},
                 {"casters_culled", double(mCulled)},
                 {"blocker_taps", double(mBlockerKernel.size())},
                 {"filter_taps", double(mFilterKernel.size())},
                 {"light_size", mParams.empty() ? 0.0 : double(mParams[0].size)},
                 {"light_size_defaulted", defaulted}};
}

} // namespace sb
