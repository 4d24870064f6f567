// Unit tests of the occluder technique's shadow planes in scenes: the built-in planes of the generated
// aircraft and teapot (scenes/BuiltinShadowPlanes) against the generated geometry, at several
// tessellations through the scene loader, and the scene file's "shadow_planes" (round trip, every error
// naming the file and the JSON path, built-ins replaced or disabled).
//
// The independent answers come from what the generators document (MeshGenerators.h): the aircraft's
// wings and stabilisers are slabs 0.028 thick in the y = 0 plane, its fins slabs as thick canted 25
// degrees, the left fin the mirror image (z -> -z) of the right one; the Utah teapot is Y-up with its lid
// on the y axis and mirror-symmetric about z = 0, its handle a tube whose C lies in z = 0.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "core/Error.h"
#include "core/Paths.h"
#include "scenes/BuiltinShadowPlanes.h"
#include "scenes/MeshGenerators.h"
#include "scenes/SceneLoader.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

constexpr float kSlabHalfThickness = 0.014f; ///< 0.02 x the 1.4 wingspan, halved (MeshGenerators.h)
const std::string kCube = std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj";

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

std::vector<glm::vec3> verticesOf(const Mesh& mesh, const std::string& part) {
    std::vector<glm::vec3> out;
    for (const auto& p : mesh.parts)
        if (p.name == part)
            for (uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i)
                out.push_back(mesh.positions[mesh.indices[i]]);
    EXPECT_FALSE(out.empty()) << "no part " << part;
    return out;
}

bool hasPart(const Mesh& mesh, const std::string& name) {
    return std::any_of(mesh.parts.begin(), mesh.parts.end(),
                       [&](const MeshPart& p) { return p.name == name; });
}

const ShadowPlane& plane(const Mesh& mesh, const std::string& name) {
    for (const auto& p : mesh.shadowPlanes)
        if (p.name == name) return p;
    ADD_FAILURE() << "no shadow plane " << name;
    static const ShadowPlane kNone;
    return kNone;
}

std::vector<std::string> planeNames(const Mesh& mesh) {
    std::vector<std::string> names;
    for (const auto& p : mesh.shadowPlanes) names.push_back(p.name);
    return names;
}

/// A point in a plane's frame: texture coordinates (equation 8 for a point on the plane, the projection
/// along the normal otherwise) and the signed distance from the plane.
struct Local {
    glm::vec2 uv;
    float distance;
};
Local local(const ShadowPlane& p, const glm::vec3& q) {
    const glm::vec3 d = q - p.origin;
    return {glm::vec2(glm::dot(p.right, d) / p.width, glm::dot(p.up, d) / p.height), glm::dot(p.normal, d)};
}
bool inRectangle(const glm::vec2& uv, float eps = 1e-5f) {
    return uv.x >= -eps && uv.x <= 1.0f + eps && uv.y >= -eps && uv.y <= 1.0f + eps;
}

void expectOrthonormal(const ShadowPlane& p) {
    EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-5f) << p.name;
    EXPECT_NEAR(glm::length(p.right), 1.0f, 1e-5f) << p.name;
    EXPECT_NEAR(glm::length(p.up), 1.0f, 1e-5f) << p.name;
    EXPECT_NEAR(glm::dot(p.normal, p.right), 0.0f, 1e-5f) << p.name;
    EXPECT_NEAR(glm::dot(p.normal, p.up), 0.0f, 1e-5f) << p.name;
    EXPECT_NEAR(glm::dot(p.right, p.up), 0.0f, 1e-5f) << p.name;
    EXPECT_GT(p.width, 0.0f) << p.name;
    EXPECT_GT(p.height, 0.0f) << p.name;
    EXPECT_NO_THROW(p.validate("test"));
}

/// Every vertex of `part` projects into the plane's rectangle.
void expectCovers(const ShadowPlane& p, const Mesh& mesh, const std::string& part) {
    int outside = 0;
    for (const auto& q : verticesOf(mesh, part)) outside += !inRectangle(local(p, q).uv);
    EXPECT_EQ(outside, 0) << p.name << ": vertices of " << part << " outside its rectangle";
}

/// The part's vertices lie on both sides of the plane: it cuts through the part.
void expectCuts(const ShadowPlane& p, const Mesh& mesh, const std::string& part) {
    float lo = 1e30f, hi = -1e30f;
    for (const auto& q : verticesOf(mesh, part)) {
        lo = std::min(lo, local(p, q).distance);
        hi = std::max(hi, local(p, q).distance);
    }
    EXPECT_LT(lo, -1e-3f) << p.name << " does not cut " << part;
    EXPECT_GT(hi, 1e-3f) << p.name << " does not cut " << part;
}

