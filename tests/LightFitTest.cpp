// The light cameras of scenes/LightFit (shadowmap's depth maps, projective's directional projector)
// against the clip coordinates worked out by hand from the fit's definition: x and y framing the
// casters with 1% + 1e-3 of padding, depth covering every instance with 1e-3 of the scene's radius,
// and the spot's frustum between the scene's nearest and farthest points along the light's axis. Then
// each fit (casters, sphere, scene, and the margin) through the share of the map a sphere of radius 1
// covers (scenes/MapCoverage), against its silhouette's area over the fitted square's, by hand.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "scenes/LightFit.h"
#include "scenes/MapCoverage.h"
#include "scenes/MeshGenerators.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Clip coordinates of values ~1 from products of floats of magnitude ~100: a few ulps of the inputs.
constexpr float kTol = 1e-4f;

std::vector<glm::vec3> corners(const glm::vec3& lo, const glm::vec3& hi) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    return out;
}

/// Adds a box [lo, hi] as a mesh of its 8 corners (bounds are all the fit reads) and one instance.
void addBox(Scene& scene, const glm::vec3& lo, const glm::vec3& hi, bool casts) {
    Mesh mesh;
    mesh.name = "box" + std::to_string(scene.meshes.size());
    mesh.positions = corners(lo, hi);
    mesh.normals.assign(8, glm::vec3(0, 1, 0));
    Instance instance;
    instance.mesh = uint32_t(scene.meshes.size());
    instance.castsShadow = casts;
    scene.meshes.push_back(mesh);
    scene.instances.push_back(instance);
    scene.updateTransforms();
}

glm::vec3 clip(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    EXPECT_GT(c.w, 0.0f);
    return glm::vec3(c) / c.w;
}

Light directional(const glm::vec3& dir) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::normalize(dir);
    return light;
}

} // namespace

TEST(LightFitTest, DirectionalFramesTheCastersWithTheirPaddingAndEveryReceiverInDepth) {
    Scene scene;
    addBox(scene, {-30, 0, -20}, {40, 12, 25}, true);       // the caster
    addBox(scene, {-100, -5, -100}, {100, -5, 100}, false); // a ground below it, wider than the map
    const glm::mat4 m = fitLightViewProjection(scene, directional({0, -1, 0}));
    // Straight down the light camera's up is +z (anyPerpendicularUp), so x_view = -(x - 5) and
    // y_view = z - 2.5 around the casters' centre (5, 6, 2.5). Half extents 35 and 22.5, padded by
    // 1% of the full extent + 1e-3 each side: the casters' extreme corners land at 35 / 35.701 and
    // 22.5 / 22.951 of the map's half width.
    const float ex = 35.0f / (35.0f + 0.701f), ey = 22.5f / (22.5f + 0.451f);
    EXPECT_NEAR(clip(m, {-30, 12, -20}).x, ex, kTol);
    EXPECT_NEAR(clip(m, {40, 12, -20}).x, -ex, kTol);
    EXPECT_NEAR(clip(m, {40, 12, 25}).y, ey, kTol);
    EXPECT_NEAR(clip(m, {40, 0, -20}).y, -ey, kTol);
    // Depth: the scene spans y in [-5, 12]; its radius is half the diagonal of (200, 17, 200). The
    // range is padded by 1e-3 radius at both ends, and depth grows downwards, along the light.
    const float r = 0.5f * std::sqrt(200.0f * 200.0f + 17.0f * 17.0f + 200.0f * 200.0f);
    const float span = 17.0f + 2e-3f * r;
    EXPECT_NEAR(clip(m, {0, 12, 0}).z, -1.0f + 2.0f * 1e-3f * r / span, kTol);
    EXPECT_NEAR(clip(m, {0, -5, 0}).z, 1.0f - 2.0f * 1e-3f * r / span, kTol);
    // The ground reaches beyond the map in x and y (only casters need to be in it), never in depth.
    for (const glm::vec3& p : corners({-100, -5, -100}, {100, -5, 100})) {
        const glm::vec3 c = clip(m, p);
        EXPECT_GT(std::abs(c.x), 1.0f);
        EXPECT_LT(std::abs(c.z), 1.0f);
    }
    // Oblique lights: no closed form worth writing out, but the same two properties.
    for (glm::vec3 dir : {glm::vec3(-0.4f, -1, -0.3f), glm::vec3(1, -0.2f, 0), glm::vec3(0.3f, -1, 0.2f)}) {
        SCOPED_TRACE(dir.x);
        const Light light = directional(dir);
        const glm::mat4 oblique = fitLightViewProjection(scene, light);
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& p : corners({-30, 0, -20}, {40, 12, 25})) {
            const glm::vec3 c = clip(oblique, p);
            lo = glm::min(lo, glm::vec2(c));
            hi = glm::max(hi, glm::vec2(c));
        }
        // Inside, and the extreme corners within the padding of the edges: 1% of the extent + 1e-3
        // each side leaves at least 1 / 1.02 of the half width (extents here are above 10, so the
        // 1e-3 adds under 2e-4).
        for (int a = 0; a < 2; ++a) {
            EXPECT_GE(lo[a], -1.0f) << "axis " << a;
            EXPECT_LE(hi[a], 1.0f) << "axis " << a;
            EXPECT_LT(lo[a], -1.0f / 1.0202f) << "axis " << a;
            EXPECT_GT(hi[a], 1.0f / 1.0202f) << "axis " << a;
        }
        for (const glm::vec3& p : corners({-100, -5, -100}, {100, -5, 100}))
            EXPECT_LT(std::abs(clip(oblique, p).z), 1.0f) << "receiver corners stay inside the depth range";
        const glm::vec3 centre(5, 6, 2.5f);
        EXPECT_GT(clip(oblique, centre + light.direction).z, clip(oblique, centre).z)
            << "depth grows along the light";
    }
}

