#include "techniques/shadowmap/MomentMapFits.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "techniques/FlatLightFits.h"
#include "techniques/LightFitProperties.h"
#include "techniques/PointLightRefusal.h"

namespace sb {

namespace {
/// Row r of a column-major matrix.
glm::dvec4 row(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

/// The corners of `box` and `viewProj`'s clip volume intersected: the points where three of their 12
/// bounding planes (n.p + d >= 0 inside) meet and all 12 hold. Any linear or convex function (depth,
/// distance to a point) takes its extremes over the intersection at one of them. Empty when the box lies
/// outside the clip volume.
std::vector<glm::dvec3> clippedCorners(const Aabb& box, const glm::mat4& viewProj) {
    std::vector<glm::dvec4> planes;
    for (int a = 0; a < 3; ++a) {
        glm::dvec4 lo(0.0), hi(0.0);
        lo[a] = 1.0;
        lo.w = -double(box.min[a]);
        hi[a] = -1.0;
        hi.w = double(box.max[a]);
        planes.push_back(lo);
        planes.push_back(hi);
    }
    const glm::dvec4 w = row(viewProj, 3);
    for (int r = 0; r < 3; ++r) {
        planes.push_back(w + row(viewProj, r));
        planes.push_back(w - row(viewProj, r));
    }
    auto inside = [&](const glm::dvec3& p) {
        for (const glm::dvec4& q : planes) {
            const double tolerance =
                1e-9 * (glm::length(glm::dvec3(q)) * (glm::length(p) + 1.0) + std::abs(q.w));
            if (glm::dot(glm::dvec3(q), p) + q.w < -tolerance) return false;
        }
        return true;
    };
    std::vector<glm::dvec3> out;
    const size_t n = planes.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                const glm::dmat3 a = glm::transpose(
                    glm::dmat3(glm::dvec3(planes[i]), glm::dvec3(planes[j]), glm::dvec3(planes[k])));
                const double scale = glm::length(glm::dvec3(planes[i])) * glm::length(glm::dvec3(planes[j])) *
                                     glm::length(glm::dvec3(planes[k]));
                if (std::abs(glm::determinant(a)) <= 1e-12 * scale) continue; // two planes parallel
                const glm::dvec3 p = glm::inverse(a) * -glm::dvec3(planes[i].w, planes[j].w, planes[k].w);
                if (inside(p)) out.push_back(p);
            }
    return out;
}

/// Every instance's clipped corners for the light camera `viewProj`.
std::vector<glm::dvec3> cornersInFrustum(const Scene& scene, const glm::mat4& viewProj) {
    std::vector<glm::dvec3> out;
    for (const Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) continue;
        const Aabb box = transformBounds(scene.meshBoundsOf(inst.mesh), inst.model);
        if (box.empty()) continue;
        const std::vector<glm::dvec3> c = clippedCorners(box, viewProj);
        out.insert(out.end(), c.begin(), c.end());
    }
    return out;
}

/// Directional lights: the depth plane mapping the window depth 0.5 z_clip + 0.5 of `viewProj`
/// (orthographic, so linear) from [zmin, zmax], the range the scene covers inside the map's frustum, to
/// [0, 1].
glm::vec4 orthographicDepthPlane(const Scene& scene, const glm::mat4& viewProj) {
    const glm::dvec4 window = 0.5 * row(viewProj, 2) + glm::dvec4(0, 0, 0, 0.5);
    double zmin = 1.0, zmax = 0.0;
    for (const glm::dvec3& p : cornersInFrustum(scene, viewProj)) {
        const double z = glm::dot(glm::dvec3(window), p) + window.w;
        zmin = std::min(zmin, z);
        zmax = std::max(zmax, z);
    }
    zmin = std::clamp(zmin, 0.0, 1.0);
    zmax = std::clamp(zmax, 0.0, 1.0);
    if (!(zmax - zmin > 1e-6)) zmin = 0.0, zmax = 1.0; // nothing in the frustum: the fit's own range
    return glm::vec4((window - glm::dvec4(0, 0, 0, zmin)) / (zmax - zmin));
}

/// Spot lights: 1 / the farthest distance from the light of what the scene has inside its frustum
/// (distance is convex, so its maximum is at a clipped corner), at least 1e-6.
float inverseFarthestDistance(const Scene& scene, const glm::mat4& viewProj, const glm::vec3& light) {
    double far = 1e-6;
    for (const glm::dvec3& p : cornersInFrustum(scene, viewProj))
        far = std::max(far, glm::length(p - glm::dvec3(light)));
    return float(1.0 / far);
}
} // namespace

float MomentMapFits::linearDepth(const glm::vec4& plane, const glm::vec4& point, const glm::vec3& p) {
    if (point.w > 0.0f) return glm::length(p - glm::vec3(point)) * point.w;
    return glm::dot(glm::vec3(plane), p) + plane.w;
}

size_t MomentMapFits::shadowedLights() const {
    return size_t(std::count(mCastsShadows.begin(), mCastsShadows.end(), uint8_t(1)));
}

void MomentMapFits::setScene(const Scene& scene, const PropertySet& p) {
    mFit = LightFitProperties::lightFit(p);
    fitLights(scene);
}

