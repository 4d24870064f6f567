#include "techniques/shadowmap/OmniLightSet.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl/FrameTargets.h"
#include "scenes/LightFit.h"
#include "techniques/shadowmap/FlatLightFits.h"

namespace sb {

namespace {
constexpr GLint kShadowMatrixLocation = 8; // common/scene.vert, shadowmap/depth.vert
constexpr GLint kMapLocation = 16;         // shadowmap/omni_lighting.glsl: ivec2 (kind, layer) per light
constexpr GLint kDepthRangeLocation = 20;  // vec2 (near, far) per light
} // namespace

void OmniLightSet::setScene(const Scene& scene) {
    mLights.clear();
    mOmni = mFlat = mSkipped = mUnshadowed = 0;
    const glm::mat4& bias = FlatLightFits::textureBias();
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    for (size_t i = 0; i < count; ++i) {
        const Light& l = scene.lights[i];
        OmniLight o;
        if (!l.castsShadows) { // no map of any kind: its lookups are compiled out (common/lighting.glsl)
            o.kind = OmniMapKind::None;
            ++mUnshadowed;
        } else if (l.type == LightType::Point) {
            o.point = PointLightFit::fit(scene, l);
            o.kind = o.point.castsShadow ? OmniMapKind::Omni : OmniMapKind::None;
            o.index = o.point.castsShadow ? mOmni++ : mSkipped++;
        } else {
            o.kind = OmniMapKind::Flat;
            o.index = mFlat++;
            o.viewProj = fitLightViewProjection(scene, l);
            o.shadowMatrix = bias * o.viewProj;
        }
        mLights.push_back(o);
    }
}

void OmniLightSet::setLightingUniforms(int flatBase, int omniLayers) const {
    const int n = shaderLightCount();
    std::vector<glm::mat4> matrices(size_t(n), glm::mat4(1.0f));
    std::vector<glm::ivec2> maps(size_t(n), glm::ivec2(0));
    std::vector<glm::vec2> ranges(size_t(n), glm::vec2(0.0f, 1.0f));
    for (size_t i = 0; i < mLights.size(); ++i) {
        const OmniLight& o = mLights[i];
        matrices[i] = o.shadowMatrix;
        const int layer = o.kind == OmniMapKind::Flat ? flatBase + o.index : omniLayers * o.index;
        maps[i] = {int(o.kind), layer};
        ranges[i] = {o.point.nearZ, o.point.farZ};
    }
    glUniformMatrix4fv(kShadowMatrixLocation, n, GL_FALSE, glm::value_ptr(matrices[0]));
    glUniform2iv(kMapLocation, n, glm::value_ptr(maps[0]));
    glUniform2fv(kDepthRangeLocation, n, glm::value_ptr(ranges[0]));
}

size_t OmniLightSet::renderFlatMaps(Submitter& submitter, const InstanceCulling& culling,
                                    const Program& depthProgram, const DepthLayers& layers, int flatBase,
                                    std::vector<uint8_t>& keep) const {
    size_t culled = 0;
    bool bound = false;
    for (const OmniLight& o : mLights) {
        if (o.kind != OmniMapKind::Flat) continue;
        if (!bound) depthProgram.use();
        bound = true;
        layers.beginLayer(flatBase + o.index);
        glUniformMatrix4fv(kShadowMatrixLocation, 1, GL_FALSE, glm::value_ptr(o.viewProj));
        const size_t kept = culling.cull(o.viewProj, DrawSet::Casters, CullPlanes::All, keep);
        culled += culling.count(DrawSet::Casters) - kept;
        submitter.draw(DrawSet::Casters, keep);
    }
    return culled;
}

} // namespace sb