// ---- aircraft -------------------------------------------------------------------------------------

void checkAircraft(const Mesh& m) {
    SCOPED_TRACE("aircraft with " + std::to_string(m.triangleCount()) + " triangles");
    ASSERT_EQ(planeNames(m), (std::vector<std::string>{"wings", "fin_right", "fin_left"}));
    for (const auto& p : m.shadowPlanes) expectOrthonormal(p);

    // Texture A: the wings' mid-plane, covering the top view without the fins.
    const ShadowPlane& wings = plane(m, "wings");
    EXPECT_EQ(wings.parts, (std::vector<std::string>{"fuselage", "wings", "stabilisers"}));
    EXPECT_FALSE(wings.solid);
    EXPECT_EQ(wings.texture, "auto");
    EXPECT_NEAR(std::abs(wings.normal.y), 1.0f, 1e-5f);
    for (const char* part : {"wings", "stabilisers"})
        for (const auto& q : verticesOf(m, part))
            ASSERT_LE(std::abs(local(wings, q).distance), kSlabHalfThickness + 1e-5f) << part;
    for (const char* part : {"fuselage", "wings", "stabilisers"}) expectCovers(wings, m, part);

    // Texture B on both fins' mid-planes.
    const ShadowPlane& right = plane(m, "fin_right");
    const ShadowPlane& left = plane(m, "fin_left");
    EXPECT_EQ(right.parts, (std::vector<std::string>{"fin_right"}));
    EXPECT_EQ(left.parts, (std::vector<std::string>{"fin_left"}));
    EXPECT_TRUE(right.textureOf.empty());
    EXPECT_EQ(left.textureOf, "fin_right");
    EXPECT_FLOAT_EQ(left.width, right.width);
    EXPECT_FLOAT_EQ(left.height, right.height);
    for (const auto* fin : {&right, &left}) {
        const std::string part = fin->name;
        // Canted 25 degrees from vertical: the normal is 25 degrees from horizontal.
        EXPECT_NEAR(std::abs(fin->normal.y), std::sin(glm::radians(25.0f)), 1e-4f) << part;
        float lowest = 1e30f;
        for (const auto& q : verticesOf(m, part)) {
            ASSERT_LE(std::abs(local(*fin, q).distance), kSlabHalfThickness + 1e-5f) << part;
            lowest = std::min(lowest, local(*fin, q).uv.y);
        }
        expectCovers(*fin, m, part);
        // The rectangle reaches below the fin's root into the fuselage, down to the wings' plane.
        EXPECT_GT(lowest, 0.05f) << part << ": no room below the root";
        EXPECT_LE(fin->origin.y, 0.0f) << part;
        EXPECT_LE((fin->origin + fin->width * fin->right).y, 0.0f) << part;
    }
    // The mirror property: a left-fin vertex and its mirror image, a right-fin vertex, share uv.
    const std::vector<glm::vec3> rightFin = verticesOf(m, "fin_right");
    for (const auto& p : verticesOf(m, "fin_left")) {
        const glm::vec3 mirrored(p.x, p.y, -p.z);
        float nearest = 1e30f;
        for (const auto& q : rightFin) nearest = std::min(nearest, glm::length(q - mirrored));
        ASSERT_LT(nearest, 1e-5f) << "the generator's fins are no longer mirror images";
        const glm::vec2 a = local(left, p).uv, b = local(right, mirrored).uv;
        ASSERT_NEAR(a.x, b.x, 1e-5f);
        ASSERT_NEAR(a.y, b.y, 1e-5f);
    }
}

// ---- teapot ---------------------------------------------------------------------------------------

std::string teapotFile() {
    const std::string path = Paths::findResource("scenes/data/teapot.bpt");
    EXPECT_FALSE(path.empty()) << "scenes/data/teapot.bpt not found";
    return path;
}

/// Number of crossings of the ray from `from` along +z with the part's triangles (Moller-Trumbore).
int crossingsUp(const Mesh& m, const std::string& part, const glm::vec3& from) {
    const glm::vec3 dir(0, 0, 1);
    int hits = 0;
    for (const auto& p : m.parts) {
        if (p.name != part) continue;
        for (uint32_t t = p.firstIndex; t + 3 <= p.firstIndex + p.indexCount; t += 3) {
            const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                            c = m.positions[m.indices[t + 2]];
            const glm::vec3 e1 = b - a, e2 = c - a, h = glm::cross(dir, e2);
            const float det = glm::dot(e1, h);
            if (std::abs(det) < 1e-12f) continue;
            const glm::vec3 s = from - a;
            const float u = glm::dot(s, h) / det;
            const glm::vec3 q = glm::cross(s, e1);
            const float v = glm::dot(dir, q) / det;
            const float t0 = glm::dot(e2, q) / det;
            if (u >= 0 && v >= 0 && u + v <= 1 && t0 > 0) ++hits;
        }
    }
    return hits;
}

