// Unit tests of scenes/SceneLoader: every error path names file, JSON path and expectation; the
// layout is deterministic; command-line options act on what they promise and nothing else.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "TestPaths.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/SplitMix64.h"
#include "scenes/Math.h"
#include "scenes/ModelLoader.h"
#include "scenes/ProxyCollection.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

const std::string kCube = std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj";

/// A small valid scene; `layoutExtra` is spliced into the layout object, `topExtra` at top level.
std::string sceneJson(const std::string& layoutExtra = "", const std::string& topExtra = "") {
    return R"({
      "meshes": [{"name": "ball", "generator": "sphere", "tessellation": 4},
                 {"name": "ground", "generator": "plane", "size": 50, "tessellation": 2}],
      "instances": [{"mesh": "ground", "casts_shadow": false}],
      "layout": {"mesh": "ball", "count": 10, "seed": 3, "region": [[-5, 1, -5], [5, 2, 5]])" +
           layoutExtra + R"(},
      "lights": [{"type": "directional", "direction": [0, -1, 0.5]}],
      "cameras": [{"name": "far", "eye": [0, 20, 30]},
                  {"name": "near", "follow": "first_instance", "offset": [0, 3, 0]}])" +
           topExtra + "}";
}

std::string errorOf(const std::string& json, const SceneOptions& options = {}) {
    try {
        SceneLoader::parse(json, "test.json", options);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        return e.what();
    }
    return "(no error)";
}

std::vector<glm::vec3> layoutPositions(const Scene& s) {
    std::vector<glm::vec3> out;
    for (const auto& i : s.instances)
        if (i.fromLayout) out.push_back(i.position);
    return out;
}

/// `json` with the first occurrence of `from` replaced by `to` (the test fails if it is missing).
std::string replaced(std::string json, const std::string& from, const std::string& to) {
    const size_t at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? json : json.replace(at, from.size(), to);
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

} // namespace

TEST(SceneLoaderTest, ValidSceneLoads) {
    const Scene s = SceneLoader::parse(sceneJson(), "dir/test.json");
    EXPECT_EQ(s.name, "test");
    EXPECT_EQ(s.sourcePath, "dir/test.json");
    ASSERT_EQ(s.instances.size(), 11u); // ground + 10 layout
    EXPECT_FALSE(s.instances[0].fromLayout);
    for (size_t i = 0; i < s.instances.size(); ++i) {
        EXPECT_EQ(s.instances[i].objectId, i + 1) << "objectId is 1-based in instance order";
        // updateTransforms() ran: the model matrix moves the origin to the position.
        EXPECT_EQ(glm::vec3(s.instances[i].model[3]), s.instances[i].position);
    }
    for (const auto& p : layoutPositions(s)) {
        EXPECT_TRUE(p.x >= -5 && p.x <= 5 && p.y >= 1 && p.y <= 2 && p.z >= -5 && p.z <= 5);
    }
    EXPECT_EQ(s.effects, uint32_t(Effect::HardShadows)); // the default
    EXPECT_NEAR(glm::length(s.lights[0].direction), 1.0f, 1e-6f);
    EXPECT_EQ(s.totalTriangles(), s.meshes[1].triangleCount() + 10 * s.meshes[0].triangleCount());
}

TEST(SceneLoaderTest, MalformedJsonGivesFileAndPosition) {
    const std::string e = errorOf("{\n  \"meshes\": [\n  }\n");
    EXPECT_TRUE(contains(e, "test.json: invalid JSON")) << e;
    EXPECT_TRUE(contains(e, "line 3")) << e;
}

TEST(SceneLoaderTest, WrongTypesNameTheJsonPath) {
    std::string json = sceneJson();
    json = replaced(json, "\"count\": 10", "\"count\": \"ten\"");
    EXPECT_EQ(errorOf(json), "test.json: /layout/count: expected a positive integer, got \"ten\"");
    EXPECT_EQ(errorOf(sceneJson(", \"scale\": -2")),
              "test.json: /layout/scale: expected a positive number, got -2");
    std::string light = sceneJson();
    light = replaced(light, "[0, -1, 0.5]", "[0, 0, 0]");
    EXPECT_EQ(errorOf(light),
              "test.json: /lights/0/direction: expected a non-zero direction [x, y, z], got [0,0,0]");
    EXPECT_EQ(errorOf(sceneJson("", ", \"ambient\": [1, 2]")),
              "test.json: /ambient: expected an array of 3 numbers, got [1,2]");
    EXPECT_EQ(errorOf("[1, 2]"), "test.json: /: expected an object, got [1,2]");
    EXPECT_TRUE(contains(errorOf("{\"meshes\": []}"), "/meshes: expected a non-empty array"));
}

TEST(SceneLoaderTest, UnknownKeysAreErrors) {
    const std::string top = errorOf(sceneJson("", ", \"camreas\": []"));
    EXPECT_TRUE(contains(top, "test.json: /camreas: unknown key (valid keys: name, description, meshes"))
        << top;
    std::string json = sceneJson();
    json = replaced(json, "\"tessellation\": 4", "\"radiuss\": 4");
    const std::string nested = errorOf(json);
    EXPECT_TRUE(contains(nested, "test.json: /meshes/0/radiuss: unknown key")) << nested;
    // A parameter of another generator is unknown too (a size on a sphere).
    json = sceneJson();
    json = replaced(json, "\"tessellation\": 4", "\"size\": 4");
    EXPECT_TRUE(contains(errorOf(json), "/meshes/0/size: unknown key"));
}

TEST(SceneLoaderTest, UnknownGeneratorListsTheValidOnes) {
    std::string json = sceneJson();
    json = replaced(json, "\"sphere\"", "\"spere\"");
    EXPECT_EQ(errorOf(json), "test.json: /meshes/0/generator: expected one of sphere, box, cylinder, plane, "
                             "aircraft, teapot, lantern, got \"spere\"");
}

