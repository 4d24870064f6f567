#include "techniques/shadowmap/CubeMapTechnique.h"

#include <glm/gtc/type_ptr.hpp>

#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr const char* kLayered = "layered";
constexpr GLint kLightMatrixLocation = 8;      // shadowmap/depth.vert
constexpr GLint kFaceViewProjLocation = 12;    // shadowmap/cube_depth.geom
constexpr GLint kLayerBaseLocation = 18;       // shadowmap/cube_depth.geom
constexpr GLuint kFlatUnit = 0, kCubeUnit = 1; // shadowmap/omni_lighting.glsl, cube_lighting.frag

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("1024", "width and height of each cube face and of each spot/directional map (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart on the face"),
        flag(kLayered, "true",
             "one pass per light with a geometry shader routing triangles to faces (true, where the "
             "context allows it), or six passes per light with per-face caster culling (false)"),
    };
}
} // namespace

TechniqueInfo CubeMapTechnique::describe() {
    return {.name = "cubemap",
            .description = "omnidirectional shadow mapping: a depth cube map per point light",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{"GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            .quality = {
                {P::kResolution, {"256", "512", "1024", "2048"}},
                P::pcfSweep(),
                P::biasConstantSweep(),
                P::biasSlopeSweep(),
            }};
}

CubeMapTechnique::CubeMapTechnique() : Technique(describe()) {}

bool CubeMapTechnique::layeredAvailable(const Context& context) {
    return context.glMajor > 3 || (context.glMajor == 3 && context.glMinor >= 2);
}

void CubeMapTechnique::setScene(const Scene& scene) {
    mLights.setScene(scene);
    mCubeLights.clear();
    for (const OmniLight& o : mLights.lights())
        if (o.kind == OmniMapKind::Omni)
            mCubeLights.push_back({o.point, CubeFaces(o.point.position, o.point.nearZ, o.point.farZ)});
    mCulling.setScene(scene);
    mOmniCulling.setScene(scene);
}

void CubeMapTechnique::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(P::kResolution));
    mLayered = p.getBool(kLayered) && layeredAvailable(ctx.context);
    mCubes.allocate(GL_TEXTURE_CUBE_MAP_ARRAY, resolution, CubeFaces::kFaces * mLights.omniCount(), mLayered);
    mFlat.allocate(GL_TEXTURE_2D_ARRAY, resolution, mLights.flatCount(), false);

    const Defines base = ctx.submitter.defines();
    mFaceDepth = &ctx.programs.get({"shadowmap/depth.vert", "shadowmap/depth.frag", ""}, base);
    mLayeredDepth = mLayered ? &ctx.programs.get({"shadowmap/cube_depth.vert", "shadowmap/depth.frag",
                                                  "shadowmap/cube_depth.geom"},
                                                 base)
                             : nullptr;
    Defines lit = ctx.defines(); // the depth passes have no shadow to apply
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(mLights.shaderLightCount());
    lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    if (mLights.flatCount() > 0) lit["FLAT_MAPS"] = "";
    if (mLights.omniCount() > 0) lit["OMNI_MAPS"] = "";
    mLighting = &ctx.programs.get({"common/scene.vert", "shadowmap/cube_lighting.frag", ""}, lit);
    std::string key = mFaceDepth->key() + "|" + mLighting->key();
    if (mLayeredDepth) key += "|layered:" + mLayeredDepth->key();
    setPermutationKey(key);
}

void CubeMapTechnique::renderCubesLayered(FrameContext& ctx) {
    mLayeredDepth->use();
    mCubes.beginLayered(); // every cube in the array belongs to a light that casts: clear them all
    for (size_t cube = 0; cube < mCubeLights.size(); ++cube) {
        const Cube& c = mCubeLights[cube];
        const size_t kept = mOmniCulling.cullSphere(c.light.position, c.light.farZ, mRange);
        mCulled += mOmniCulling.casters() - kept;
        if (kept == 0) continue;
        glUniformMatrix4fv(kFaceViewProjLocation, CubeFaces::kFaces, GL_FALSE,
                           glm::value_ptr(c.faces.viewProjections()[0]));
        glUniform1i(kLayerBaseLocation, CubeFaces::kFaces * int(cube));
        ctx.submitter.draw(DrawSet::Casters, mRange);
        mFacesRendered += CubeFaces::kFaces;
    }
}

void CubeMapTechnique::renderCubesSixPass(FrameContext& ctx) {
    mFaceDepth->use();
    for (size_t cube = 0; cube < mCubeLights.size(); ++cube) {
        const Cube& c = mCubeLights[cube];
        const CubeFaces& faces = c.faces;
        mOmniCulling.cullSphere(c.light.position, c.light.farZ, mRange);
        for (int f = 0; f < CubeFaces::kFaces; ++f) {
            mCubes.beginLayer(CubeFaces::kFaces * int(cube) + f);
            mCulling.cull(faces.viewProjection(f), DrawSet::Casters, CullPlanes::All, mKeep);
            size_t kept = 0;
            for (size_t i = 0; i < mKeep.size(); ++i) kept += (mKeep[i] &= mRange[i]) ? 1 : 0;
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept == 0) continue; // the cleared face is the answer: nothing casts into it
            glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(faces.viewProjection(f)));
            ctx.submitter.draw(DrawSet::Casters, mKeep);
            ++mFacesRendered;
        }
    }
}

void CubeMapTechnique::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    mCulled = 0;
    mFacesRendered = 0;
    if (mCubes.empty() && mFlat.empty()) return; // no light casts: no depth work at all
    DepthPassState state(int(p.getInt(P::kResolution)), float(p.getFloat(P::kBiasSlope)),
                         float(p.getFloat(P::kBiasConstant)));
    if (!mFlat.empty())
        mCulled += mLights.renderFlatMaps(ctx.submitter, mCulling, *mFaceDepth, mFlat, 0, mKeep);
    if (!mCubes.empty()) {
        if (mLayered)
            renderCubesLayered(ctx);
        else
            renderCubesSixPass(ctx);
    }
}

void CubeMapTechnique::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting->use();
    mLights.setLightingUniforms(0, 1); // flat maps at their index, cubes by cube index
    if (!mFlat.empty()) glBindTextureUnit(kFlatUnit, mFlat.texture());
    if (!mCubes.empty()) glBindTextureUnit(kCubeUnit, mCubes.texture());
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); // bilinear footprints and PCF taps cross face edges
    ctx.submitter.draw(DrawSet::All);
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindTextureUnit(kFlatUnit, 0);
    glBindTextureUnit(kCubeUnit, 0);
}

void CubeMapTechnique::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); });
    const double res = double(properties().getInt(P::kResolution));
    const double maps = double(CubeFaces::kFaces * mLights.omniCount() + mLights.flatCount());
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"shadow_map_texels", res * res * maps},
                 {"faces_rendered", double(mFacesRendered)},
                 {"casters_culled", double(mCulled)},
                 {"lights_skipped", double(mLights.skippedCount())},
                 {"lights_unshadowed", double(mLights.unshadowedCount())}};
}

} // namespace sb