void checkTeapot(const Mesh& m) {
    SCOPED_TRACE("teapot with " + std::to_string(m.triangleCount()) + " triangles");
    ASSERT_EQ(planeNames(m), (std::vector<std::string>{"lid_side", "lid_front", "lid_knob", "spout_vertical",
                                                       "spout_horizontal", "spout_cap", "handle_1",
                                                       "handle_2", "handle_3", "handle_4", "handle_5"}));
    for (const auto& p : m.shadowPlanes) {
        expectOrthonormal(p);
        ASSERT_FALSE(p.parts.empty()) << p.name;
        for (const auto& part : p.parts) EXPECT_TRUE(hasPart(m, part)) << p.name << ": " << part;
        EXPECT_EQ(p.texture, "auto") << p.name;
    }
    // No plane for the round body, rim or bottom (thesis section 5).
    for (const auto& p : m.shadowPlanes)
        for (const auto& part : p.parts) EXPECT_TRUE(part == "lid" || part == "spout" || part == "handle");

    // The lid: two perpendicular vertical planes through its axis (the y axis), one texture.
    const ShadowPlane& side = plane(m, "lid_side");
    const ShadowPlane& front = plane(m, "lid_front");
    for (const auto* p : {&side, &front}) {
        EXPECT_EQ(p->parts, (std::vector<std::string>{"lid"}));
        EXPECT_FALSE(p->solid);
        EXPECT_NEAR(p->normal.y, 0.0f, 1e-5f) << p->name << " is not vertical";
        EXPECT_NEAR(std::abs(p->up.y), 1.0f, 1e-5f) << p->name;
        for (float y : {2.4f, 3.15f})
            EXPECT_NEAR(local(*p, glm::vec3(0, y, 0)).distance, 0.0f, 1e-4f) << p->name;
        expectCuts(*p, m, "lid");
        expectCovers(*p, m, "lid");
    }
    EXPECT_NEAR(glm::dot(side.normal, front.normal), 0.0f, 1e-5f);
    EXPECT_TRUE(side.textureOf.empty());
    EXPECT_EQ(front.textureOf, "lid_side");
    // The shared texture maps alike: a lid vertex turned 90 degrees about the axis (side's normal onto
    // front's) lands on the same uv of front as it had on side.
    const float turn =
        std::atan2(glm::cross(side.normal, front.normal).y, glm::dot(side.normal, front.normal));
    for (const auto& p : verticesOf(m, "lid")) {
        const glm::vec3 q(std::cos(turn) * p.x + std::sin(turn) * p.z, p.y,
                          -std::sin(turn) * p.x + std::cos(turn) * p.z);
        const glm::vec2 a = local(side, p).uv, b = local(front, q).uv;
        ASSERT_NEAR(a.x, b.x, 1e-4f);
        ASSERT_NEAR(a.y, b.y, 1e-4f);
    }

    // The knob's plane: horizontal at the knob's widest ring. Independently: going up from the rim the
    // lid's rings narrow to the neck (the first ring narrower than the next one), the knob is the lid
    // above the neck, and its widest ring gives the height.
    const std::vector<glm::vec3> lid = verticesOf(m, "lid");
    std::vector<std::pair<float, float>> rings; // (y, radius), bottom up
    {
        std::vector<std::pair<float, float>> profile;
        for (const auto& p : lid) profile.emplace_back(p.y, std::sqrt(p.x * p.x + p.z * p.z));
        std::sort(profile.begin(), profile.end());
        for (const auto& [y, r] : profile)
            if (rings.empty() || y - rings.back().first > 1e-5f)
                rings.emplace_back(y, r);
            else
                rings.back().second = std::max(rings.back().second, r);
    }
    size_t neck = 0;
    while (neck + 1 < rings.size() && rings[neck + 1].second <= rings[neck].second) ++neck;
    ASSERT_LT(neck + 1, rings.size()) << "no neck";
    float knobY = 0.0f, knobR = 0.0f;
    for (size_t i = neck + 1; i < rings.size(); ++i)
        if (rings[i].second > knobR) std::tie(knobY, knobR) = rings[i];
    const ShadowPlane& knob = plane(m, "lid_knob");
    EXPECT_EQ(knob.parts, (std::vector<std::string>{"lid"}));
    EXPECT_NEAR(std::abs(knob.normal.y), 1.0f, 1e-5f);
    EXPECT_NEAR(knob.origin.y, knobY, 1e-4f);
    const glm::vec3 knobCentre = knob.origin + 0.5f * knob.width * knob.right + 0.5f * knob.height * knob.up;
    EXPECT_NEAR(knobCentre.x, 0.0f, 1e-4f);
    EXPECT_NEAR(knobCentre.z, 0.0f, 1e-4f);
    EXPECT_NEAR(knob.width, knob.height, 1e-5f);
    EXPECT_GE(0.5f * knob.width, knobR); // the square holds the widest ring, with a narrow border
    EXPECT_LE(0.5f * knob.width, 1.2f * knobR);
    expectCuts(knob, m, "lid");
    for (const auto& p : lid)
        if (local(knob, p).distance > 0.0f) {
            EXPECT_TRUE(inRectangle(local(knob, p).uv)) << "knob top outside";
        }

    // The spout: a vertical profile (the mirror plane z = 0), a horizontal profile and a cap, along its
    // axis on an angle.
    const ShadowPlane& vertical = plane(m, "spout_vertical");
    const ShadowPlane& horizontal = plane(m, "spout_horizontal");
    const ShadowPlane& cap = plane(m, "spout_cap");
    EXPECT_NEAR(std::abs(vertical.normal.z), 1.0f, 1e-5f);
    EXPECT_NEAR(local(vertical, glm::vec3(2.5f, 1.5f, 0.0f)).distance, 0.0f, 1e-4f);
    EXPECT_NEAR(horizontal.normal.z, 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(vertical.normal, horizontal.normal), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(vertical.normal, cap.normal), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(horizontal.normal, cap.normal), 0.0f, 1e-5f);
    const float elevation = glm::degrees(std::asin(std::abs(cap.normal.y)));
    EXPECT_TRUE(elevation > 20.0f && elevation < 70.0f) << "spout axis at " << elevation << " degrees";
    EXPECT_TRUE(cap.normal.x > 0.0f && cap.normal.y > 0.0f) << "the axis runs up and out (+x), to the tip";
    int beyondCap = 0;
    const std::vector<glm::vec3> spout = verticesOf(m, "spout");
    for (const auto& p : spout) beyondCap += local(cap, p).distance > 0.0f;
    EXPECT_GT(beyondCap, 0);
    EXPECT_LT(float(beyondCap), 0.2f * float(spout.size())) << "the cap is not at the spout's tip";
    for (const auto* p : {&vertical, &horizontal, &cap}) {
        EXPECT_EQ(p->parts, (std::vector<std::string>{"spout"}));
        EXPECT_FALSE(p->solid);
        EXPECT_TRUE(p->textureOf.empty());
        expectCuts(*p, m, "spout");
        expectCovers(*p, m, "spout");
    }

    // The handle: five solid strips end to end along the C, across its width (z).
    const std::vector<glm::vec3> handle = verticesOf(m, "handle");
    float halfWidth = 0.0f;
    for (const auto& p : handle) halfWidth = std::max(halfWidth, std::abs(p.z));
    std::vector<const ShadowPlane*> strips;
    for (int i = 1; i <= 5; ++i) strips.push_back(&plane(m, "handle_" + std::to_string(i)));
    float meanWidth = 0.0f;
    for (const auto* s : strips) meanWidth += s->width / 5.0f;
    for (size_t i = 0; i < strips.size(); ++i) {
        const ShadowPlane& s = *strips[i];
        EXPECT_TRUE(s.solid) << s.name;
        EXPECT_TRUE(s.textureOf.empty()) << s.name;
        EXPECT_EQ(s.parts, (std::vector<std::string>{"handle"}));
        EXPECT_NEAR(std::abs(s.up.z), 1.0f, 1e-5f) << s.name << ": not across the handle";
        EXPECT_NEAR(s.origin.z * glm::sign(s.up.z), -halfWidth, 1e-3f) << s.name;
        EXPECT_NEAR(s.height, 2.0f * halfWidth, 2e-3f) << s.name;
        EXPECT_TRUE(s.width > 0.6f * meanWidth && s.width < 1.4f * meanWidth) << s.name << " not a fifth";
        if (i + 1 < strips.size()) { // the next strip starts where this one ends
            const glm::vec3 gap = s.origin + s.width * s.right - strips[i + 1]->origin;
            EXPECT_LT(glm::length(glm::cross(gap, s.up)), 1e-4f) << s.name << " and the next do not meet";
        }
        // The strip runs inside the tube: points of its middle line (z = 0) have the handle's wall
        // above them once (inside a closed cross-section) rather than 0 or 2 times.
        for (int k = 1; k < 10; ++k) {
            const glm::vec3 q = s.origin + (0.1f * float(k)) * s.width * s.right + 0.5f * s.height * s.up +
                                glm::vec3(1.3e-5f, 0.7e-5f, 0.0f); // off the patch seams
            EXPECT_EQ(crossingsUp(m, "handle", q - glm::vec3(0, 0, q.z)), 1)
                << s.name << " leaves the handle at " << q.x << ", " << q.y;
        }
    }
    EXPECT_GT(strips.front()->origin.y,
              (strips.back()->origin + strips.back()->width * strips.back()->right).y)
        << "numbered from the upper joint";

    // Cover: the strips' solid shadows join into the handle's. For lights in the C's plane (z = 0; the
    // overhead light, where one C-shaped plane would cast nothing, among them) a receiver behind any
    // handle vertex, as seen from the light, is shadowed by some strip once moved towards the strips'
    // shadow by at most the tolerance. The strips are chords of the tube's centre line, so the handle's
    // shadow is wider by the tube's radius on each side, and more where a chord cuts a bend of the C
    // (its sagitta): the tolerance is the tube's full thickness in the C's plane (measured at the C's
    // back, where the tube is vertical: from its outermost vertex in to the inner wall), and most
    // shadows must need no more than the radius. Across the C (z) the strips are exactly as wide as
    // the handle; receivers are taken 1e-4 inside that edge.
    float back = 1e30f, backY = 0.0f;
    for (const auto& p : handle)
        if (p.x < back) std::tie(back, backY) = std::make_pair(p.x, p.y);
    float inner = -1e30f;
    for (const auto& p : handle)
        if (std::abs(p.y - backY) < 0.02f && std::abs(p.z) < 1e-3f) inner = std::max(inner, p.x);
    const float radius = 0.5f * (inner - back), tolerance = 2.0f * radius;
    EXPECT_GT(radius, 0.05f);
    float worst = 0.0f;
    int withinRadius = 0, total = 0;
    for (int degrees = 0; degrees < 360; degrees += 5) {
        const float a = glm::radians(float(degrees));
        const glm::vec3 towardLight(std::cos(a), std::sin(a), 0.0f), across(-std::sin(a), std::cos(a), 0.0f);
        for (const auto& p : handle) {
            const glm::vec3 receiver = glm::vec3(p.x, p.y, p.z * (1.0f - 1e-4f)) - 10.0f * towardLight;
            float needed = 1e30f;
            for (int k = 0; k <= 40 && needed > 1e29f; ++k) {
                const float offset = tolerance * float(k) / 40.0f;
                for (float sign : {1.0f, -1.0f})
                    for (const auto* s : strips)
                        if (s->solidShadows(receiver + sign * offset * across, towardLight)) needed = offset;
            }
            worst = std::max(worst, needed);
            withinRadius += needed <= radius;
            ++total;
        }
    }
    EXPECT_LE(worst, tolerance) << "a handle vertex's shadow lies farther than the tube's thickness from the "
                                   "strips' shadows";
    EXPECT_GE(float(withinRadius), 0.95f * float(total)) << "shadows farther than the tube's radius";
}