TEST(SceneLoaderTest, UnknownMeshReferenceIsNamed) {
    std::string json = sceneJson();
    json = replaced(json, "{\"mesh\": \"ground\"", "{\"mesh\": \"grund\"");
    EXPECT_EQ(errorOf(json), "test.json: /instances/0/mesh: unknown mesh \"grund\" (meshes: ball, ground)");
}

TEST(SceneLoaderTest, InstanceCountsAreBounded) {
    SceneOptions zero;
    zero.instances = 0;
    EXPECT_EQ(errorOf(sceneJson(), zero), "--instances must be at least 1");
    std::string json = sceneJson();
    json = replaced(json, "\"count\": 10", "\"count\": 0");
    EXPECT_EQ(errorOf(json), "test.json: /layout/count: expected a positive integer, got 0");
    SceneOptions tooMany;
    tooMany.instances = 1000001;
    EXPECT_TRUE(
        contains(errorOf(sceneJson(), tooMany), "--instances 1000001: more than the maximum of 1000000"));
}

TEST(SceneLoaderTest, AbsurdInstancesExceedTheMemoryLimit) {
    // 1e6 aircraft: ~2.6k triangles * 72 B each in display lists = ~190 GB, far over 8 GiB.
    std::string json = sceneJson();
    json = replaced(json, "\"generator\": \"sphere\", \"tessellation\": 4", "\"generator\": \"aircraft\"");
    SceneOptions options;
    options.instances = 1000000;
    const std::string e = errorOf(json, options);
    EXPECT_EQ(e.rfind("--instances 1000000: estimated memory ", 0), 0u) << e;
    EXPECT_TRUE(contains(e, "GiB exceeds the limit of 8.0 GiB")) << e;
    // The estimate is instances * (triangles * 72 + 128) + meshes + the document: with a tiny limit
    // the document itself is refused before it is parsed, with a little more room the 10 instances.
    SceneOptions tiny;
    tiny.memoryLimitBytes = 1000;
    const std::string document = errorOf(sceneJson(), tiny);
    EXPECT_TRUE(contains(document, "test.json: ")) << document;
    EXPECT_TRUE(contains(document, " JSON values, 1 instances: estimated memory ")) << document;
    EXPECT_TRUE(contains(document, " to read them exceeds the limit of 1000 bytes (--max-memory-gib)"))
        << document;
    tiny.memoryLimitBytes = 40000;
    EXPECT_TRUE(
        contains(errorOf(sceneJson(), tiny), "test.json: /layout/count: 10 instances: estimated memory"));
    tiny.memoryLimitBytes = 100000000;
    EXPECT_NO_THROW(SceneLoader::parse(sceneJson(), "test.json", tiny));
}

TEST(SceneLoaderTest, TessellationPastTheMemoryLimitIsRefusedBeforeBuilding) {
    // A sphere at 4096 has 2 * 4096 * 2048 = 16.8 M triangles; ten instances' copies of 72 B per
    // triangle alone are 12 GB > 8 GiB. The refusal names the tessellation (the mesh's key) and comes
    // from the estimate, not from building the mesh first (before: the layout's count was blamed after
    // the mesh was built, 8.8 s and 1.7 GB later).
    const std::string big = replaced(sceneJson(), "\"tessellation\": 4", "\"tessellation\": 4096");
    const std::string e = errorOf(big);
    EXPECT_TRUE(contains(e, "test.json: /meshes/0: tessellation 4096")) << e;
    EXPECT_TRUE(contains(e, "10 instances")) << e;
    EXPECT_TRUE(contains(e, "exceeds the limit of 8.0 GiB")) << e;
    // --tess is blamed when it set the tessellation.
    SceneOptions tess;
    tess.tessellation = 1024;
    tess.memoryLimitBytes = 100000000; // 1024: 2.1 M triangles, ~0.2 GB of copies for 10 > 0.1 GB
    EXPECT_TRUE(contains(errorOf(sceneJson(), tess), "--tess 1024: mesh \"ball\""))
        << errorOf(sceneJson(), tess);
    // Negative control, and the estimate against a hand count: a sphere at 128 has 256 slices x 254
    // triangles per slice = 65024 triangles; ten instances' copies (72 B each, 46.8 MB) and the mesh
    // (257 x 129 vertices of 24 B, 12 B of indices per triangle: 1.6 MB) make 48.4 MB. A 60 MB limit
    // must accept it, a 40 MB limit refuse it from the estimate (before the mesh is built, so the message
    // names the tessellation, not the layout).
    const std::string mid = replaced(sceneJson(), "\"tessellation\": 4", "\"tessellation\": 128");
    SceneOptions limit;
    limit.memoryLimitBytes = 60000000;
    EXPECT_NO_THROW(SceneLoader::parse(mid, "test.json", limit));
    limit.memoryLimitBytes = 40000000;
    EXPECT_TRUE(contains(errorOf(mid, limit), "/meshes/0: tessellation 128 (about 65024 triangles"))
        << errorOf(mid, limit);
}

TEST(SceneLoaderTest, MissingModelFileIsNamed) {
    std::string json = sceneJson();
    json = replaced(json, "\"generator\": \"sphere\", \"tessellation\": 4", "\"file\": \"nope.obj\"");
    EXPECT_EQ(errorOf(json), "test.json: /meshes/0/file: model file 'nope.obj': no such file");
    SceneOptions options;
    options.modelPath = "/nonexistent/x.obj";
    EXPECT_EQ(errorOf(sceneJson(), options), "model file '/nonexistent/x.obj': no such file");
}

