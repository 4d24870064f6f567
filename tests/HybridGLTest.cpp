// `hybrid` (techniques/hybrid/HybridGL.h): two techniques in one frame, each shading the instances
// of its role. The independent answer is each part rendered alone on the same harness: on the aircraft
// scene, a hybrid of occluder textures (self) and a shadow map (cast) must show, pixel for pixel, the
// occluder's visibility and colour on the aircraft and the shadow map's on the ground. Tolerance 0: each
// pixel is the same program on the same inputs as in its part's own frame, only the instances the other
// part shades are left out of the view passes. Judged on visible pixels away from the 1-px outline of
// the aircraft, where a pixel's winner in the depth test could change with the order of the draws.
// Also: the census shows both parts' passes with their draws counted from the scene; a role with no
// instance runs no pass and says why; every submission mode gives the same frame.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 256;

bool onGround(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-2f; // the aircraft scene's ground is y = 0, the aircraft above 2
}

/// Pixels whose 4 neighbours are on the same side (ground or aircraft, or background).
std::vector<bool> interior(const std::vector<glm::vec4>& world, int size) {
    auto kind = [&](int x, int y) {
        const glm::vec4& w = world[size_t(y) * size_t(size) + size_t(x)];
        return w.w == 0.0f ? 0 : onGround(w) ? 1 : 2;
    };
    std::vector<bool> out(world.size(), false);
    for (int y = 1; y + 1 < size; ++y)
        for (int x = 1; x + 1 < size; ++x) {
            const int k = kind(x, y);
            out[size_t(y) * size_t(size) + size_t(x)] = k != 0 && kind(x - 1, y) == k &&
                                                        kind(x + 1, y) == k && kind(x, y - 1) == k &&
                                                        kind(x, y + 1) == k;
        }
    return out;
}

std::unique_ptr<GlTechnique> make(const std::string& spec) {
    return TechniqueRegistry::create(TechniqueSpec::parse(spec));
}

size_t countInstances(const Scene& scene, bool casters) {
    size_t n = 0;
    for (const Instance& inst : scene.instances) n += inst.castsShadow == casters;
    return n;
}

const PassWork* findPass(const FrameLoads& loads, const std::string& name) {
    for (const auto& [pass, work] : loads.passes)
        if (pass == name) return &work;
    return nullptr;
}

} // namespace

TEST(Hybrid, EachPartShadesItsOwnInstancesAsItWouldAlone) {
    for (SubmitMode mode : kAllSubmitModes) {
        SCOPED_TRACE(submitModeName(mode));
        Harness h(test::quickConfig("aircraft", "mid", kSize, mode));
        auto occluder = make("occluder");
        auto shadowmap = make("shadowmap");
        auto hybrid = make("hybrid:self=occluder:cast=shadowmap");
        const test::RenderedFrame self = test::renderOnce(h, *occluder);
        const test::RenderedFrame cast = test::renderOnce(h, *shadowmap);
        const test::RenderedFrame both = test::renderOnce(h, *hybrid);
        const std::vector<bool> judged = interior(both.world, kSize);
        size_t ground = 0, aircraft = 0, groundShadowed = 0, aircraftShadowed = 0, visibilityDiffers = 0,
               colourDiffers = 0;
        for (size_t i = 0; i < both.world.size(); ++i) {
            if (!judged[i]) continue;
            const bool isGround = onGround(both.world[i]);
            const test::RenderedFrame& expected = isGround ? cast : self;
            (isGround ? ground : aircraft) += 1;
            if (expected.visibility[4 * i] < 0.5f) (isGround ? groundShadowed : aircraftShadowed) += 1;
            visibilityDiffers += both.visibility[4 * i] != expected.visibility[4 * i];
            for (int c = 0; c < 3; ++c)
                colourDiffers += both.colour[4 * i + size_t(c)] != expected.colour[4 * i + size_t(c)];
        }
        EXPECT_EQ(visibilityDiffers, 0u);
        std::printf("[ hybrid   ] %s: %zu ground pixels (%zu shadowed), %zu aircraft pixels (%zu shadowed), "
                    "%zu visibility and %zu colour values differ\n",
                    submitModeName(mode), ground, groundShadowed, aircraft, aircraftShadowed,
                    visibilityDiffers, colourDiffers);
        EXPECT_EQ(colourDiffers, 0u);
        // Not vacuous: both kinds of pixel are there, with shadows on the ground (the map's) and on the
        // aircraft (the occluder textures' self-shadowing), and the parts differ where it matters: the
        // occluder alone leaves the ground lit.
        EXPECT_GT(ground, 5000u);
        EXPECT_GT(aircraft, 500u);
        EXPECT_GT(groundShadowed, 1000u);
        EXPECT_GT(aircraftShadowed, 20u);
        size_t occluderLitWhereMapShadows = 0;
        for (size_t i = 0; i < both.world.size(); ++i)
            occluderLitWhereMapShadows += judged[i] && onGround(both.world[i]) &&
                                          cast.visibility[4 * i] < 0.5f && self.visibility[4 * i] > 0.5f;
        EXPECT_GT(occluderLitWhereMapShadows, 300u);
    }
}