// ---- scene files ------------------------------------------------------------------------------------

/// Writes a scene with one aircraft mesh whose "shadow_planes" is `planes` (JSON text) and returns
/// its path.
std::string writeAircraftScene(const std::string& dir, const std::string& planes, int tess = 4) {
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"meshes": [{"name": "jet", "generator": "aircraft", "tessellation": )" +
                              std::to_string(tess) +
                              (planes.empty() ? "" : ", \"shadow_planes\": " + planes) +
                              R"(}], "instances": [{"mesh": "jet"}]})");
    return path;
}

const std::string kValidPlane = R"({"name": "ok", "origin": [0, 0, 0], "normal": [0, 1, 0],
    "right": [1, 0, 0], "up": [0, 0, -1], "width": 1, "height": 1})";

/// The message of the sb::Error that loading `planes` as the aircraft's shadow planes throws.
std::string planeError(const std::string& dir, const std::string& planes) {
    const std::string path = writeAircraftScene(dir, planes);
    try {
        SceneLoader::load(path);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        const std::string message = e.what();
        EXPECT_TRUE(contains(message, path)) << message << " does not name the file";
        return message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an sb::Error: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no error for " << planes;
    return "";
}

/// A second plane that differs from the valid one by `from` -> `to`.
std::string withBadSecond(const std::string& from, const std::string& to) {
    std::string bad = kValidPlane;
    const size_t at = bad.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    const size_t name = bad.find("\"ok\"");
    bad.replace(name, 4, "\"bad\"");
    return "[" + kValidPlane + ", " + bad + "]";
}

} // namespace