TEST(SceneLoaderTest, ModelFileIsFoundRelativeToTheSceneFile) {
    std::string json = sceneJson();
    json = replaced(json, "\"generator\": \"sphere\", \"tessellation\": 4", "\"file\": \"data/cube.obj\"");
    const Scene s = SceneLoader::parse(json, std::string(SB_SOURCE_DIR) + "/tests/scene.json");
    EXPECT_EQ(s.meshes[0].triangleCount(), 12u);
    EXPECT_EQ(s.meshes[0].name, "ball");
}

TEST(SceneLoaderTest, ModelOptionReplacesTheLayoutMeshAtTheSameSize) {
    SceneOptions options;
    options.modelPath = kCube;
    const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.triangleCount(), 12u);
    // The cube (bounding-sphere radius sqrt 3) is scaled onto the unit sphere's radius 1: its corners
    // end at distance 1 from the centre.
    for (const auto& p : m.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
}

TEST(SceneLoaderTest, LayoutIsDeterministicPerSeed) {
    const auto a = layoutPositions(SceneLoader::parse(sceneJson(), "test.json"));
    const auto b = layoutPositions(SceneLoader::parse(sceneJson(), "test.json"));
    EXPECT_EQ(a, b);
    SceneOptions other;
    other.seed = 4;
    const auto c = layoutPositions(SceneLoader::parse(sceneJson(), "test.json", other));
    ASSERT_EQ(a.size(), c.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_NE(a[i], c[i]);
    // The JSON seed 3 equals --seed 3.
    other.seed = 3;
    EXPECT_EQ(layoutPositions(SceneLoader::parse(sceneJson(), "test.json", other)), a);
}

TEST(SceneLoaderTest, LayoutRandomNumbersAreTheReferenceSplitMix64) {
    // Published reference outputs of SplitMix64 with seed 0 (Vigna's splitmix64.c): the layout does
    // not depend on the standard library's distributions.
    SplitMix64 rng(0);
    EXPECT_EQ(rng.next(), 0xe220a8397b1dcdafull);
    EXPECT_EQ(rng.next(), 0x6e789e6aa1b965f4ull);
    EXPECT_EQ(rng.next(), 0x06c45d188009454full);
    // The first layout instance is therefore fixed: x = lo + (hi - lo) * (next() >> 11) / 2^53.
    SplitMix64 ref(3);
    const double u = double(ref.next() >> 11) / 9007199254740992.0;
    EXPECT_FLOAT_EQ(layoutPositions(SceneLoader::parse(sceneJson(), "test.json"))[0].x,
                    float(-5.0 + 10.0 * u));
}

TEST(SceneLoaderTest, InstancesOptionOverridesTheCount) {
    SceneOptions options;
    options.instances = 37;
    const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
    EXPECT_EQ(layoutPositions(s).size(), 37u);
    // The first instances do not depend on the count (same stream).
    const auto ten = layoutPositions(SceneLoader::parse(sceneJson(), "test.json"));
    for (size_t i = 0; i < ten.size(); ++i) EXPECT_EQ(layoutPositions(s)[i], ten[i]);
}

TEST(SceneLoaderTest, ScaleOptionAppliesOnlyToLayoutInstances) {
    SceneOptions options;
    options.scale = 10.0f;
    const Scene s = SceneLoader::parse(sceneJson(", \"scale\": 0.5"), "test.json", options);
    for (const auto& i : s.instances) EXPECT_FLOAT_EQ(i.scale, i.fromLayout ? 5.0f : 1.0f);
    // The near camera keeps its framing: offset 3 in units of the instance scale.
    const CameraPreset* near = s.findCamera("near");
    ASSERT_NE(near, nullptr);
    EXPECT_NEAR(glm::length(near->eye - near->target), 15.0f, 1e-4f);
}

TEST(SceneLoaderTest, TessellationOptionOverridesAllButThePlane) {
    SceneOptions options;
    options.tessellation = 8;
    const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
    EXPECT_EQ(s.meshes[0].triangleCount(), size_t(4 * 8 * 7)); // sphere at tess 8
    EXPECT_EQ(s.meshes[1].triangleCount(), size_t(2 * 2 * 2)); // plane keeps its own 2
}

TEST(SceneLoaderTest, LightTypeOverrideKeepsTheLightAimedAtTheScene) {
    const Scene base = SceneLoader::parse(sceneJson(), "test.json");
    const glm::vec3 dir = base.lights[0].direction;
    const Aabb casters = base.computeBounds(true);
    for (LightType type : {LightType::Point, LightType::Spot}) {
        SceneOptions options;
        options.lightType = type;
        const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
        const Light& l = s.lights[0];
        EXPECT_EQ(l.type, type);
        // The light sits up-light of the casters' centre, on the line along the old direction.
        const glm::vec3 toCentre = casters.center() - l.position;
        EXPECT_NEAR(glm::dot(glm::normalize(toCentre), dir), 1.0f, 1e-5f);
        EXPECT_GT(glm::length(toCentre), 0.5f * glm::length(casters.extent()));
        if (type != LightType::Spot) continue;
        EXPECT_NEAR(glm::dot(l.direction, dir), 1.0f, 1e-6f);
        // The cone encloses every corner of the casters' bounds.
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 p(c & 1 ? casters.max.x : casters.min.x, c & 2 ? casters.max.y : casters.min.y,
                              c & 4 ? casters.max.z : casters.min.z);
            const float angle =
                glm::degrees(std::acos(glm::dot(glm::normalize(p - l.position), l.direction)));
            EXPECT_LT(angle, l.spotOuterDeg);
        }
    }
}

TEST(SceneLoaderTest, EffectsAndUnknownEffect) {
    const Scene s =
        SceneLoader::parse(sceneJson("", ", \"effects\": [\"hard_shadows\", \"self_shadowing\"]"), "t.json");
    EXPECT_EQ(effectMaskToString(s.effects), "hard_shadows+self_shadowing");
    EXPECT_TRUE(contains(errorOf(sceneJson("", ", \"effects\": [\"soft\"]")),
                         "/effects/0: expected one of hard_shadows"));
}

