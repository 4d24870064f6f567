#include "techniques/shadowmap/ShadowMapTechnique.h"

#include <algorithm>
#include <array>
#include <cfloat>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/LightFit.h"

namespace sb {

namespace {
constexpr const char* kResolution = "resolution";
constexpr const char* kBiasConstant = "bias_constant";
constexpr const char* kBiasSlope = "bias_slope";
constexpr const char* kPcf = "pcf";
constexpr const char* kHardwareCompare = "hardware_compare";
constexpr GLint kLightMatrixLocation = 8; // shadowmap/depth.vert and common/scene.vert

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(kResolution, "2048", 16, 8192, "shadow map width and height (texels)"),
        real(kBiasConstant, "2", 0, 10000,
             "glPolygonOffset units: constant depth bias in depth-buffer steps"),
        real(kBiasSlope, "2", 0, 64, "glPolygonOffset factor: slope-scaled depth bias"),
        integer(kPcf, "1", 1, 9, "PCF kernel width: pcf x pcf taps one texel apart"),
        flag(kHardwareCompare, "true",
             "depth-compare sampler with bilinear filtering (true) or nearest fetch + shader compare"),
    };
}
} // namespace

ShadowMapTechnique::ShadowMapTechnique()
    : Technique(
          {.name = "shadowmap",
           .description = "two-pass shadow mapping: depth from each light, compare in the lighting pass",
           .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                      Effect::MultipleLights,
           .capabilities = {{"GL 4.5", 4, 5, ""}},
           .passes = {"depth", "lighting"},
           .properties = declareProperties(),
           // What `bench accuracy --sweep` walks, one knob at a time around the defaults.
           .quality = {
               {kResolution, {"256", "512", "1024", "2048", "4096"}},
               {kPcf, {"1", "3", "5"}},
               {kBiasConstant, {"0.5", "2", "8", "32"}},
               {kBiasSlope, {"0.5", "2", "4"}},
           }}) {}

ShadowMapTechnique::~ShadowMapTechnique() {
    releaseMaps();
}

void ShadowMapTechnique::setScene(const Scene& scene) {
    mLightViewProj.clear();
    mShadowMatrix.clear();
    size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    const glm::mat4 bias =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    for (size_t i = 0; i < count; ++i) {
        const Light& l = scene.lights[i];
        if (l.type == LightType::Point)
            throw Error("shadowmap: light " + std::to_string(i) +
                            " is a point light, which needs a cube shadow map (not implemented here); use "
                            "--light directional or --light spot",
                        ExitCode::Unsupported);
        mLightViewProj.push_back(fitLightViewProjection(scene, l));
        mShadowMatrix.push_back(bias * mLightViewProj.back());
    }
}

void ShadowMapTechnique::releaseMaps() {
    if (!mFbos.empty()) glDeleteFramebuffers(GLsizei(mFbos.size()), mFbos.data());
    mFbos.clear();
    if (mDepthArray) glDeleteTextures(1, &mDepthArray);
    mDepthArray = 0;
    mResolution = mLayers = 0;
}

void ShadowMapTechnique::allocateMaps(int resolution, int layers) {
    if (resolution == mResolution && layers == mLayers) return;
    releaseMaps();
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mDepthArray);
    glTextureStorage3D(mDepthArray, 1, GL_DEPTH_COMPONENT24, resolution, resolution, layers);
    glTextureParameteri(mDepthArray, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mDepthArray, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    mFbos.resize(size_t(layers));
    glCreateFramebuffers(layers, mFbos.data());
    for (int i = 0; i < layers; ++i) {
        glNamedFramebufferTextureLayer(mFbos[size_t(i)], GL_DEPTH_ATTACHMENT, mDepthArray, 0, i);
        glNamedFramebufferDrawBuffer(mFbos[size_t(i)], GL_NONE);
        glNamedFramebufferReadBuffer(mFbos[size_t(i)], GL_NONE);
        GLenum status = glCheckNamedFramebufferStatus(mFbos[size_t(i)], GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw Error("shadowmap: depth framebuffer incomplete (status 0x" + std::to_string(status) + ")",
                        ExitCode::Failure);
    }
    mResolution = resolution;
    mLayers = layers;
}

void ShadowMapTechnique::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    int layers = std::max<int>(1, int(mLightViewProj.size()));
    allocateMaps(int(p.getInt(kResolution)), layers);
    bool hw = p.getBool(kHardwareCompare);
    // Hardware compare: LINEAR filters the four comparison results (bilinear PCF); without it the shader
    // compares NEAREST depth values itself.
    glTextureParameteri(mDepthArray, GL_TEXTURE_COMPARE_MODE, hw ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(mDepthArray, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(mDepthArray, GL_TEXTURE_MIN_FILTER, hw ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(mDepthArray, GL_TEXTURE_MAG_FILTER, hw ? GL_LINEAR : GL_NEAREST);

    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"shadowmap/depth.vert", "shadowmap/depth.frag", ""}, base);
    Defines lit = base;
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(layers);
    lit["PCF_SIZE"] = std::to_string(p.getInt(kPcf));
    if (hw) lit["HW_COMPARE"] = "";
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/lighting.frag", ""}, lit);
    setPermutationKey(mDepthProgram->key() + "|" + mLightingProgram->key());
}

void ShadowMapTechnique::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    glViewport(0, 0, mResolution, mResolution);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(float(p.getFloat(kBiasSlope)), float(p.getFloat(kBiasConstant)));
    mDepthProgram->use();
    for (size_t i = 0; i < mLightViewProj.size(); ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, mFbos[i]);
        glClear(GL_DEPTH_BUFFER_BIT);
        glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(mLightViewProj[i]));
        ctx.submitter.draw(DrawSet::Casters);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void ShadowMapTechnique::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLightingProgram->use();
    if (!mShadowMatrix.empty())
        glUniformMatrix4fv(kLightMatrixLocation, GLsizei(mShadowMatrix.size()), GL_FALSE,
                           glm::value_ptr(mShadowMatrix[0]));
    glBindTextureUnit(0, mDepthArray);
    ctx.submitter.draw(DrawSet::All);
    glBindTextureUnit(0, 0);
}

void ShadowMapTechnique::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("depth");
    renderDepth(ctx);
    ctx.passes.begin("lighting");
    renderLighting(ctx);
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"shadow_map_texels", double(mResolution) * mResolution * double(mLightViewProj.size())}};
}

} // namespace sb
