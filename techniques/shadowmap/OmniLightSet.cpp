#include "techniques/shadowmap/OmniLightSet.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/LightFit.h"
#include "shading/ShaderLimits.h"
#include "techniques/FlatLightFits.h"

namespace sb {

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

OmniLightSet::LightingArrays OmniLightSet::lightingArrays(int flatBase, int omniLayers) const {
    const size_t n = size_t(shaderLightCount());
    LightingArrays a{std::vector<glm::mat4>(n, glm::mat4(1.0f)), std::vector<glm::ivec2>(n, glm::ivec2(0)),
                     std::vector<glm::vec2>(n, glm::vec2(0.0f, 1.0f))};
    for (size_t i = 0; i < mLights.size(); ++i) {
        const OmniLight& o = mLights[i];
        a.shadowMatrices[i] = o.shadowMatrix;
        const int layer = o.kind == OmniMapKind::Flat ? flatBase + o.index : omniLayers * o.index;
        a.maps[i] = {int(o.kind), layer};
        a.depthRanges[i] = {o.point.nearZ, o.point.farZ};
    }
    return a;
}

size_t OmniLightSet::cullFlatCasters(const OmniLight& light, const InstanceCulling& culling,
                                     std::vector<uint8_t>& keep) const {
    const size_t kept = culling.cull(light.viewProj, DrawSet::Casters, CullPlanes::All, keep);
    return culling.count(DrawSet::Casters) - kept;
}

} // namespace sb