TEST(SceneLoaderTest, ContentHashChangesWithContentOnly) {
    const Scene a = SceneLoader::parse(sceneJson(), "a.json");
    const Scene b = SceneLoader::parse(sceneJson(), "b.json");
    EXPECT_EQ(a.computeContentHash(), b.computeContentHash()); // the file name is not content
    EXPECT_EQ(a.computeContentHash().size(), 16u);
    Scene moved = a;
    moved.lights[0].direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.5f));
    EXPECT_NE(moved.computeContentHash(), a.computeContentHash());
    Scene seeded = a;
    seeded.instances.back().position.x += 0.001f;
    seeded.updateTransforms();
    EXPECT_NE(seeded.computeContentHash(), a.computeContentHash());
}

// "lighting" (scenes/LightingRate.h): fragment unless the file or --lighting says vertex; a scene lit per
// vertex hashes differently (its image differs), one lit per fragment keeps the hash it had before the
// key existed (the same as the file without it).
TEST(SceneLoaderTest, LightingRateFromTheFileAndTheOption) {
    const Scene plain = SceneLoader::parse(sceneJson(), "a.json");
    EXPECT_EQ(plain.lighting, LightingRate::Fragment);
    const Scene fragment = SceneLoader::parse(sceneJson("", R"(, "lighting": "fragment")"), "a.json");
    EXPECT_EQ(fragment.computeContentHash(), plain.computeContentHash());
    const Scene vertex = SceneLoader::parse(sceneJson("", R"(, "lighting": "vertex")"), "a.json");
    EXPECT_EQ(vertex.lighting, LightingRate::Vertex);
    EXPECT_NE(vertex.computeContentHash(), plain.computeContentHash());
    SceneOptions perFragment;
    perFragment.lighting = LightingRate::Fragment;
    EXPECT_EQ(SceneLoader::parse(sceneJson("", R"(, "lighting": "vertex")"), "a.json", perFragment).lighting,
              LightingRate::Fragment);
    SceneOptions perVertex;
    perVertex.lighting = LightingRate::Vertex;
    EXPECT_EQ(SceneLoader::parse(sceneJson(), "a.json", perVertex).computeContentHash(),
              vertex.computeContentHash());
    EXPECT_TRUE(contains(errorOf(sceneJson("", R"(, "lighting": "gouraud")")),
                         "/lighting: expected one of fragment, vertex"));
}

TEST(SceneLoaderTest, BuiltinScenesLoadWithTheFourCameras) {
    const auto names = SceneLoader::listBuiltinScenes();
    for (const char* name :
         {"aircraft", "teapot", "primitives", "sphere_plane", "city", "point_light", "jack_o_lantern"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
        const Scene s = SceneLoader::load(name);
        EXPECT_EQ(s.name, name);
        for (const char* cam : {"far", "mid", "near", "top"})
            EXPECT_NE(s.findCamera(cam), nullptr) << name << " " << cam;
        // "top" looks straight down.
        const CameraPreset& top = *s.findCamera("top");
        EXPECT_NEAR(glm::normalize(top.target - top.eye).y, -1.0f, 1e-6f) << name;
        // The whole layout is in view of "far" (aspect 1, the narrowest a window gets here).
        const CameraPreset& far = *s.findCamera("far");
        const glm::mat4 vp = cameraProjection(far, 1.0f) * cameraView(far);
        for (const auto& inst : s.instances) {
            if (!inst.fromLayout) continue;
            const Aabb b = transformBounds(s.meshes[inst.mesh].computeBounds(), inst.model);
            for (int c = 0; c < 8; ++c) {
                const glm::vec4 p = vp * glm::vec4(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y,
                                                   c & 4 ? b.max.z : b.min.z, 1.0f);
                ASSERT_GT(p.w, 0.0f);
                EXPECT_LE(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) / p.w, 1.0f) << name;
            }
        }
    }
}

TEST(SceneLoaderTest, BuiltinLayoutScenesFollowTheFirstInstanceStraightDown) {
    for (const char* name : {"aircraft", "teapot", "primitives"}) {
        const Scene s = SceneLoader::load(name);
        const auto first =
            std::find_if(s.instances.begin(), s.instances.end(), [](auto& i) { return i.fromLayout; });
        ASSERT_NE(first, s.instances.end());
        const CameraPreset& near = *s.findCamera("near");
        EXPECT_EQ(near.target, first->position) << name;
        EXPECT_NEAR(glm::normalize(near.target - near.eye).y, -1.0f, 1e-6f) << name;
        EXPECT_GT(glm::length(glm::cross(near.up, near.target - near.eye)), 0.0f)
            << name << ": degenerate up";
    }
    const Scene aircraft = SceneLoader::load("aircraft");
    EXPECT_EQ(layoutPositions(aircraft).size(), 200u);
    EXPECT_EQ(effectMaskToString(aircraft.effects), "hard_shadows+self_shadowing");
}

TEST(SceneLoaderTest, SpherePlaneIsTheAnalyticSetup) {
    const Scene s = SceneLoader::load("sphere_plane");
    const auto sphere =
        std::find_if(s.instances.begin(), s.instances.end(), [](auto& i) { return i.castsShadow; });
    ASSERT_NE(sphere, s.instances.end());
    EXPECT_EQ(sphere->position, glm::vec3(0, 3, 0));
    const Aabb b = s.meshes[sphere->mesh].computeBounds();
    EXPECT_NEAR(b.max.y, 1.0f, 1e-6f); // radius 1
    EXPECT_NEAR(glm::dot(s.lights[0].direction, glm::normalize(glm::vec3(0.3f, -1, 0.2f))), 1.0f, 1e-6f);
}

