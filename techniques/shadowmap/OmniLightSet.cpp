#include "techniques/shadowmap/OmniLightSet.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/LightFit.h"
#include "shading/ShaderLimits.h"
#include "techniques/FlatLightFits.h"

namespace sb {

void OmniLightSet::setScene(const Scene& scene, OmniShape shape, int resolution) {
    mShape = shape;
    mResolution = resolution;
    mCubeShadow.clear();
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
        mCubeShadow.emplace_back();
        if (o.kind == OmniMapKind::Omni && shape == OmniShape::Cube) {
            const CubeFaces faces(o.point.position, o.point.nearZ, o.point.farZ);
            for (int f = 0; f < CubeFaces::kFaces; ++f)
                mCubeShadow.back()[size_t(f)] = bias * faces.viewProjection(f);
        }
    }
}

std::optional<MapPoint> OmniLightSet::texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const {
    if (light >= mLights.size()) return std::nullopt;
    const OmniLight& o = mLights[light];
    if (o.kind == OmniMapKind::Flat && looksUp(o.shadowMatrix, at.position))
        return MapPoint{0, mResolution, projectedTexel(o.shadowMatrix, mResolution, q)};
    if (o.kind == OmniMapKind::Omni) return omniTexel(light, o, at, q);
    return std::nullopt;
}

std::optional<MapPoint> OmniLightSet::omniTexel(size_t light, const OmniLight& o, const ShadedPoint& at,
                                                const glm::dvec3& q) const {
    const glm::dvec3 origin = glm::dvec3(o.point.position);
    const glm::dvec3 v = at.position - origin;
    const double nearZ = o.point.nearZ, farZ = o.point.farZ;
    if (mShape == OmniShape::Cube) {
        const glm::dvec3 a = glm::abs(v);
        const double z = std::max(a.x, std::max(a.y, a.z)); // cube_lighting.frag: the major-axis distance
        if (z <= nearZ || z >= farZ) return std::nullopt;
        const int face = CubeFaces::faceOf(glm::vec3(v));
        return MapPoint{face, mResolution, projectedTexel(mCubeShadow[light][size_t(face)], mResolution, q)};
    }
    const double dist = glm::length(v);
    if (dist <= nearZ || dist >= farZ) return std::nullopt;
    const int half = -v.y >= 0.0 ? 0 : 1; // paraboloidFrame(v, 0).z = -v.y
    return MapPoint{half, mResolution, paraboloidTexel(q - origin, half, mResolution)};
}

glm::dvec2 OmniLightSet::paraboloidTexel(const glm::dvec3& v, int half, int resolution) {
    glm::dvec3 p(v.x, v.z, -v.y); // the front half's frame; the back one turned 180 degrees about x
    if (half != 0) p = {p.x, -p.y, -p.z};
    const double dist = glm::length(p);
    const glm::dvec3 d = dist > 0.0 ? p / dist : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec2 uv = 0.5 * glm::dvec2(d) / (1.0 + d.z) + 0.5;
    return uv * double(resolution);
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