TEST(LightFitTest, SpotIsTheConeBetweenTheScenesNearestAndFarthestPoints) {
    Scene scene;
    addBox(scene, {-3, 0, -3}, {3, 5, 3}, true);
    Light light;
    light.type = LightType::Spot;
    light.position = {0, 20, 0};
    light.direction = {0, -1, 0};
    light.spotOuterDeg = 30.0f;
    const glm::mat4 m = fitLightViewProjection(scene, light);
    // fov = 2 x 30 degrees: at depth 10 on the axis, 10 tan(30) off it is the frustum's edge.
    const glm::vec3 onEdge = clip(m, {0, 10, 10.0f * std::tan(glm::radians(30.0f))});
    EXPECT_NEAR(std::max(std::abs(onEdge.x), std::abs(onEdge.y)), 1.0f, kTol);
    // Near at the box's top (depth 15), far at its bottom (depth 20), exactly.
    EXPECT_NEAR(clip(m, {0, 5, 0}).z, -1.0f, kTol);
    EXPECT_NEAR(clip(m, {0, 0, 0}).z, 1.0f, kTol);
    for (const glm::vec3& p : corners({-3, 0, -3}, {3, 5, 3})) {
        const glm::vec3 c = clip(m, p);
        for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(c[a]), 1.0f + kTol) << "axis " << a;
    }
}

TEST(LightFitTest, SpotInsideTheSceneKeepsItsNearPlanePositive) {
    Scene scene;
    addBox(scene, {-5, -5, -5}, {5, 5, 5}, true);
    Light light;
    light.type = LightType::Spot;
    light.position = {0, 1, 0};
    light.direction = {0, -1, 0};
    const glm::mat4 m = fitLightViewProjection(scene, light);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
    // The box's top is 4 behind the light, its bottom 6 in front: far = 6 and the near plane, which
    // would be at -4, is clamped to 1e-3 x far = 0.006 in front of the light.
    EXPECT_NEAR(clip(m, {0, 1.0f - 0.006f, 0}).z, -1.0f, kTol);
    EXPECT_NEAR(clip(m, {0, -5, 0}).z, 1.0f, kTol);
    EXPECT_GT((m * glm::vec4(0, 0.5f, 0, 1)).w, 0.0f) << "a point just in front of the light is in front";
}