TEST(SceneLoaderTest, UnknownSceneNameListsTheBuiltins) {
    try {
        SceneLoader::load("aircarft");
        FAIL();
    } catch (const Error& e) {
        EXPECT_TRUE(contains(e.what(), "unknown scene 'aircarft'")) << e.what();
        EXPECT_TRUE(contains(e.what(), "aircraft")) << e.what();
    }
    EXPECT_THROW(SceneLoader::load("/nonexistent/scene.json"), Error);
}

TEST(SceneLoaderTest, OptionsThatNeedALayoutSayWhenThereIsNone) {
    SceneOptions options;
    options.instances = 5;
    EXPECT_THROW(SceneLoader::load("sphere_plane", options), Error);
}

TEST(SceneLoaderTest, LanternTakesRadiusAndThicknessInSceneUnits) {
    std::string json = sceneJson();
    json = replaced(json, "\"generator\": \"sphere\", \"tessellation\": 4",
                    "\"generator\": \"lantern\", \"radius\": 2, \"thickness\": 0.3, \"tessellation\": 12");
    const Scene s = SceneLoader::parse(json, "test.json");
    const Mesh& m = s.meshes[0];
    float inner = 1e9f, outer = 0.0f;
    for (const auto& p : m.positions) {
        inner = std::min(inner, glm::length(p));
        outer = std::max(outer, glm::length(p));
    }
    EXPECT_NEAR(outer, 2.0f, 1e-5f);
    EXPECT_NEAR(inner, 1.7f, 1e-5f);
    EXPECT_EQ(m.parts.size(), 2u);
    // The --tess knob reaches it, clamped to its minimum of 8 by the factor.
    SceneOptions coarse;
    coarse.tessellationFactor = 0.1f;
    EXPECT_NO_THROW(SceneLoader::parse(json, "test.json", coarse));
    // Errors name the key.
    EXPECT_TRUE(contains(errorOf(replaced(json, "\"thickness\": 0.3", "\"thickness\": 2")),
                         "/meshes/0/thickness: expected a thickness below the radius (2), got 2"));
    EXPECT_TRUE(contains(errorOf(replaced(json, "\"tessellation\": 12", "\"tessellation\": 7")),
                         "/meshes/0: lantern: tessellation must be in [8, 4096], got 7"));
    EXPECT_TRUE(
        contains(errorOf(replaced(json, "\"radius\": 2", "\"size\": 2")), "/meshes/0/size: unknown key"));
}

namespace {
const Instance* firstCaster(const Scene& s) {
    for (const auto& i : s.instances)
        if (i.castsShadow) return &i;
    return nullptr;
}
} // namespace

TEST(SceneLoaderTest, CityIsATopViewOfBlocksUnderASteepSun) {
    const Scene s = SceneLoader::load("city");
    size_t casters = 0;
    float tallest = 0.0f;
    for (const auto& inst : s.instances) {
        if (!inst.castsShadow) continue;
        ++casters;
        tallest = std::max(tallest, transformBounds(s.meshes[inst.mesh].computeBounds(), inst.model).max.y);
    }
    EXPECT_EQ(casters, 144u);
    EXPECT_EQ(s.instances.size(), 145u); // and the ground, which does not cast
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_NEAR(glm::dot(s.lights[0].direction, glm::normalize(glm::vec3(0.35f, -1, 0.25f))), 1.0f, 1e-6f);
    // The chapter's ideal case: every camera above all the blocks, "far" looking steeply down.
    for (const auto& c : s.cameras) EXPECT_GT(c.eye.y, tallest) << c.name;
    const CameraPreset& far = *s.findCamera("far");
    EXPECT_LT(glm::normalize(far.target - far.eye).y, -0.8f);
}

TEST(SceneLoaderTest, PointLightSceneGivesRangeCullingAndScissoringWork) {
    const Scene s = SceneLoader::load("point_light");
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& light = s.lights[0];
    EXPECT_EQ(light.type, LightType::Point);
    ASSERT_GT(light.range, 0.0f);
    // Casters wholly outside the range (culled by 9.5.2) and casters inside it.
    size_t outside = 0, inside = 0;
    for (const auto& inst : s.instances) {
        if (!inst.castsShadow) continue;
        const Aabb b = transformBounds(s.meshes[inst.mesh].computeBounds(), inst.model);
        const glm::vec3 nearest = glm::clamp(light.position, b.min, b.max);
        (glm::length(nearest - light.position) > light.range ? outside : inside)++;
    }
    EXPECT_GE(outside, 10u);
    EXPECT_GE(inside, 10u);
    // From "far", the range sphere's screen bounds (its bounding box projected) cover only part of the
    // screen: the scissor rectangle of 9.6.2 is smaller than the viewport.
    const CameraPreset& far = *s.findCamera("far");
    const glm::mat4 vp = cameraProjection(far, 1.0f) * cameraView(far);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner =
            light.position + light.range * glm::vec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
        const glm::vec4 p = vp * glm::vec4(corner, 1.0f);
        ASSERT_GT(p.w, 0.0f);
        lo = glm::min(lo, glm::vec2(p) / p.w);
        hi = glm::max(hi, glm::vec2(p) / p.w);
    }
    lo = glm::max(lo, glm::vec2(-1.0f));
    hi = glm::min(hi, glm::vec2(1.0f));
    EXPECT_LT((hi.x - lo.x) * (hi.y - lo.y) / 4.0f, 0.75f) << "scissor covers the whole screen";
}