TEST(ShadowPlanesSceneTest, AircraftPlanesAtEveryTessellation) {
    for (int tess : {2, 4, 8, 16, 32}) {
        Mesh m = MeshGenerators::aircraft(tess);
        m.shadowPlanes = BuiltinShadowPlanes::forGenerator("aircraft", m);
        checkAircraft(m);
    }
}

TEST(ShadowPlanesSceneTest, TeapotPlanesAtTheDefaultTessellation) {
    Mesh m = MeshGenerators::teapot(teapotFile(), 8);
    m.shadowPlanes = BuiltinShadowPlanes::forGenerator("teapot", m);
    checkTeapot(m);
}

TEST(ShadowPlanesSceneTest, GeneratedPlanesSurviveTheTessellationOption) {
    // Through the loader: --tess replaces the file's tessellation and the planes are computed on the
    // mesh it makes.
    const std::string dir = test::freshTestDir("planes");
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"meshes": [{"name": "jet", "generator": "aircraft"},
                                         {"name": "pot", "generator": "teapot"}],
                              "instances": [{"mesh": "jet"}, {"mesh": "pot", "position": [5, 0, 0]}]})");
    for (int tess : {4, 8, 16}) {
        SCOPED_TRACE("--tess " + std::to_string(tess));
        SceneOptions options;
        options.tessellation = tess;
        const Scene s = SceneLoader::load(path, options);
        EXPECT_EQ(s.meshes[0].triangleCount(), MeshGenerators::aircraft(tess).triangleCount());
        EXPECT_EQ(s.meshes[1].triangleCount(), MeshGenerators::teapot(teapotFile(), tess).triangleCount());
        checkAircraft(s.meshes[0]);
        checkTeapot(s.meshes[1]);
    }
}