namespace {

/// The sphere of scenes/data/sphere_plane.json (radius 1, tessellation 32: 32 rings of 64 segments,
/// centred at (0, 3, 0)) over its 40 x 40 ground at y = 0, lit straight down.
Scene sphereOverGround() {
    Scene scene = SceneLoader::load("sphere_plane");
    scene.lights[0].direction = {0, -1, 0};
    return scene;
}

/// Straight down, the sphere's silhouette is its equator: a regular 64-gon inscribed in the unit
/// circle, area (64 / 2) sin(2 pi / 64).
const double kEquatorArea = 32.0 * std::sin(2.0 * kPi / 64.0);

/// The share of a `resolution`^2 map that a convex region of `area` (world units^2) covers when the
/// map's square side is `side` world units, and the counting's tolerance: a texel whose centre's side
/// differs from its share of the region meets the region's boundary, and a convex curve meets at most
/// its bounding box's perimeter in texels + 4 of them (`diameter` bounds the box's side).
struct Expected {
    double share, tolerance;
};
Expected expectedShare(double area, double diameter, double side, int resolution) {
    const double texelsPerUnit = resolution / side;
    return {area / (side * side), (4.0 * diameter * texelsPerUnit + 4.0) / (double(resolution) * resolution)};
}

double coveredShare(const Scene& scene, const LightFit& fit, int resolution) {
    const MapCoverage c =
        MapCoverage::count(scene, fitLightViewProjection(scene, scene.lights[0], fit), resolution);
    EXPECT_EQ(c.texels, uint64_t(resolution) * uint64_t(resolution));
    return double(c.covered) / double(c.texels);
}

} // namespace

TEST(LightFitTest, CoverageCountsTheTexelCentresInsideAHandPlacedTriangle) {
    // Clip space is world space (identity): window x = (x + 1) / 2 x 64. The right triangle with legs of
    // n = 10 texels on the map's corner covers the centres (i + 0.5, j + 0.5) with i + j <= n - 1:
    // n (n + 1) / 2 = 55 of them; drawn twice (both windings) they still count once.
    const int res = 64, n = 10;
    const float t = 2.0f * float(n) / float(res);
    Scene scene;
    Mesh mesh;
    mesh.positions = {{-1, -1, 0}, {-1 + t, -1, 0}, {-1, -1 + t, 0}};
    mesh.normals.assign(3, glm::vec3(0, 0, 1));
    mesh.indices = {0, 1, 2, 0, 2, 1};
    scene.meshes.push_back(mesh);
    scene.instances.emplace_back();
    scene.updateTransforms();
    EXPECT_EQ(MapCoverage::count(scene, glm::mat4(1.0f), res).covered, uint64_t(n * (n + 1) / 2));
    // A non-caster covers nothing, and a triangle behind the near plane (z < -w) is cut away.
    scene.instances[0].castsShadow = false;
    EXPECT_EQ(MapCoverage::count(scene, glm::mat4(1.0f), res).covered, 0u);
    scene.instances[0].castsShadow = true;
    for (glm::vec3& p : scene.meshes[0].positions) p.z = -2.0f;
    EXPECT_EQ(MapCoverage::count(scene, glm::mat4(1.0f), res).covered, 0u);
}

TEST(LightFitTest, CoverageOfATriangleBeyondEveryEdgeIsTheWholeMapAndStaysInside) {
    // A triangle reaching past all four sides of the map covers every texel centre: exactly res^2. Its
    // rows start left of the map; the count must clip them at texel 0 (under the sanitizers a write
    // before the first row's start is a heap-buffer-overflow).
    const int res = 16;
    Scene scene;
    Mesh mesh;
    mesh.positions = {{-3, -3, 0}, {5, -3, 0}, {-3, 5, 0}};
    mesh.normals.assign(3, glm::vec3(0, 0, 1));
    mesh.indices = {0, 1, 2};
    scene.meshes.push_back(mesh);
    scene.instances.emplace_back();
    scene.updateTransforms();
    const MapCoverage c = MapCoverage::count(scene, glm::mat4(1.0f), res);
    EXPECT_EQ(c.covered, uint64_t(res * res));
    EXPECT_EQ(c.texels, uint64_t(res * res));
}