TEST(SceneLoaderTest, JackOLanternHasTheLightInsideTheClosedShell) {
    const Scene s = SceneLoader::load("jack_o_lantern");
    const Instance* lantern = firstCaster(s);
    ASSERT_NE(lantern, nullptr);
    EXPECT_EQ(s.meshes[lantern->mesh].parts.size(), 2u); // the lantern generator's shell and holes
    size_t casters = 0;
    for (const auto& inst : s.instances) casters += inst.castsShadow ? 1 : 0;
    EXPECT_EQ(casters, 1u); // the ground does not cast
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    // The light is at the lantern's centre, well inside its inner sphere.
    float inner = 1e9f;
    for (const auto& p : s.meshes[lantern->mesh].positions)
        inner = std::min(inner, glm::length(p) * lantern->scale);
    EXPECT_LT(glm::length(s.lights[0].position - lantern->position), 0.5f * inner);
    // No range, or one that reaches the whole ground.
    const Aabb ground = s.computeBounds(false);
    for (int c = 0; c < 4; ++c) {
        const glm::vec3 corner(c & 1 ? ground.max.x : ground.min.x, 0.0f,
                               c & 2 ? ground.max.z : ground.min.z);
        if (s.lights[0].range > 0.0f) {
            EXPECT_GT(s.lights[0].range, glm::length(corner - s.lights[0].position));
        }
    }
}

// ---- model files: errors naming the file, objects kept apart -----------------------------------------

namespace {

const std::string kInfinite = std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.obj";
const std::string kRoom = "/usr/share/assimp/models/3DS/test1.3ds"; // nine 3DS objects (assimp-testmodels)

/// Whether unit-shape point `q` (the proxy frame's inverse applied) lies inside `shape`, within `eps`.
bool insideUnitShape(ShadowProxy::Shape shape, const glm::vec3& q, float eps) {
    switch (shape) {
    case ShadowProxy::Shape::Sphere:
        return glm::length(q) <= 1.0f + eps;
    case ShadowProxy::Shape::Box:
        return std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}) <= 1.0f + eps;
    case ShadowProxy::Shape::Cylinder:
        return glm::length(glm::vec2(q)) <= 1.0f + eps && std::abs(q.z) <= 1.0f + eps;
    }
    return false;
}

} // namespace

TEST(SceneLoaderTest, ModelOptionNamesTheModelFileNotTheReplacedMesh) {
    // Errors about the mesh (volume's open edges, Embree's non-finite vertex ...) print its name: it
    // must be the file the user gave, not the layout mesh's "ball" they never typed.
    SceneOptions options;
    options.modelPath = kCube;
    const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
    EXPECT_EQ(s.meshes[0].name, "cube.obj");
}

TEST(SceneLoaderTest, InfiniteVertexIsRefusedOnEveryPath) {
    // A scene file's model entry: the scene file, the JSON path and the model file are all named.
    const std::string scene = std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.json";
    std::string error;
    try {
        SceneLoader::load(scene);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        error = e.what();
    }
    EXPECT_EQ(error.rfind(scene + ": /meshes/0/file: model file '", 0), 0u) << error;
    EXPECT_NE(error.find("infinite_vertex.obj': vertex 1 of mesh 'defaultobject' is (inf, 0, 0)"),
              std::string::npos)
        << error;
    // --model: the model file is named.
    SceneOptions options;
    options.modelPath = kInfinite;
    error = errorOf(sceneJson(), options);
    EXPECT_EQ(error.rfind("model file '" + kInfinite + "': vertex 1 ", 0), 0u) << error;
}

TEST(SceneLoaderTest, MultiObjectModelKeepsEveryObjectAsItsOwnCaster) {
    if (!std::filesystem::exists(kRoom)) GTEST_SKIP() << kRoom << " not installed (scripts/install-deps.sh)";
    // test1.3ds has nine objects: --model makes nine meshes, and each of the 10 layout placements nine
    // instances with one transform, so the user's 10 instances are still 10.
    SceneOptions options;
    options.modelPath = kRoom;
    const Scene s = SceneLoader::parse(sceneJson(), "test.json", options);
    const std::vector<Mesh> objects = ModelLoader::loadObjects(kRoom);
    ASSERT_EQ(objects.size(), 9u);
    ASSERT_EQ(s.meshes.size(), 10u); // the nine objects, then the ground
    EXPECT_EQ(s.instances.size(), 1u + 10u * 9u);
    EXPECT_EQ(s.countLayoutInstances(), 10u);
    for (size_t k = 0; k < 9; ++k) EXPECT_EQ(s.meshes[k].name, "test1.3ds:" + objects[k].name);
    for (size_t placement = 0; placement < 10; ++placement)
        for (uint32_t k = 0; k < 9; ++k) {
            const Instance& inst = s.instances[1 + placement * 9 + k];
            EXPECT_EQ(inst.mesh, k);
            EXPECT_EQ(inst.object, k);
            EXPECT_EQ(inst.model, s.instances[1 + placement * 9].model);
        }
    // The objects keep their places relative to each other: one scale and offset maps the file's
    // bounds of every object onto the scene's (tolerance 1e-4 of the unit-sphere fit: float rounding).
    const float scale = s.meshes[0].computeBounds().extent().x / objects[0].computeBounds().extent().x;
    const glm::vec3 offset = s.meshes[0].computeBounds().min - objects[0].computeBounds().min * scale;
    for (size_t k = 0; k < 9; ++k) {
        const Aabb got = s.meshes[k].computeBounds(), file = objects[k].computeBounds();
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(got.min[a], file.min[a] * scale + offset[a], 1e-4f) << objects[k].name;
            EXPECT_NEAR(got.max[a], file.max[a] * scale + offset[a], 1e-4f) << objects[k].name;
        }
    }
}

