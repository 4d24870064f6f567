// OccluderTextures on a real context: baked silhouettes, dilation and cross-sections judged texel by
// texel against point-in-polygon / point-in-polyhedron answers computed here on the CPU, and the image
// round trip (orientation, luma, errors).
//
// Tolerance of the geometric checks: a rasteriser covers a texel when its centre is inside the
// projected triangle, with vertices snapped to the subpixel grid (llvmpipe 1/256 texel; GL requires at
// least 4 bits, 1/16 texel). So every texel whose centre is farther than kMargin = 1/8 texel from the
// expected boundary must match exactly; only centres within kMargin of the boundary are not judged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "PngDecoder.h"
#include "TestSupport.h"
#include "core/Error.h"
#include "core/PngFile.h"
#include "gl/Context.h"
#include "gl/ProgramCache.h"
#include "gl/TextureFramebuffer.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/MeshGenerators.h"
#include "techniques/occluder/OccluderTextures.h"

namespace sb {
namespace {

constexpr float kMarginTexels = 0.125f;
constexpr uint8_t kBlack = 0, kWhite = 255;

class OccluderTexturesGLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        sContext = createContext(ContextOptions{});
        sPrograms = std::make_unique<ProgramCache>(std::string(SB_SOURCE_DIR) + "/shaders");
    }
    static void TearDownTestSuite() {
        sPrograms.reset();
        sContext.reset();
    }
    static std::unique_ptr<Context> sContext;
    static std::unique_ptr<ProgramCache> sPrograms;
};
std::unique_ptr<Context> OccluderTexturesGLTest::sContext;
std::unique_ptr<ProgramCache> OccluderTexturesGLTest::sPrograms;

struct Baked {
    std::vector<uint8_t> texels;
    int width = 0, height = 0;
    uint8_t at(int i, int j) const { return texels[size_t(j) * size_t(width) + size_t(i)]; }
    size_t black() const { return size_t(std::count(texels.begin(), texels.end(), kBlack)); }
};

Baked bake(ProgramCache& programs, const Mesh& mesh, const ShadowPlane& plane,
           const OccluderBakeOptions& options) {
    const GLuint texture = OccluderTextures::bake(programs, mesh, plane, options);
    Baked b;
    b.texels = OccluderTextures::readBack(texture, b.width, b.height);
    glDeleteTextures(1, &texture);
    return b;
}

ShadowPlane makePlane(glm::vec3 origin, glm::vec3 right, glm::vec3 up, float size) {
    ShadowPlane p;
    p.name = "test";
    p.origin = origin;
    p.right = right;
    p.up = up;
    p.normal = glm::cross(right, up);
    p.width = p.height = size;
    return p;
}

/// World position of texel (i, j)'s centre on the plane.
glm::vec3 texelCentre(const ShadowPlane& p, int n, int i, int j) {
    return p.origin + (float(i) + 0.5f) / float(n) * p.width * p.right +
           (float(j) + 0.5f) / float(n) * p.height * p.up;
}

/// Signed distance of q to a convex polygon (either winding): max over edges of the outward distance;
/// negative inside. Exact inside; outside a lower bound of the true distance, which is what the
/// "must be white" side needs.
float polygonDistance(const std::vector<glm::vec2>& poly, glm::vec2 q) {
    float area = 0.0f;
    for (size_t k = 0; k < poly.size(); ++k) {
        const glm::vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
        area += a.x * b.y - b.x * a.y;
    }
    float d = -1e30f;
    for (size_t k = 0; k < poly.size(); ++k) {
        const glm::vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
        const glm::vec2 e = glm::normalize(b - a);
        const glm::vec2 outward = area > 0.0f ? glm::vec2(e.y, -e.x) : glm::vec2(-e.y, e.x);
        d = std::max(d, glm::dot(outward, q - a));
    }
    return d;
}

