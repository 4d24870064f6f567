#include "techniques/planar/PlanarGL.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/Motion.h"
#include "scenes/ShadowWork.h"
#include "techniques/SubmissionPlan.h"
#include "techniques/gl/FrameState.h"
#include "techniques/gl/InstancedSubmitter.h"

namespace sb {

namespace {
constexpr GLint kFlattenLocation = 8, kPlaneLocation = 12, kLightLocation = 13, kAlbedoLightLocation = 14,
                kDarknessLocation = 15; // shaders/planar/shadow.*

} // namespace

PlanarGL::PlanarGL() : GlTechnique(Planar::declaration()) {}

PlanarGL::~PlanarGL() {
    release();
}

void PlanarGL::release() {
    if (mProxyInstances) glDeleteBuffers(1, &mProxyInstances);
    mProxyInstances = 0;
    mProxyBatches.clear();
}

void PlanarGL::setScene(const Scene& scene) {
    release();
    mPlanes = ReceiverPlane::find(scene);
    if (mPlanes.empty())
        std::cerr << "planar: scene '" << scene.name
                  << "' declares no receiver plane (a planar instance that receives and casts no shadow): "
                     "nothing is shadowed\n";
    mReceivers.upload(mPlanes);
    uploadProxies(scene);
    mCulling.setScene(scene);
}

void PlanarGL::uploadProxies(const Scene& scene) {
    // The casters' proxies, grouped by shape: one instanced draw per shape and flattening.
    const Scene shapes = Planar::unitShapes();
    mProxyMeshes.upload(shapes);
    const Planar::ProxyPlan plan = Planar::planProxies(scene, shapes);
    const std::vector<InstanceRecord>& records = plan.records;
    mProxyTriangles = plan.triangles;
    for (const Planar::ProxyBatch& b : plan.batches)
        mProxyBatches.push_back({mProxyMeshes.vao(b.shape), mProxyMeshes.indexCount(b.shape),
                                 GLsizei(b.first), GLsizei(b.count)});
    glCreateBuffers(1, &mProxyInstances);
    glNamedBufferStorage(mProxyInstances,
                         GLsizeiptr(std::max<size_t>(1, records.size()) * sizeof(InstanceRecord)),
                         records.empty() ? nullptr : records.data(), 0);
    for (size_t s = 0; s < shapes.meshes.size(); ++s)
        InstancedSubmitter::attachInstances(mProxyMeshes.vao(s), mProxyInstances);
}

void PlanarGL::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kLightsMoved) mProjections = Planar::projections(mPlanes, scene, mGuards);
    if (changes & kCastersMoved) mCulling.instancesMoved(scene);
    if ((changes & kCastersMoved) && mUseProxies) {
        release();
        uploadProxies(scene);
    }
}

void PlanarGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    mStencil = p.getBool(Planar::kStencil);
    mUseProxies = p.getEnum(Planar::kOccluder) == "proxy";
    mGuards = p.getBool(Planar::kGuards);
    mCull = p.getBool(Planar::kCull) && !mUseProxies;
    mDarkness = float(p.getFloat(Planar::kDarkness));
    mProjections = Planar::projections(mPlanes, ctx.scene, mGuards);

    Defines base = withLightKinds(ctx.submitter.defines(), ctx.scene);
    Defines lit = base;
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    mLitProgram = &ctx.programs.get({"common/scene.vert", "common/lit.frag", ""}, lit);
    mMarkProgram = &mReceivers.compile(ctx.programs);
    Defines shadow = lit;
    if (mGuards) shadow["GUARDS"] = "";
    mShadowProgram = &ctx.programs.get({"planar/shadow.vert", "planar/shadow.frag", ""}, shadow);
    Defines proxy = shadow;
    proxy["SB_INSTANCED"] = ""; // the proxies' own instance buffer
    mProxyProgram = &ctx.programs.get({"planar/shadow.vert", "planar/shadow.frag", ""}, proxy);
    const Program& occluders = mUseProxies ? *mProxyProgram : *mShadowProgram;
    std::string key = mLitProgram->key() + "|" + occluders.key();
    if (mStencil) key += "|" + mMarkProgram->key();
    setPermutationKey(key);
}