TEST(SceneLoaderTest, ProxyFitsOneProxyPerObjectOfAModel) {
    if (!std::filesystem::exists(kRoom)) GTEST_SKIP() << kRoom << " not installed (scripts/install-deps.sh)";
    // One instance of the nine-object room: nine fitted proxies, each holding every vertex of its own
    // object (tolerance 1e-4 in unit-shape coordinates: the frames' float inverse), and each crate's
    // proxy far smaller than one box around the room would be.
    const std::string json = R"({"meshes": [{"name": "room", "file": ")" + kRoom + R"("}],
        "instances": [{"mesh": "room", "position": [1, 2, 3], "rotation": [0, 30, 0]}]})";
    const Scene s = SceneLoader::parse(json, "test.json");
    std::vector<uint32_t> owners;
    const std::vector<ShadowProxy> proxies = ProxyCollection::collect(s, false, &owners);
    ASSERT_EQ(proxies.size(), 9u);
    const Aabb room = s.computeBounds();
    const float roomVolume = room.extent().x * room.extent().y * room.extent().z;
    for (size_t k = 0; k < 9; ++k) {
        const Instance& inst = s.instances[k];
        EXPECT_EQ(owners[k], inst.objectId);
        const glm::mat4 toUnit = glm::inverse(proxies[k].frame);
        for (const glm::vec3& p : s.meshes[inst.mesh].positions) {
            const glm::vec3 q(toUnit * inst.model * glm::vec4(p, 1.0f));
            ASSERT_TRUE(insideUnitShape(proxies[k].shape, q, 1e-4f)) << s.meshes[inst.mesh].name;
        }
        if (s.meshes[inst.mesh].name.find("Box05") != std::string::npos) {
            EXPECT_LT(std::abs(glm::determinant(proxies[k].frame)) * 8.0f, 0.05f * roomVolume);
        }
    }
}

TEST(SceneLoaderTest, ModelEntryUpNamesTheFilesUpAxis) {
    if (!std::filesystem::exists(kRoom)) GTEST_SKIP() << kRoom << " not installed (scripts/install-deps.sh)";
    // The room's floor slab Box01 is thin along the file's y (it is Y-up as stored). Declared Z-up,
    // the file's z is turned to +Y, so the slab's thin axis becomes Z (a closed-form swap of axes).
    auto floorExtent = [](const std::string& up) {
        const std::string json = R"({"meshes": [{"name": "room", "file": ")" + kRoom + "\"" + up +
                                 R"(}], "instances": [{"mesh": "room"}]})";
        const Scene s = SceneLoader::parse(json, "test.json");
        for (const Mesh& m : s.meshes)
            if (m.name == "room:Box01") return m.computeBounds().extent();
        ADD_FAILURE() << "no mesh room:Box01";
        return glm::vec3(0.0f);
    };
    const glm::vec3 asStored = floorExtent(""), declared = floorExtent(R"(, "up": "z")");
    EXPECT_NEAR(declared.z, asStored.y, 1e-4f);
    EXPECT_NEAR(declared.y, asStored.z, 1e-4f);
    EXPECT_NEAR(declared.x, asStored.x, 1e-4f);
    const std::string bad = R"({"meshes": [{"name": "room", "file": ")" + kRoom +
                            R"(", "up": "w"}], "instances": [{"mesh": "room"}]})";
    EXPECT_NE(errorOf(bad).find(
                  "test.json: /meshes/0/up: expected the file's up axis, one of x, -x, y, -y, z or -z"),
              std::string::npos)
        << errorOf(bad);
}

// ---- hostile input: every refusal is bad input (exit 2) with one bounded line naming where ---------

TEST(SceneLoaderTest, DeepNestingIsRefusedWithItsPosition) {
    // 200 KB of "[[[[...]]]]" crashed with SIGSEGV: the error message dumped the value recursively,
    // one stack frame per level. Refused where the 65th level opens (JsonReader::kMaxDepth = 64).
    const std::string arrays = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_EQ(errorOf(arrays), "test.json: invalid JSON at line 1, column 65: arrays and objects nested "
                               "deeper than 64 levels (a scene file needs about 5)");
    std::string objects = "{\n\"name\": ";
    for (int i = 0; i < 50000; ++i) objects += "{\"a\":";
    objects += "1" + std::string(50000, '}') + "}";
    // Line 2, column 9 + 5 * 63: the 65th level is the 64th {"a": (the document's { is the first).
    EXPECT_EQ(errorOf(objects).rfind("test.json: invalid JSON at line 2, column 324: arrays and objects", 0),
              0u)
        << errorOf(objects);
    // Exactly 64 levels parse (the error is then about the value, not the depth), and brackets inside
    // strings and comments are not nesting.
    const std::string deep64 = "{\"name\": " + std::string(63, '[') + std::string(63, ']') + "}";
    EXPECT_TRUE(contains(errorOf(deep64), "test.json: /name: expected a string, got [[[["))
        << errorOf(deep64);
    const std::string brackets = std::string(200, '[');
    const Scene s = SceneLoader::parse(
        "// " + brackets + "\n/* " + brackets + " */" +
            replaced(sceneJson(), "\"meshes\"", "\"description\": \"" + brackets + "\", \"meshes\""),
        "test.json");
    EXPECT_EQ(s.instances.size(), 11u);
}

TEST(SceneLoaderTest, DeepValuesAreDescribedWithoutRecursingThroughThem) {
    // JsonReader also reads documents parsed without JsonReader::parse's depth bound (nlohmann's
    // parser is iterative and takes 100000 levels); describing one in an error dumped it recursively
    // and overflowed the stack (SIGSEGV). Now it renders only the first 60 characters.
    const nlohmann::json deep = nlohmann::json::parse(std::string(100000, '[') + std::string(100000, ']'));
    try {
        JsonReader(deep, "x.json").string();
        ADD_FAILURE() << "a nested array was read as a string";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "x.json: /: expected a string, got " + std::string(57, '[') + "...");
    }
}