TEST(LightFitTest, EachFitFramesTheSphereAsWorkedOutByHand) {
    const Scene scene = sphereOverGround();
    const int res = 4096;
    struct Case {
        const char* name;
        LightFit fit;
        double side; ///< the map's side in world units, from the fit's definition
    };
    // Casters: the sphere's box is 2 x 2 seen from above, + 1% + 1e-3 each side. Sphere: a square of
    // half-width the box's half-diagonal sqrt(3), the same margin. Scene: the ground's 40 x 40.
    // The margin: 0.5 each side doubles the casters' side, 0 leaves only the 1e-3.
    const double sphere = 2.0 * std::sqrt(3.0);
    const Case cases[] = {
        {"casters", {LightFitBounds::Casters, 0.01f}, 2.0 * 1.02 + 2e-3},
        {"sphere", {LightFitBounds::Sphere, 0.01f}, sphere * 1.02 + 2e-3},
        {"scene", {LightFitBounds::Scene, 0.01f}, 40.0 * 1.02 + 2e-3},
        {"casters, margin 0.5", {LightFitBounds::Casters, 0.5f}, 2.0 * 2.0 + 2e-3},
        {"casters, margin 0", {LightFitBounds::Casters, 0.0f}, 2.0 + 2e-3},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const Expected e = expectedShare(kEquatorArea, 2.0, c.side, res);
        EXPECT_NEAR(coveredShare(scene, c.fit, res), e.share, e.tolerance);
    }
    // The default is the casters' box with today's margin: the fit before it was a choice.
    EXPECT_EQ(fitLightViewProjection(scene, scene.lights[0]),
              fitLightViewProjection(scene, scene.lights[0], {LightFitBounds::Casters, 0.01f}));
    EXPECT_EQ(LightFit{}.bounds, LightFitBounds::Casters);
    EXPECT_EQ(std::string(lightFitBoundsNames().choices()), "casters, sphere or scene");
}

TEST(LightFitTest, TheSphereFitFramesTheSameSquareUnderAnObliqueLight) {
    // sphere_plane's own oblique light (0.3, -1, 0.2): the casters' box seen obliquely frames a larger
    // map than from above, the sphere fit the same square from every direction. The silhouette is then
    // no longer the equator: it lies between the discs of the polytope's inradius and of radius 1. The
    // faces' vertices lie on the unit sphere within an angle of (pi / 64) sqrt(2) of each face's centre
    // (a cell of 32 rings x 64 segments is pi / 32 on a side), so the inradius is at least
    // cos(sqrt(2) pi / 64).
    const Scene scene = SceneLoader::load("sphere_plane");
    const int res = 4096;
    const double side = 2.0 * std::sqrt(3.0) * 1.02 + 2e-3;
    const double inradius = std::cos(std::sqrt(2.0) * kPi / 64.0);
    const Expected lo = expectedShare(kPi * inradius * inradius, 2.0, side, res);
    const Expected hi = expectedShare(kPi, 2.0, side, res);
    const double share = coveredShare(scene, {LightFitBounds::Sphere, 0.01f}, res);
    EXPECT_GE(share, lo.share - lo.tolerance);
    EXPECT_LE(share, hi.share + hi.tolerance);
    // The casters' fit frames the oblique box's outline, wider than its 2 x 2 from above: a smaller
    // share than straight down, and still more than the sphere's square gives.
    const double casters = coveredShare(scene, {}, res);
    EXPECT_LT(casters, expectedShare(kEquatorArea, 2.0, 2.0 * 1.02 + 2e-3, res).share);
    EXPECT_GT(casters, share);
}