void PlanarGL::drawOccluders(FrameContext& ctx, const Projection& p, InstanceMask keep) {
    const ReceiverPlane& plane = mPlanes[p.plane];
    const Program& program = mUseProxies ? *mProxyProgram : *mShadowProgram;
    program.use();
    glUniformMatrix4fv(kFlattenLocation, 1, GL_FALSE, glm::value_ptr(p.matrix));
    glUniform4fv(kPlaneLocation, 1, glm::value_ptr(plane.equation()));
    glUniform4fv(kLightLocation, 1, glm::value_ptr(p.lightPos));
    glUniform4f(kAlbedoLightLocation, plane.albedo.r, plane.albedo.g, plane.albedo.b, float(p.light));
    glUniform1f(kDarknessLocation, mDarkness);
    if (!mUseProxies) {
        ctx.submitter.draw(DrawSet::Casters, keep);
        return;
    }
    for (const ProxyBatch& b : mProxyBatches) {
        glBindVertexArray(b.vao);
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, b.indexCount, GL_UNSIGNED_INT, nullptr, b.count,
                                            GLuint(b.first));
    }
    glBindVertexArray(0);
}

void PlanarGL::setShadowState(bool stencil) {
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(ReceiverStencil::kOffsetFactor, ReceiverStencil::kOffsetUnits);
    if (mGuards) { // only the guarded shader writes gl_ClipDistance (unwritten ones are undefined)
        glEnable(GL_CLIP_DISTANCE0);
        glEnable(GL_CLIP_DISTANCE1);
    }
    ReceiverStencil::setDarkenBlending(); // the light's term removed, its visibility channel scaled
    if (stencil) {
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
    } else {
        glDepthFunc(GL_LEQUAL); // the slides' "use bias": shadow polygons depth-tested, offset forwards
    }
}

void PlanarGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    mLitProgram->use();
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx)); // the flattened casters below: both faces

    if (mProjections.empty()) {
        const char* reason = ShadowWork::noneNeeded(ctx.scene);
        ctx.passes.skip("shadows", reason            ? reason
                                   : mPlanes.empty() ? "no receiver plane"
                                                     : "no light above a plane");
    } else {
        renderShadows(ctx);
    }
    setCounters(ctx);
}

void PlanarGL::renderShadows(FrameContext& ctx) {
    ctx.passes.begin("shadows");
    setShadowState(mStencil);
    int ref = 0;
    mCulled = 0;
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    for (const Projection& p : mProjections) {
        if (mCull) {
            // Casters whose flattened bounds miss the view darken nothing the camera sees.
            const size_t kept = mCulling.cullFlattened(p.matrix, viewProj, !mGuards, mKeep);
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept == 0) continue; // nothing to flatten: no receiver marking either
        }
        if (mStencil) {
            // A fresh reference value per flattening marks the receiver anew without clearing the
            // stencil: values left by the previous one never equal it. 255 flattenings, then a clear.
            if (++ref > 255) {
                glClear(GL_STENCIL_BUFFER_BIT);
                ref = 1;
            }
            // The slides' steps 3 and 4: the receiver marks the stencil where it is visible; the
            // occluder polygons, without depth test, pass where it is set and clear it (each pixel
            // darkens once).
            mReceivers.mark(p.plane, ref, GL_ZERO);
        }
        drawOccluders(ctx, p, mCull ? InstanceMask(mKeep) : InstanceMask{});
    }
    resetFrameState();
}

void PlanarGL::setCounters(const FrameContext& ctx) {
    mCounters = Planar::counters(ctx.submitter.stats(),
                                 {.planes = mPlanes.size(),
                                  .flattenings = mProjections.size(),
                                  .culled = mCulled,
                                  .proxyBatches = mProxyBatches.size(),
                                  .proxyTriangles = mProxyTriangles,
                                  .proxies = mUseProxies},
                                 ctx.scene);
}

} // namespace sb