void MomentMapFits::fitLights(const Scene& scene) {
    mFitted.clear();
    mCastsShadows.clear();
    mDirectional.clear();
    mLightPosition.clear();
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    for (size_t i = 0; i < count; ++i) {
        const Light& l = scene.lights[i];
        mCastsShadows.push_back(l.castsShadows);
        if (!l.castsShadows) { // lit, never looked up: no fit (a point light has none)
            mFitted.emplace_back(1.0f);
            mDirectional.push_back(true);
            mLightPosition.push_back(l.position);
            continue;
        }
        PointLightRefusal::refuse(l, i, mOwner);
        mFitted.push_back(fitLightViewProjection(scene, l, mFit));
        mDirectional.push_back(l.type == LightType::Directional);
        mLightPosition.push_back(l.position);
    }
    mCulling.setScene(scene);
    mReceiverBounds = Aabb{};
    for (const Instance& inst : scene.instances)
        if (inst.receivesShadow && inst.mesh < scene.meshes.size())
            mReceiverBounds.extend(transformBounds(scene.meshBoundsOf(inst.mesh), inst.model));
    mViewProj.clear(); // fit() makes them
    mMarginTexels = -1;
    mFitResolution = 0;
}

void MomentMapFits::sceneChanged(const Scene& scene) {
    const int resolution = mFitResolution, margin = mMarginTexels;
    fitLights(scene);
    if (resolution > 0) fit(scene, resolution, margin);
}

void MomentMapFits::fit(const Scene& scene, int resolution, int marginTexels) {
    if (4 * marginTexels > resolution)
        throw Error(mOwner + ": the blur needs a border of " + std::to_string(marginTexels) +
                        " texels (blur / 2 + 1), more than a quarter of the map's " +
                        std::to_string(resolution) + ": raise resolution or lower blur",
                    ExitCode::BadInput);
    if (resolution == mFitResolution && marginTexels == mMarginTexels && mViewProj.size() == mFitted.size())
        return;
    mViewProj.clear();
    mShadowMatrix.clear();
    mDepthPlane.clear();
    mDepthPoint.clear();
    const glm::mat4& bias = FlatLightFits::textureBias();
    // The fitted frustum, widened so that it fills only the inner resolution - 2 margin texels.
    const float shrink = float(resolution - 2 * marginTexels) / float(resolution);
    const glm::mat4 pad = glm::scale(glm::mat4(1.0f), glm::vec3(shrink, shrink, 1.0f));
    for (size_t i = 0; i < mFitted.size(); ++i) {
        const glm::mat4 viewProj = pad * mFitted[i];
        mViewProj.push_back(viewProj);
        mShadowMatrix.push_back(bias * viewProj);
        if (mDirectional[i]) {
            mDepthPlane.push_back(orthographicDepthPlane(scene, viewProj));
            mDepthPoint.emplace_back(0.0f);
        } else {
            mDepthPlane.emplace_back(0.0f);
            mDepthPoint.emplace_back(mLightPosition[i],
                                     inverseFarthestDistance(scene, viewProj, mLightPosition[i]));
        }
    }
    mFitResolution = resolution;
    mMarginTexels = marginTexels;
    if (scene.motion && mCoverageCounted) return;
    mCoverage = {};
    for (size_t i = 0; i < mViewProj.size(); ++i)
        if (castsShadow(i)) mCoverage += MapCoverage::count(scene, mViewProj[i], resolution);
    mCoverageCounted = true;
}

std::optional<MapPoint> MomentMapFits::texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const {
    if (light >= mShadowMatrix.size() || !castsShadow(light) || mFitResolution <= 0) return std::nullopt;
    const glm::mat4& shadow = mShadowMatrix[light];
    if (!looksUp(shadow, at.position, double(marginUv(mFitResolution)), false)) return std::nullopt;
    return MapPoint{0, mFitResolution, projectedTexel(shadow, mFitResolution, q)};
}

MomentMapFits::LightDraws MomentMapFits::cull(size_t light, const Scene& scene,
                                              const glm::mat4& cameraViewProj, std::vector<uint8_t>& keep,
                                              std::vector<uint8_t>& keepBackground, size_t& culled) const {
    LightDraws out;
    const glm::mat4& viewProj = mViewProj[light];
    size_t kept = mCulling.cull(viewProj, DrawSet::Casters, CullPlanes::All, keep);
    if (mViewCull) {
        // The blur and the bilinear lookup reach mMarginTexels (+2 for rounding) around a texel.
        const float margin = float(mMarginTexels + 2) *
                             FlatLightFits::texelWorldSize(viewProj, mFitResolution) *
                             FlatLightFits::farthestW(viewProj, mReceiverBounds);
        kept =
            mCulling.keepReachingView(scene.lights[light], {cameraViewProj, mReceiverBounds}, margin, keep);
    }
    culled += mCulling.count(DrawSet::Casters) - kept;
    out.casters = kept;
    out.background = kept > 0 && mReceiverBackground &&
                     mCulling.cull(viewProj, DrawSet::NonCasters, CullPlanes::All, keepBackground) > 0;
    return out;
}

Counters MomentMapFits::counters(const SubmitStats& s, int resolution, double blurTexels,
                                 size_t culled) const {
    const double res = resolution;
    return {{"draw_calls", double(s.drawCalls)},
            {"triangles", double(s.triangles)},
            {"shadow_map_texels", res * res * double(shadowedLights())},
            {"lights_unshadowed", double(lights() - shadowedLights())},
            {"blur_texels", blurTexels},
            {"casters_culled", double(culled)},
            {"map_covered_pct", mCoverage.percent()}};
}

} // namespace sb