TEST(ShadowPlanesSceneTest, TessellationFactorPlanesAreThoseOfTheFinalMesh) {
    const std::string dir = test::freshTestDir("planes");
    SceneOptions options;
    options.tessellationFactor = 2.0f;
    const Scene s = SceneLoader::load(writeAircraftScene(dir, "", 4), options);
    const Mesh expected = MeshGenerators::aircraft(8);
    ASSERT_EQ(s.meshes[0].triangleCount(), expected.triangleCount());
    const auto planes = BuiltinShadowPlanes::forGenerator("aircraft", expected);
    ASSERT_EQ(s.meshes[0].shadowPlanes.size(), planes.size());
    for (size_t i = 0; i < planes.size(); ++i) {
        EXPECT_EQ(s.meshes[0].shadowPlanes[i].origin, planes[i].origin);
        EXPECT_EQ(s.meshes[0].shadowPlanes[i].height, planes[i].height);
    }
}

TEST(ShadowPlanesSceneTest, OtherGeneratorsAndModelFilesHaveNone) {
    for (const char* g : {"sphere", "box", "cylinder", "plane", "lantern"}) {
        const std::string json = std::string(R"({"meshes": [{"name": "m", "generator": ")") + g +
                                 R"("}], "instances": [{"mesh": "m"}]})";
        EXPECT_TRUE(SceneLoader::parse(json, "test.json").meshes[0].shadowPlanes.empty()) << g;
    }
    const std::string model =
        R"({"meshes": [{"name": "m", "file": ")" + kCube + R"("}], "instances": [{"mesh": "m"}]})";
    EXPECT_TRUE(SceneLoader::parse(model, "test.json").meshes[0].shadowPlanes.empty());
    // A model file takes declared planes.
    const std::string declared = R"({"meshes": [{"name": "m", "file": ")" + kCube +
                                 R"(", "shadow_planes": [)" + kValidPlane +
                                 R"(]}], "instances": [{"mesh": "m"}]})";
    EXPECT_EQ(SceneLoader::parse(declared, "test.json").meshes[0].shadowPlanes.size(), 1u);
    // A non-standard teapot file (one part "patches") has none of the parts the planes stand for.
    Mesh patches = MeshGenerators::teapot(teapotFile(), 4);
    patches.parts = {{"patches", 0, uint32_t(patches.indices.size())}};
    EXPECT_TRUE(BuiltinShadowPlanes::forGenerator("teapot", patches).empty());
}

