#include "techniques/shadowmap/CubeMapGL.h"
#include "techniques/shadowmap/OmniLightsGL.h"

#include <glm/gtc/type_ptr.hpp>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthPassState.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr GLint kLightMatrixLocation = 8;      // common/depth.vert
constexpr GLint kFaceViewProjLocation = 12;    // shadowmap/cube_depth.geom
constexpr GLint kLayerBaseLocation = 18;       // shadowmap/cube_depth.geom
constexpr GLuint kFlatUnit = 0, kCubeUnit = 1; // shadowmap/omni_lighting.glsl, cube_lighting.frag

} // namespace

CubeMapGL::CubeMapGL() : GlTechnique(CubeMap::declaration()) {}

bool CubeMapGL::layeredAvailable(const Context& context) {
    return context.glMajor > 3 || (context.glMajor == 3 && context.glMinor >= 2);
}

void CubeMapGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), CubeMap::declaration().passes);
}

void CubeMapGL::setScene(const Scene& scene) {
    mLights.setScene(scene, OmniShape::Cube, int(properties().getInt(P::kResolution)));
    mCubeLights = CubeMap::cubes(mLights);
    mCulling.setScene(scene);
    mOmniCulling.setScene(scene);
}

void CubeMapGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(P::kResolution));
    mLayered = p.getBool(CubeMap::kLayered) && layeredAvailable(ctx.context);
    mCubes.allocate(GL_TEXTURE_CUBE_MAP_ARRAY, resolution, CubeFaces::kFaces * mLights.omniCount(), mLayered);
    mFlat.allocate(GL_TEXTURE_2D_ARRAY, resolution, mLights.flatCount(), false);

    const Defines base = ctx.submitter.defines();
    mFaceDepth = &ctx.programs.get({"common/depth.vert", "common/depth.frag", ""}, base);
    mContact.compile(p, ctx.programs, base);
    mLayeredDepth =
        mLayered ? &ctx.programs.get(
                       {"shadowmap/cube_depth.vert", "common/depth.frag", "shadowmap/cube_depth.geom"}, base)
                 : nullptr;
    // The depth passes have no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = CubeMap::lightingDefines(ctx.defines(), p, mLights);
    std::string key = mFaceDepth->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/cube_lighting.frag", ""}, lit);
    if (mLayeredDepth) key += "|layered:" + mLayeredDepth->key();
    setPermutationKey(key);
}

void CubeMapGL::renderCubesLayered(FrameContext& ctx) {
    mLayeredDepth->use();
    mCubes.beginLayered(); // every cube in the array belongs to a light that casts: clear them all
    for (size_t cube = 0; cube < mCubeLights.size(); ++cube) {
        const CubeMap::Cube& c = mCubeLights[cube];
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

void CubeMapGL::renderCubesSixPass(FrameContext& ctx) {
    mFaceDepth->use();
    for (size_t cube = 0; cube < mCubeLights.size(); ++cube) {
        const CubeMap::Cube& c = mCubeLights[cube];
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
            // Each face's own view decides, and its handedness sets the front face (faces may mirror).
            ctx.submitter.drawCulled(DrawSet::Casters, {faces.viewProjection(f), false}, mKeep);
            ++mFacesRendered;
        }
    }
}

void CubeMapGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    mCulled = 0;
    mFacesRendered = 0;
    if (mCubes.empty() && mFlat.empty()) return; // no light casts: no depth work at all
    DepthPassState state(int(p.getInt(P::kResolution)), float(p.getFloat(P::kBiasSlope)),
                         float(p.getFloat(P::kBiasConstant)));
    if (!mFlat.empty())
        mCulled += renderOmniFlatMaps(mLights, ctx.submitter, mCulling, *mFaceDepth, mFlat, 0, mKeep);
    if (!mCubes.empty()) {
        if (mLayered)
            renderCubesLayered(ctx);
        else
            renderCubesSixPass(ctx);
    }
}

void CubeMapGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    setOmniLightingUniforms(mLights, 0, 1); // flat maps at their index, cubes by cube index
    if (!mFlat.empty()) glBindTextureUnit(kFlatUnit, mFlat.texture());
    if (!mCubes.empty()) glBindTextureUnit(kCubeUnit, mCubes.texture());
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); // bilinear footprints and PCF taps cross face edges
    mContact.bind();
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    mContact.unbind();
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glBindTextureUnit(kFlatUnit, 0);
    glBindTextureUnit(kCubeUnit, 0);
}

void CubeMapGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); }, mContact.prePass(ctx),
        ContactShadows::kPass);
    mCounters =
        CubeMap::counters(s, int(properties().getInt(P::kResolution)), mLights, mFacesRendered, mCulled);
}

} // namespace sb
