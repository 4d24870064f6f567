#include "techniques/FlatLightFits.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/LightFit.h"
#include "shading/ShaderLimits.h"
#include "techniques/LightFitProperties.h"
#include "techniques/PointLightRefusal.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

const glm::mat4& FlatLightFits::textureBias() {
    static const glm::mat4 kBias =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    return kBias;
}

void FlatLightFits::setScene(const Scene& scene, const std::string& technique, const PropertySet& p,
                             PointLights points) {
    setScene(scene, technique, LightFitProperties::lightFit(p),
             int(p.getInt(ShadowMapProperties::kResolution)), points);
}

void FlatLightFits::setScene(const Scene& scene, const std::string& technique, const LightFit& fit,
                             int resolution, PointLights points) {
    mViewProj.clear();
    mShadowMatrix.clear();
    mCastsShadows.clear();
    mResolution = resolution;
    const bool recount = !(scene.motion && mCoverageCounted);
    if (recount) mCoverage = {};
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    for (size_t i = 0; i < count; ++i) {
        const Light& l = scene.lights[i];
        const bool unmapped = points == PointLights::Unmapped && l.type == LightType::Point;
        mCastsShadows.push_back(l.castsShadows && !unmapped);
        if (!mCastsShadows.back()) { // no map, never looked up: no fit (a point light has none)
            mViewProj.emplace_back(1.0f);
            mShadowMatrix.push_back(textureBias());
            continue;
        }
        PointLightRefusal::refuse(l, i, technique);
        mViewProj.push_back(fitLightViewProjection(scene, l, fit));
        mShadowMatrix.push_back(textureBias() * mViewProj.back());
        if (recount) mCoverage += MapCoverage::count(scene, mViewProj.back(), resolution);
    }
    mCoverageCounted = true;
}

float FlatLightFits::texelWorldSize(const glm::mat4& lightViewProj, int resolution) {
    auto rowLength = [&](int r) {
        return glm::length(glm::vec3(lightViewProj[0][r], lightViewProj[1][r], lightViewProj[2][r]));
    };
    return 2.0f / (std::min(rowLength(0), rowLength(1)) * float(resolution));
}

float FlatLightFits::farthestW(const glm::mat4& lightViewProj, const Aabb& bounds) {
    float w = 1.0f;
    if (!bounds.empty())
        for (const glm::vec3& c : bounds.corners())
            w = std::max(w, std::abs((lightViewProj * glm::vec4(c, 1.0f)).w));
    return w;
}

std::optional<MapPoint> FlatLightFits::texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const {
    if (light >= size() || !castsShadow(light) || !looksUp(mShadowMatrix[light], at.position))
        return std::nullopt;
    return MapPoint{0, mResolution, projectedTexel(mShadowMatrix[light], mResolution, q)};
}

size_t FlatLightFits::shadowed() const {
    return size_t(std::count(mCastsShadows.begin(), mCastsShadows.end(), uint8_t(1)));
}

size_t FlatLightFits::cullCasters(size_t light, const InstanceCulling& culling, std::vector<uint8_t>& keep,
                                  const ViewCull* view) const {
    size_t kept = culling.cull(mViewProj[light], DrawSet::Casters, CullPlanes::All, keep);
    if (view)
        kept = culling.keepReachingView((*view->lights)[light], view->reach, view->margins[light], keep);
    return culling.count(DrawSet::Casters) - kept;
}

} // namespace sb