TEST(ShadowPlanesSceneTest, ModelOptionDropsTheReplacedMeshsPlanes) {
    const std::string json = R"({"meshes": [{"name": "jet", "generator": "aircraft", "tessellation": 4}],
        "layout": {"mesh": "jet", "count": 2, "region": [[0, 0, 0], [1, 1, 1]]}})";
    EXPECT_EQ(SceneLoader::parse(json, "test.json").meshes[0].shadowPlanes.size(), 3u);
    SceneOptions options;
    options.modelPath = kCube;
    EXPECT_TRUE(SceneLoader::parse(json, "test.json", options).meshes[0].shadowPlanes.empty());
}

TEST(ShadowPlanesSceneTest, GeneratedAircraftWithoutTheKeyGetsTheBuiltins) {
    const std::string dir = test::freshTestDir("planes");
    const Scene s = SceneLoader::load(writeAircraftScene(dir, ""));
    EXPECT_EQ(planeNames(s.meshes[0]), (std::vector<std::string>{"wings", "fin_right", "fin_left"}));
    checkAircraft(s.meshes[0]);
}

TEST(ShadowPlanesSceneTest, EmptyListDisablesTheBuiltins) {
    const std::string dir = test::freshTestDir("planes");
    const Scene s = SceneLoader::load(writeAircraftScene(dir, "[]"));
    EXPECT_TRUE(s.meshes[0].shadowPlanes.empty());
}

TEST(ShadowPlanesSceneTest, DeclaredPlanesRoundTrip) {
    const std::string dir = test::freshTestDir("planes");
    fs::create_directories(dir + "/tex");
    test::writeFile(dir + "/tex/fin.png", "not decoded by the loader");
    const std::string planes = R"([
      {"name": "top", "origin": [1.5, -2, 3.25], "normal": [0, 1, 0], "right": [0.6, 0, 0.8],
       "up": [0.8, 0, -0.6], "width": 2.5, "height": 0.75, "solid": false, "parts": ["wings", "fuselage"],
       "texture": "tex/../tex/fin.png"},
      {"name": "twin", "origin": [0, 0, 0], "normal": [0, 0, 1], "right": [1, 0, 0], "up": [0, 1, 0],
       "width": 1, "height": 2, "texture_of": "top", "section_only": true},
      {"name": "block", "origin": [0, 1, 0], "normal": [1, 0, 0], "right": [0, 0, -1], "up": [0, 1, 0],
       "width": 0.5, "height": 0.25, "solid": true, "texture": "auto", "parts": ["fin_left"]}])";
    const Scene s = SceneLoader::load(writeAircraftScene(dir, planes));
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(planeNames(m), (std::vector<std::string>{"top", "twin", "block"}));
    const ShadowPlane& top = m.shadowPlanes[0];
    EXPECT_EQ(top.origin, glm::vec3(1.5f, -2.0f, 3.25f));
    EXPECT_EQ(top.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(top.right, glm::vec3(0.6f, 0.0f, 0.8f)); // as given, not renormalised
    EXPECT_EQ(top.up, glm::vec3(0.8f, 0.0f, -0.6f));
    EXPECT_EQ(top.width, 2.5f);
    EXPECT_EQ(top.height, 0.75f);
    EXPECT_FALSE(top.solid);
    EXPECT_EQ(top.parts, (std::vector<std::string>{"wings", "fuselage"}));
    EXPECT_TRUE(fs::path(top.texture).is_absolute()) << top.texture;
    EXPECT_EQ(top.texture, fs::absolute(fs::path(dir) / "tex/fin.png").lexically_normal().string());
    EXPECT_TRUE(top.textureOf.empty());
    EXPECT_FALSE(top.sectionOnly);
    const ShadowPlane& twin = m.shadowPlanes[1];
    EXPECT_TRUE(twin.sectionOnly);
    EXPECT_EQ(twin.textureOf, "top");
    EXPECT_EQ(twin.texture, "auto");
    EXPECT_TRUE(twin.parts.empty()); // the whole mesh
    EXPECT_FALSE(twin.solid);
    const ShadowPlane& block = m.shadowPlanes[2];
    EXPECT_TRUE(block.solid);
    EXPECT_EQ(block.texture, "auto");
    EXPECT_EQ(block.parts, (std::vector<std::string>{"fin_left"}));
}