TEST(Hybrid, TheCensusShowsBothPartsPassesWithTheirDraws) {
    Harness h(test::quickConfig("aircraft", "mid", kSize));
    auto hybrid = make("hybrid:self=occluder:cast=shadowmap");
    h.prepare(*hybrid);
    const FrameLoads loads = h.measureLoads(*hybrid);
    std::vector<std::string> names;
    for (const auto& [pass, work] : loads.passes) names.push_back(pass);
    EXPECT_EQ(names, (std::vector<std::string>{"self_lighting", "cast_depth", "cast_lighting"}));
    const size_t casters = countInstances(h.scene(), true), others = countInstances(h.scene(), false);
    ASSERT_GT(casters, 10u);
    ASSERT_EQ(others, 1u); // the ground
    const PassWork* selfLighting = findPass(loads, "self_lighting");
    const PassWork* castDepth = findPass(loads, "cast_depth");
    const PassWork* castLighting = findPass(loads, "cast_lighting");
    ASSERT_TRUE(selfLighting && castDepth && castLighting);
    // Retained mode: one draw per instance. The occluder shades every aircraft and nothing else; the
    // shadow map's view pass draws the ground alone; its depth pass draws every caster but those whose
    // shadow cannot reach the view from mid (the map is fitted to all casters; its counter says how
    // many it left out, some but not most here).
    const size_t culled = size_t(test::counter(hybrid->counters(), "cast_casters_culled"));
    EXPECT_GT(culled, 0u);
    EXPECT_LT(culled, casters / 2);
    EXPECT_EQ(selfLighting->submitted.drawCalls, casters);
    EXPECT_EQ(castLighting->submitted.drawCalls, others);
    EXPECT_EQ(castDepth->submitted.drawCalls, casters - culled);
    EXPECT_EQ(loads.submitted.drawCalls, 2 * casters - culled + others);
    EXPECT_EQ(test::counter(hybrid->counters(), "draw_calls"), double(2 * casters - culled + others));
    EXPECT_EQ(test::counter(hybrid->counters(), "self_draw_calls"), double(casters));
    EXPECT_GT(test::counter(hybrid->counters(), "cast_shadow_map_texels"), 0.0);
    // The permutation names each part's programs under its role.
    // The permutation names each part's programs under its role: the occluder's plane count under self,
    // the shadow map's lookup under cast.
    EXPECT_NE(hybrid->permutationKey().find("self:LIGHT_COUNT,PLANE_COUNT="), std::string::npos)
        << hybrid->permutationKey();
    EXPECT_NE(hybrid->permutationKey().find("cast:HW_COMPARE,"), std::string::npos)
        << hybrid->permutationKey();
}

TEST(Hybrid, ARoleWithNoInstanceRunsNoPassAndSaysWhy) {
    // Every instance casts: the cast part has no receiver to shade.
    const std::string path = test::freshTestDir("hybrid_roles") + "/all_cast.json";
    test::writeFile(path, R"({"name": "all_cast",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 1, "tessellation": 16},
             {"name": "floor", "generator": "plane", "size": 10, "tessellation": 2}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0]}, {"mesh": "ball", "position": [0, 2, 0]}],
  "lights": [{"type": "directional", "direction": [0.2, -1, 0.1]}],
  "cameras": [{"name": "view", "eye": [0, 8, 8], "target": [0, 0, 0], "fov": 45, "near": 0.5, "far": 50}]})");
    Harness h(test::quickConfig(path, "view", 64));
    auto hybrid = make("hybrid:self=shadowmap:cast=planar");
    h.prepare(*hybrid);
    const FrameLoads loads = h.measureLoads(*hybrid);
    std::vector<std::string> ran;
    for (const auto& [pass, work] : loads.passes) ran.push_back(pass);
    EXPECT_EQ(ran, (std::vector<std::string>{"self_depth", "self_lighting"}));
    ASSERT_EQ(loads.skipped.size(), 2u);
    EXPECT_EQ(loads.skipped[0].first, "cast_lighting");
    EXPECT_EQ(loads.skipped[1].first, "cast_shadows");
    EXPECT_NE(loads.skipped[0].second.find("every instance casts a shadow"), std::string::npos);
    EXPECT_EQ(findPass(loads, "self_lighting")->submitted.drawCalls,
              2u); // the floor casts, so self shades it
}

TEST(Hybrid, PassesEffectsAndBadRolesFollowTheProperties) {
    auto hybrid = make("hybrid:self=volume:cast=projective");
    EXPECT_EQ(hybrid->info().passes,
              (std::vector<std::string>{"self_ambient", "self_mark", "self_lighting", "cast_texture",
                                        "cast_blur", "cast_lighting"}));
    EXPECT_EQ(hybrid->info().viewPasses,
              (std::vector<std::string>{"self_ambient", "self_lighting", "cast_lighting"}));
    // volume: hard, self, non-planar, multi; projective: hard, non-planar, multi: self-shadowing comes
    // from the self part alone, the rest from both.
    EXPECT_EQ(effectMaskToString(hybrid->info().effects),
              "hard_shadows+self_shadowing+non_planar_receivers+multiple_lights");
    EXPECT_EQ(effectMaskToString(make("hybrid:self=planar:cast=shadowmap")->info().effects),
              "hard_shadows+multiple_lights");
    EXPECT_EQ(effectMaskToString(make("hybrid:self=occluder:cast=blob")->info().effects),
              "self_shadowing+multiple_lights");
    try {
        make("hybrid:cast=reference");
        FAIL() << "the reference is the judge, not a part";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(std::string(e.what()).find("cast"), std::string::npos) << e.what();
    }
}