/// The same for a closed convex mesh wound counter-clockwise outward: max over face planes.
float polyhedronDistance(const Mesh& mesh, glm::vec3 q) {
    float d = -1e30f;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                        c = mesh.positions[mesh.indices[t + 2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        if (len < 1e-12f) continue;
        d = std::max(d, glm::dot(n / len, q - a));
    }
    return d;
}

/// Compares every texel with `distance` (world units, negative = occluder) at its centre: black where
/// distance < -margin, white where > margin. Returns the number of wrong texels and, in `judged`,
/// how many were judged.
struct Mismatch {
    size_t wrong = 0, judged = 0, expectedBlack = 0;
};
Mismatch compare(const Baked& b, const ShadowPlane& plane, const std::function<float(glm::vec3)>& distance) {
    const float margin = kMarginTexels * plane.width / float(b.width);
    Mismatch m;
    for (int j = 0; j < b.height; ++j)
        for (int i = 0; i < b.width; ++i) {
            const float d = distance(texelCentre(plane, b.width, i, j));
            if (std::abs(d) <= margin) continue;
            ++m.judged;
            m.expectedBlack += d < 0.0f;
            m.wrong += b.at(i, j) != (d < 0.0f ? kBlack : kWhite);
        }
    return m;
}

/// Two triangles spanning [lo, hi]^2 in the z = 0 plane.
Mesh squareQuad(float lo, float hi) {
    Mesh m;
    m.name = "quad";
    m.positions = {{lo, lo, 0}, {hi, lo, 0}, {hi, hi, 0}, {lo, hi, 0}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

ShadowPlane unitZPlane() {
    return makePlane(glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 1.0f);
}

/// Texels of an n x n bake over [0, 1]^2 whose index lies in [first, last] on both axes are black.
size_t squareMismatches(const Baked& b, int first, int last) {
    size_t wrong = 0;
    for (int j = 0; j < b.height; ++j)
        for (int i = 0; i < b.width; ++i) {
            const bool inside = i >= first && i <= last && j >= first && j <= last;
            wrong += b.at(i, j) != (inside ? kBlack : kWhite);
        }
    return wrong;
}

TEST_F(OccluderTexturesGLTest, SquareQuadSilhouetteIsExact) {
    OccluderBakeOptions options;
    options.resolution = 64;
    options.dilate = 0;
    options.crossSection = false;
    const GLuint texture =
        OccluderTextures::bake(*sPrograms, squareQuad(0.25f, 0.75f), unitZPlane(), options);
    GLint format = 0, minFilter = 0, magFilter = 0, wrapS = 0, wrapT = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureParameteriv(texture, GL_TEXTURE_MIN_FILTER, &minFilter);
    glGetTextureParameteriv(texture, GL_TEXTURE_MAG_FILTER, &magFilter);
    glGetTextureParameteriv(texture, GL_TEXTURE_WRAP_S, &wrapS);
    glGetTextureParameteriv(texture, GL_TEXTURE_WRAP_T, &wrapT);
    EXPECT_EQ(format, GL_R8);
    EXPECT_EQ(minFilter, GL_LINEAR);
    EXPECT_EQ(magFilter, GL_LINEAR);
    EXPECT_EQ(wrapS, GL_CLAMP_TO_EDGE);
    EXPECT_EQ(wrapT, GL_CLAMP_TO_EDGE);
    Baked b;
    b.texels = OccluderTextures::readBack(texture, b.width, b.height);
    glDeleteTextures(1, &texture);
    ASSERT_EQ(b.width, 64);
    ASSERT_EQ(b.height, 64);
    // The square's edges 0.25 and 0.75 fall on texel boundaries 16 and 48, half a texel from every
    // centre (far beyond any subpixel snapping), so no texel is ambiguous: texels 16..47 exactly,
    // 32^2 = 1024 black, and every texel 0 or 255.
    EXPECT_EQ(squareMismatches(b, 16, 47), 0u);
    EXPECT_EQ(b.black(), 1024u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(OccluderTexturesGLTest, DilationGrowsTheSquareByExactlyKTexels) {
    OccluderBakeOptions options;
    options.resolution = 64;
    options.dilate = 2;
    options.crossSection = false;
    const Baked b = bake(*sPrograms, squareQuad(0.25f, 0.75f), unitZPlane(), options);
    // A (2k+1)^2 min filter grows an axis-aligned square by k on every side: texels 14..49, (32+4)^2.
    EXPECT_EQ(squareMismatches(b, 14, 49), 0u);
    EXPECT_EQ(b.black(), 36u * 36u);
    // At the border the filter clamps (no wrap-around): a square touching the left edge grows only right.
    const Baked edge = bake(*sPrograms, squareQuad(0.0f, 0.25f), unitZPlane(), options);
    EXPECT_EQ(squareMismatches(edge, 0, 17), 0u);
}

/// The unit sphere (tess 32) split into "cap" (the triangles whose three vertices have y >= 0.5: whole
/// bands from the +Y pole to ring 10, so the cap's projection along Y is exactly that ring's regular
/// 64-gon) and "rest".
Mesh sphereWithCap(float& capRadius) {
    Mesh sphere = MeshGenerators::sphere(32);
    std::vector<uint32_t> cap, rest;
    capRadius = 0.0f;
    for (size_t t = 0; t < sphere.indices.size(); t += 3) {
        bool inCap = true;
        for (size_t k = 0; k < 3; ++k) inCap = inCap && sphere.positions[sphere.indices[t + k]].y >= 0.5f;
        for (size_t k = 0; k < 3; ++k) {
            const glm::vec3 p = sphere.positions[sphere.indices[t + k]];
            (inCap ? cap : rest).push_back(sphere.indices[t + k]);
            if (inCap) capRadius = std::max(capRadius, std::hypot(p.x, p.z));
        }
    }
    sphere.indices = cap;
    sphere.indices.insert(sphere.indices.end(), rest.begin(), rest.end());
    sphere.parts = {{"cap", 0, uint32_t(cap.size())}, {"rest", uint32_t(cap.size()), uint32_t(rest.size())}};
    return sphere;
}

/// Regular n-gon of circumradius r with a vertex at angle 0 (the sphere's rings in the xz plane).
std::vector<glm::vec2> regularPolygon(int n, float r) {
    std::vector<glm::vec2> poly;
    for (int k = 0; k < n; ++k) {
        const float a = glm::two_pi<float>() * float(k) / float(n);
        poly.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return poly;
}

float equivalentRadius(const Baked& b, const ShadowPlane& plane) {
    const float texelArea = plane.width * plane.height / float(b.width * b.height);
    return std::sqrt(float(b.black()) * texelArea / glm::pi<float>());
}

TEST_F(OccluderTexturesGLTest, SphereCapSilhouetteAndCrossSection) {
    float capRadius = 0.0f;
    const Mesh sphere = sphereWithCap(capRadius);
    Mesh closed = MeshGenerators::sphere(32); // the same solid, for the half-space test
    ASSERT_NEAR(capRadius, std::sin(10.0f * glm::pi<float>() / 32.0f), 1e-5f); // ring 10
    // The plane y = 0 (right x, up -z: right x up = +y), 3 x 3 around the centre.
    ShadowPlane plane = makePlane({-1.5f, 0.0f, 1.5f}, {1, 0, 0}, {0, 0, -1}, 3.0f);
    plane.parts = {"cap"};
    OccluderBakeOptions options;
    options.resolution = 128;
    options.dilate = 0;
    const std::vector<glm::vec2> capPolygon = regularPolygon(64, capRadius);
    auto capDistance = [&](glm::vec3 q) { return polygonDistance(capPolygon, {q.x, q.z}); };

    // Silhouette only: the cap's projection, the 64-gon of radius sin(56.25 deg) = 0.831 (a cap cut
    // at exactly y = 0.5 would give 0.866; the tessellation's cap ends at ring 10).
    options.crossSection = false;
    const Baked silhouette = bake(*sPrograms, sphere, plane, options);
    const Mismatch s = compare(silhouette, plane, capDistance);
    EXPECT_EQ(s.wrong, 0u) << "of " << s.judged << " judged texels";
    EXPECT_GT(s.expectedBlack, 1000u);
    // The same plane facing the other way (normal -y: the cap behind it) bakes the same silhouette,
    // mirrored in v: the silhouette is never clipped to the normal's side, only the cross-section is.
    ShadowPlane flipped = makePlane({-1.5f, 0.0f, -1.5f}, {1, 0, 0}, {0, 0, 1}, 3.0f);
    flipped.parts = {"cap"};
    ASSERT_NEAR(flipped.normal.y, -1.0f, 1e-6f);
    const Mismatch f = compare(bake(*sPrograms, sphere, flipped, options), flipped, capDistance);
    EXPECT_EQ(f.wrong, 0u) << "of " << f.judged << " judged texels, plane facing away from the cap";

    // With the cross-section: the plane y = 0 lies inside the whole sphere's solid over its equatorial
    // 64-gon (radius 1), a superset of the cap's projection.
    options.crossSection = true;
    const Baked both = bake(*sPrograms, sphere, plane, options);
    const Mismatch c = compare(
        both, plane, [&](glm::vec3 q) { return std::min(capDistance(q), polyhedronDistance(closed, q)); });
    EXPECT_EQ(c.wrong, 0u) << "of " << c.judged << " judged texels";
    // The black areas as radii of equal-area discs, against the polygons' (area of a regular n-gon of
    // circumradius r: n/2 r^2 sin(2 pi/n)); tolerance: the boundary's texels, perimeter x texel / area
    // of relative area, i.e. half that in radius (2 pi r texel / (2 pi r^2) r = texel).
    const float texel = plane.width / float(options.resolution);
    auto polygonRadius = [](float r) {
        return std::sqrt(32.0f * r * r * std::sin(glm::two_pi<float>() / 64.0f) / glm::pi<float>());
    };
    const float rSilhouette = equivalentRadius(silhouette, plane), rBoth = equivalentRadius(both, plane);
    std::cout << "[ measured ] cap silhouette radius " << rSilhouette << " (64-gon "
              << polygonRadius(capRadius) << "), with cross-section " << rBoth << " (64-gon "
              << polygonRadius(1.0f) << "), texel " << texel << "\n";
    std::cout << "[ measured ] sphere texels judged: " << s.judged << ", " << f.judged << ", " << c.judged
              << " of " << 128 * 128 << "\n";
    EXPECT_NEAR(rSilhouette, polygonRadius(capRadius), texel);
    EXPECT_NEAR(rBoth, polygonRadius(1.0f), texel);
}

TEST_F(OccluderTexturesGLTest, TiltedPlaneCrossSectionAlone) {
    // A plane at distance d = 0.5 from the sphere's centre, tilted (normal (1, 2, 2) / 3): the
    // cross-section alone (no silhouette) is the polygonal disc of the convex mesh, between the discs
    // of radius sqrt(r_in^2 - d^2) and sqrt(1 - d^2) = 0.866 (r_in: the faces' least distance from
    // the centre). Judged texel by texel with the mesh's half-spaces.
    const Mesh sphere = MeshGenerators::sphere(32);
    const glm::vec3 n = glm::vec3(1, 2, 2) / 3.0f;
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 0, 1), n));
    const glm::vec3 up = glm::cross(n, right);
    const float d = 0.5f, size = 2.4f;
    ShadowPlane plane = makePlane(d * n - 0.5f * size * (right + up), right, up, size);
    ASSERT_NEAR(glm::dot(plane.normal, n), 1.0f, 1e-5f);
    OccluderBakeOptions options;
    options.resolution = 128;
    options.dilate = 0;
    options.silhouette = false;
    const Baked b = bake(*sPrograms, sphere, plane, options);
    const Mismatch m = compare(b, plane, [&](glm::vec3 q) { return polyhedronDistance(sphere, q); });
    EXPECT_EQ(m.wrong, 0u) << "of " << m.judged << " judged texels";
    EXPECT_GT(m.expectedBlack, 5000u);
    const float rIn = -polyhedronDistance(sphere, glm::vec3(0.0f)); // centre to the nearest face
    const float texel = size / float(options.resolution), r = equivalentRadius(b, plane);
    std::cout << "[ measured ] tilted cross-section radius " << r << " in [" << std::sqrt(rIn * rIn - d * d)
              << ", " << std::sqrt(1.0f - d * d) << "], texel " << texel << "\n";
    EXPECT_GE(r, std::sqrt(rIn * rIn - d * d) - texel);
    EXPECT_LE(r, std::sqrt(1.0f - d * d) + texel);
    // (Without the clip to the normal's side every plane point would see the whole sphere, +1 - 1 = 0,
    // and nothing would be black.) The plane moved outside the sphere (d = 1.2): nothing is black.
    plane.origin += 0.7f * n;
    EXPECT_EQ(bake(*sPrograms, sphere, plane, options).black(), 0u);
}

TEST_F(OccluderTexturesGLTest, OverlappingClosedPartsUseTheNonZeroRule) {
    // Two overlapping closed boxes in one mesh (as the aircraft's fins reach into the fuselage): inside
    // both, a parity count is even and would leave a white hole; the winding number is 2 and marks it.
    // A: x [-0.75, 0.25], y [-0.5, 0.5]; B: x [-0.25, 0.75], y [0, 0.5]; both z [-0.5, 0.5]. The plane
    // z = 0 over [-1, 1]^2 at 64 texels: every edge on a texel boundary, so the answer is exact.
    Mesh a = MeshGenerators::box({0.5f, 0.5f, 0.5f}, 1), b = MeshGenerators::box({0.5f, 0.25f, 0.5f}, 2);
    for (auto& p : a.positions) p += glm::vec3(-0.25f, 0.0f, 0.0f);
    for (auto& p : b.positions) p += glm::vec3(0.25f, 0.25f, 0.0f);
    for (auto& i : b.indices) i += uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    a.indices.insert(a.indices.end(), b.indices.begin(), b.indices.end());
    const ShadowPlane plane = makePlane({-1, -1, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f);
    OccluderBakeOptions options;
    options.resolution = 64;
    options.dilate = 0;
    options.silhouette = false;
    const Baked baked = bake(*sPrograms, a, plane, options);
    size_t wrong = 0, overlapBlack = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const glm::vec3 q = texelCentre(plane, 64, i, j);
            const bool inA = q.x > -0.75f && q.x < 0.25f && q.y > -0.5f && q.y < 0.5f;
            const bool inB = q.x > -0.25f && q.x < 0.75f && q.y > 0.0f && q.y < 0.5f;
            wrong += baked.at(i, j) != (inA || inB ? kBlack : kWhite);
            overlapBlack += inA && inB && baked.at(i, j) == kBlack;
        }
    EXPECT_EQ(wrong, 0u);
    EXPECT_EQ(overlapBlack, 16u * 16u);                          // the overlap x [-0.25, 0.25], y [0, 0.5]
    EXPECT_EQ(baked.black(), 32u * 32u + 32u * 16u - 16u * 16u); // A + B - overlap
}

// ---- the aircraft's right tail fin ----------------------------------------------------------------

/// The fin's frame as scenes/MeshGenerators.cpp addFin builds it: root (0, 0.03, 0.07), x along the
/// body, `up` canted 25 degrees outward; a point is root + (x, 0, 0) + h up.
struct FinFrame {
    float cant = glm::radians(25.0f);
    glm::vec3 root{0.0f, 0.03f, 0.07f};
    glm::vec3 up{0.0f, std::cos(cant), std::sin(cant)};
    /// The planform in (x, h): root chord x [-0.82, -0.50], tip chord [-0.90, -0.74] at h = 0.38.
    std::vector<glm::vec2> planform{{-0.50f, 0.0f}, {-0.82f, 0.0f}, {-0.90f, 0.38f}, {-0.74f, 0.38f}};
    /// (x, h) of a point of the fin's plane.
    glm::vec2 local(glm::vec3 q) const { return {q.x - root.x, glm::dot(q - root, up)}; }
};

/// The fuselage's tail section (x < -0.3) as addFuselage builds it at tess 8: cross-sections are the
/// 16-gons inscribed in the ellipse y = r sin t, z = 1.3 r cos t, r linear in x there (rings interpolate
/// it exactly). Distance in the normalised (z / 1.3r, y / r) plane, scaled by r (a lower bound).
float fuselageDistance(glm::vec3 q) {
    const float s = (1.0f - q.x) * 0.5f;
    const float r = 0.11f * (1.0f - 0.45f * (s - 0.65f) / 0.35f);
    static const std::vector<glm::vec2> kPolygon = regularPolygon(16, 1.0f);
    return r * polygonDistance(kPolygon, {q.z / (1.3f * r), q.y / r});
}

/// The right stabiliser: planform (x, z) root x [-0.95, -0.62] at z = 0.05, tip [-0.97, -0.82] at
/// z = 0.40, a slab 0.028 thick around y = 0.
float stabiliserDistance(glm::vec3 q) {
    static const std::vector<glm::vec2> kPlanform{
        {-0.62f, 0.05f}, {-0.95f, 0.05f}, {-0.97f, 0.40f}, {-0.82f, 0.40f}};
    return std::max(std::abs(q.y) - 0.014f, polygonDistance(kPlanform, {q.x, q.z}));
}

TEST_F(OccluderTexturesGLTest, AircraftFinPlanformAndItsExtensionIntoTheBody) {
    const Mesh aircraft = MeshGenerators::aircraft(8);
    const FinFrame fin;
    // The fin's mid-plane: u along +x from x = -0.95, v along `up` from h = -0.05, 0.5 x 0.5. Its
    // normal is parallel to the slab's, so both faces of the slab project onto the planform exactly
    // and the side faces (0.028 wide, parallel to the normal) project onto its edges: zero area.
    ShadowPlane plane =
        makePlane(fin.root + glm::vec3(-0.95f, 0, 0) - 0.05f * fin.up, {1, 0, 0}, fin.up, 0.5f);
    plane.name = "fin_right";
    plane.parts = {"fin_right"};
    OccluderBakeOptions options;
    options.resolution = 256;
    options.dilate = 0;
    options.crossSection = false;
    const Baked silhouette = bake(*sPrograms, aircraft, plane, options);
    auto finDistance = [&](glm::vec3 q) { return polygonDistance(fin.planform, fin.local(q)); };
    const Mismatch s = compare(silhouette, plane, finDistance);
    EXPECT_EQ(s.wrong, 0u) << "of " << s.judged << " judged texels";

    // Area: the trapezoid (0.32 + 0.16) / 2 x 0.38 = 0.0912. Tolerance: only texels the boundary
    // crosses can be miscounted, each by at most one texel; the boundary (perimeter P) crosses at
    // most sqrt(2) P / texel + 8 of them.
    const float texel = plane.width / float(options.resolution), area = 0.5f * (0.32f + 0.16f) * 0.38f;
    float perimeter = 0.0f;
    for (size_t k = 0; k < 4; ++k) perimeter += glm::length(fin.planform[(k + 1) % 4] - fin.planform[k]);
    const float measured = float(silhouette.black()) * texel * texel;
    const float tolerance = (std::sqrt(2.0f) * perimeter / texel + 8.0f) * texel * texel;
    std::cout << "[ measured ] fin planform area " << measured << " (trapezoid " << area << ", tolerance "
              << tolerance << ", perimeter " << perimeter << ", texel " << texel << ")\n";
    EXPECT_NEAR(measured, area, tolerance);

    // The cross-section (thesis section 5: the fin's silhouette extended down into the body): black
    // also where the mid-plane lies inside the fuselage (or the stabiliser, which reaches into it).
    options.crossSection = true;
    const Baked extended = bake(*sPrograms, aircraft, plane, options);
    const Mismatch c = compare(extended, plane, [&](glm::vec3 q) {
        return std::min({finDistance(q), fuselageDistance(q), stabiliserDistance(q)});
    });
    EXPECT_EQ(c.wrong, 0u) << "of " << c.judged << " judged texels";
    // Below the root (h < 0): nothing in the silhouette, the body's section in the extension.
    size_t belowRootSilhouette = 0, belowRootExtended = 0;
    for (int j = 0; j < 256; ++j)
        for (int i = 0; i < 256; ++i)
            if (fin.local(texelCentre(plane, 256, i, j)).y < 0.0f) {
                belowRootSilhouette += silhouette.at(i, j) == kBlack;
                belowRootExtended += extended.at(i, j) == kBlack;
            }
    std::cout << "[ measured ] fin texels judged (all matched): " << s.judged << " silhouette, " << c.judged
              << " with cross-section, of " << 256 * 256 << "\n";
    std::cout << "[ measured ] black texels below the fin root: " << belowRootSilhouette << " silhouette, "
              << belowRootExtended << " with cross-section\n";
    EXPECT_EQ(belowRootSilhouette, 0u);
    EXPECT_GT(belowRootExtended, 1000u);
}

// ---- errors and state ---------------------------------------------------------------------------

TEST_F(OccluderTexturesGLTest, UnknownPartAndBadOptionsThrow) {
    ShadowPlane plane = unitZPlane();
    plane.parts = {"no_such_part"};
    const Mesh aircraft = MeshGenerators::aircraft(2);
    try {
        OccluderTextures::bake(*sPrograms, aircraft, plane, {});
        FAIL() << "expected sb::Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_part"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("fin_left"), std::string::npos) << e.what();
    }
    OccluderBakeOptions options;
    options.resolution = 0;
    EXPECT_THROW(OccluderTextures::bake(*sPrograms, squareQuad(0.2f, 0.4f), unitZPlane(), options), Error);
    options.resolution = 16;
    options.dilate = -1;
    EXPECT_THROW(OccluderTextures::bake(*sPrograms, squareQuad(0.2f, 0.4f), unitZPlane(), options), Error);
}

TEST_F(OccluderTexturesGLTest, LeavesGlStateAsFound) {
    TextureFramebuffer target("state", 8, 8, {GL_RGBA8});
    target.bind();
    glViewport(1, 2, 3, 4);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glStencilFunc(GL_EQUAL, 3, 0x0F);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    OccluderBakeOptions options;
    options.resolution = 32;
    options.dilate = 1;
    const GLuint texture =
        OccluderTextures::bake(*sPrograms, MeshGenerators::sphere(8),
                               makePlane({-1.5f, -1.5f, 0}, {1, 0, 0}, {0, 1, 0}, 3.0f), options);
    glDeleteTextures(1, &texture);
    GLint viewport[4] = {}, fbo = 0, func = 0, ref = 0, pass = 0, program = -1;
    GLboolean mask[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    glGetIntegerv(GL_STENCIL_FUNC, &func);
    glGetIntegerv(GL_STENCIL_REF, &ref);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &pass);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_EQ(viewport[0], 1);
    EXPECT_EQ(viewport[3], 4);
    EXPECT_EQ(GLuint(fbo), target.fbo());
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
    EXPECT_FALSE(glIsEnabled(GL_CLIP_DISTANCE0));
    EXPECT_EQ(mask[1], GL_FALSE);
    EXPECT_EQ(mask[2], GL_TRUE);
    EXPECT_EQ(func, GL_EQUAL);
    EXPECT_EQ(ref, 3);
    EXPECT_EQ(pass, GL_REPLACE);
    EXPECT_EQ(program, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// ---- image files ----------------------------------------------------------------------------------

TEST_F(OccluderTexturesGLTest, WriteLoadRoundTripKeepsTexelsAndOrientation) {
    const std::string dir = test::freshTestDir("occluder");
    const std::string path = dir + "/gradient.png";
    const int w = 16, h = 8;
    std::vector<uint8_t> texels(size_t(w * h));
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) texels[size_t(j * w + i)] = uint8_t(i * 15 + j); // all distinct
    OccluderTextures::write(path, texels, w, h);

    // As viewed, the image's bottom-left pixel (last row, first column) is texel (0, 0), v near 0, and
    // its top-left pixel is texel (0, h - 1).
    const test::DecodedPng png = test::decodePng(path); // a reader independent of core/PngFile
    ASSERT_TRUE(png.ok) << png.why;
    ASSERT_EQ(png.width, w);
    ASSERT_EQ(png.height, h);
    ASSERT_EQ(png.channels, 1);
    const std::vector<uint8_t>& image = png.pixels;
    EXPECT_EQ(image[size_t((h - 1) * w)], texels[0]);
    EXPECT_EQ(image[0], texels[size_t((h - 1) * w)]);

    const GLuint texture = OccluderTextures::load(path);
    int rw = 0, rh = 0;
    const std::vector<uint8_t> back = OccluderTextures::readBack(texture, rw, rh);
    glDeleteTextures(1, &texture);
    EXPECT_EQ(rw, w);
    EXPECT_EQ(rh, h);
    EXPECT_EQ(back, texels); // 8-bit PNG: exact
}

TEST_F(OccluderTexturesGLTest, RgbImagesLoadAsLuma) {
    const std::string path = test::freshTestDir("occluder") + "/colours.png";
    // Rec. 709 luma of the encoded values, round(0.2126 R + 0.7152 G + 0.0722 B), by hand:
    // red 54.213 -> 54, green 182.376 -> 182, blue 18.411 -> 18,
    // (100, 150, 200): 21.26 + 107.28 + 14.44 = 142.98 -> 143. Alpha (RGBA) is ignored: not
    // multiplied in (alpha 0 and 10 on red and green would give 0 and 7).
    const uint8_t rgba[4 * 4] = {255, 0, 0, 0, 0, 255, 0, 10, 0, 0, 255, 200, 100, 150, 200, 255};
    PngFile::write(path, 4, 1, 4, rgba); // PngFileTest holds the writer to an independent decoder
    const GLuint texture = OccluderTextures::load(path);
    int w = 0, h = 0;
    const std::vector<uint8_t> back = OccluderTextures::readBack(texture, w, h);
    glDeleteTextures(1, &texture);
    ASSERT_EQ(w, 4);
    ASSERT_EQ(h, 1);
    EXPECT_EQ(back, (std::vector<uint8_t>{54, 182, 18, 143}));
}

TEST_F(OccluderTexturesGLTest, LoadErrorsNameTheFile) {
    const std::string dir = test::freshTestDir("occluder");
    const std::string missing = dir + "/missing.png";
    try {
        OccluderTextures::load(missing);
        FAIL() << "expected sb::Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
    }
    const std::string garbage = dir + "/garbage.png";
    test::writeFile(garbage, "not an image");
    try {
        OccluderTextures::load(garbage);
        FAIL() << "expected sb::Error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(garbage), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos) << e.what();
    }
    EXPECT_THROW(OccluderTextures::write(dir + "/short.png", std::vector<uint8_t>(5), 4, 4), Error);
    EXPECT_THROW(OccluderTextures::write(dir + "/no_such_dir/x.png", std::vector<uint8_t>(16), 4, 4), Error);
}

} // namespace
} // namespace sb