TEST(ShadowPlanesSceneTest, EveryErrorNamesTheFileAndTheJsonPath) {
    const std::string dir = test::freshTestDir("planes");
    test::writeFile(dir + "/fin.png", "an image");
    struct Case {
        std::string planes, expected;
    };
    const std::string p1 = "/meshes/0/shadow_planes/1";
    const std::vector<Case> cases = {
        {withBadSecond("\"normal\": [0, 1, 0]", "\"normal\": [0, 1]"),
         p1 + "/normal: expected an array of 3 numbers"},
        {withBadSecond("\"normal\": [0, 1, 0]", "\"normal\": [0, \"up\", 0]"),
         p1 + "/normal: expected an array"},
        {withBadSecond("\"normal\": [0, 1, 0]", "\"normal\": [0, 2, 0]"),
         p1 + "/normal: expected a unit vector"},
        {withBadSecond("\"up\": [0, 0, -1]", "\"up\": [0, 0, -0.5]"), p1 + "/up: expected a unit vector"},
        {withBadSecond("\"right\": [1, 0, 0]", "\"right\": [0.6, 0.8, 0]"),
         p1 + ": shadow plane 'bad': normal, right and up must be perpendicular"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"colour\": 1"),
         p1 + "/colour: unknown key (valid keys: name"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"parts\": [\"wings\", \"wing\"]"),
         p1 + "/parts/1: unknown part \"wing\" of mesh \"jet\" (parts: fuselage, wings, stabilisers, "
              "fin_left, "
              "fin_right)"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"parts\": \"wings\""),
         p1 + "/parts: expected an array"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"texture_of\": \"nope\""),
         p1 + "/texture_of: no shadow plane \"nope\" in mesh \"jet\" (planes: ok, bad)"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"texture_of\": \"bad\""),
         p1 + "/texture_of: a plane cannot use its own texture"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"solid\": true, \"texture\": \"fin.png\""),
         p1 + "/texture: a solid plane has no texture"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"solid\": true, \"texture_of\": \"ok\""),
         p1 + "/texture_of: a solid plane uses no texture"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"texture\": \"fin.png\", \"texture_of\": \"ok\""),
         p1 + "/texture: \"texture\" and \"texture_of\" both give the texture"},
        {withBadSecond("\"width\": 1", "\"width\": 1, \"texture\": \"missing.png\""),
         p1 + "/texture: texture file '" + fs::absolute(fs::path(dir) / "missing.png").string() +
             "' not found"},
        {withBadSecond("\"width\": 1", "\"width\": 0"), p1 + "/width: expected a positive number, got 0"},
        {withBadSecond("\"height\": 1", "\"height\": -2"),
         p1 + "/height: expected a positive number, got -2"},
        {withBadSecond(", \"height\": 1", ""), p1 + ": missing required key \"height\""},
        {"[" + kValidPlane + ", " + kValidPlane + "]", p1 + "/name: duplicate shadow plane name \"ok\""},
        {"[" + kValidPlane + ", 3]", p1 + ": expected an object"},
        {"{}", "/meshes/0/shadow_planes: expected an array"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.planes);
        const std::string message = planeError(dir, c.planes);
        EXPECT_TRUE(contains(message, dir + "/scene.json: " + c.expected)) << message;
    }
}

TEST(ShadowPlanesSceneTest, TextureOfMustNameAPlaneThatOwnsATexture) {
    const std::string dir = test::freshTestDir("planes");
    auto named = [](const std::string& name, const std::string& extra) {
        std::string p = kValidPlane;
        p.replace(p.find("\"ok\""), 4, "\"" + name + "\"");
        return p.substr(0, p.size() - 1) + extra + "}";
    };
    // A chain: c uses b's texture, but b uses a's.
    std::string message =
        planeError(dir, "[" + named("a", "") + ", " + named("b", ", \"texture_of\": \"a\"") + ", " +
                            named("c", ", \"texture_of\": \"b\"") + "]");
    EXPECT_TRUE(contains(message, "/meshes/0/shadow_planes/2/texture_of: shadow plane \"b\" itself uses the "
                                  "texture of \"a\""))
        << message;
    // A solid plane has no texture to share.
    message = planeError(dir, "[" + named("a", ", \"solid\": true") + ", " +
                                  named("b", ", \"texture_of\": \"a\"") + "]");
    EXPECT_TRUE(contains(message, "/meshes/0/shadow_planes/1/texture_of: shadow plane \"a\" is solid"))
        << message;
}