TEST(SceneLoaderTest, ErrorMessagesShowAShortOneLineExcerpt) {
    // A 200 KB value in a message is cut to 60 characters; before, the whole value was dumped first.
    std::string big = "[";
    for (int i = 0; i < 40000; ++i) big += "12345,";
    big += "0]";
    const std::string e = errorOf("{\"name\": " + big + "}");
    EXPECT_EQ(e, "test.json: /name: expected a string, got [12345,12345,12345,12345,12345,12345,12345,12345,"
                 "12345,12...");
    // A key with a newline (and any length) stays one line: control characters are escaped.
    const std::string key = errorOf("{\"bad\\nkey" + std::string(500, 'k') + "\": 1}");
    EXPECT_EQ(key.find('\n'), std::string::npos) << key;
    EXPECT_TRUE(contains(key, "test.json: /bad\\u000akeykkkk")) << key;
    EXPECT_LT(key.size(), 300u) << key;
    // nlohmann's reason ends with the token read so far: for an unterminated string, the rest of the file.
    const std::string open = errorOf("{\"name\": \"" + std::string(200000, 'x'));
    EXPECT_TRUE(contains(open, "test.json: invalid JSON at line 1, column ")) << open;
    EXPECT_LT(open.size(), 300u) << open.substr(0, 300);
}

TEST(SceneLoaderTest, NumberBeyondDoubleRangeNamesFileAndPosition) {
    // nlohmann throws out_of_range 406 for 1e400 without a position: it left the loader as an
    // unknown exception, exit 1, naming neither the file nor where.
    const std::string e = errorOf(replaced(sceneJson(), "\"count\": 10", "\"count\":\n  1e400"));
    EXPECT_EQ(e.rfind("test.json: invalid JSON at line ", 0), 0u) << e;
    EXPECT_TRUE(contains(e, ", column 3: the number 1e400 is beyond the range of a double")) << e;
    EXPECT_TRUE(contains(errorOf("{\"name\": -2e999}"), "column 10: the number -2e999 is beyond"));
    // An underflow is a number (0 or a denormal), as nlohmann reads it: no error about range.
    EXPECT_TRUE(contains(errorOf(sceneJson("", ", \"ambient\": [1e-400, 0, 0]")), "(no error)"));
}

TEST(SceneLoaderTest, NumbersBeyondFloatRangeAreRefused) {
    // Each was converted to float as +inf (undefined behaviour, in practice inf) and accepted. One row
    // per float getter of JsonReader the scene loader uses.
    const struct {
        const char* name;
        std::string json;
        std::string error;
    } cases[] = {
        {"vec3", sceneJson("", ", \"instances\": [{\"mesh\": \"ball\", \"position\": [1e308, 0, 0]}]"),
         "test.json: /instances/0/position: expected an array of 3 numbers within float range (|x| <= "
         "3.4e38), got [1e+308,0,0]"},
        {"positiveNumber", sceneJson(", \"scale\": 1e39"),
         "test.json: /layout/scale: expected a positive number within float range (|x| <= 3.4e38), got "
         "1e+39"},
        {"nonNegativeNumber",
         replaced(sceneJson(), "\"type\": \"directional\"", "\"type\": \"point\", \"intensity\": 4e38"),
         "test.json: /lights/0/intensity: expected a number >= 0 within float range (|x| <= 3.4e38), got "
         "4e+38"},
        {"generator radius", replaced(sceneJson(), "\"tessellation\": 4", "\"radius\": 1e300"),
         "test.json: /meshes/0/radius: expected a positive number within float range (|x| <= 3.4e38), got "
         "1e+300"},
    };
    for (const auto& c : cases) EXPECT_EQ(errorOf(c.json), c.error) << c.name;
}

TEST(SceneLoaderTest, OverflowingProductsNameTheInstance) {
    // Each number is a finite float, but scale * size, or a point a technique squares distances from,
    // is beyond ModelLoader::kMaxCoordinate (1e18): these loaded and drew inf/NaN.
    const std::string products =
        sceneJson("", ", \"instances\": [{\"mesh\": \"ground\"}, {\"mesh\": \"ball\", \"scale\": 1e30}]");
    EXPECT_EQ(errorOf(products),
              "test.json: /instances/1: instance 1 of mesh \"ball\": world bounds (-1e+30, "
              "-1e+30, -1e+30) to (1e+30, 1e+30, 1e+30) reach beyond +-1e18 (position "
              "+ scale * the mesh's size)");
    // The layout's instances are named by the layout (its scale and region are to blame).
    const std::string layout = errorOf(sceneJson(", \"scale\": 1e20"));
    EXPECT_EQ(layout.rfind("test.json: /layout: instance 1 of mesh \"ball\": world bounds (", 0), 0u)
        << layout;
    // A mesh that is itself too large is named by its entry.
    const std::string mesh = errorOf(replaced(sceneJson(), "\"size\": 50", "\"size\": 1e30"));
    EXPECT_EQ(mesh, "test.json: /meshes/1: mesh \"ground\": bounds (-5e+29, 0, -5e+29) to (5e+29, 0, 5e+29) "
                    "reach beyond +-1e18 in object space");
    EXPECT_EQ(errorOf(replaced(sceneJson(), "[0, 20, 30]", "[0, 2e18, 30]")),
              "test.json: /cameras/0: the point (0, 2e+18, 30) lies beyond +-1e18");
    EXPECT_EQ(errorOf(replaced(sceneJson(), "\"type\": \"directional\"",
                               "\"type\": \"point\", \"position\": [-3e30, 0, 0]")),
              "test.json: /lights/0/position: the point (-3e+30, 0, 0) lies beyond +-1e18");
    // Large but sane scenes still load: a 1e6 ground at 1e12.
    const Scene s = SceneLoader::parse(replaced(replaced(sceneJson(), "\"size\": 50", "\"size\": 1e6"),
                                                "{\"mesh\": \"ground\",",
                                                "{\"mesh\": \"ground\", \"position\": [1e12, 0, 0],"),
                                       "test.json");
    EXPECT_EQ(s.instances[0].position.x, 1e12f);
}
