// The sweep's plan without running it: which configurations a definition expands to, in
// which order, how shards split them, and what changes a sweep's identity. Expected values are
// counted by hand from the axes.
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/bottleneck/BottleneckStudy.h"
#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/sweep/SweepDefinition.h"
#include "bench/lib/sweep/SweepJob.h"
#include "core/Error.h"
#include "scenes/MeshGenerators.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

SweepDefinition twoByTwo() {
    SweepDefinition d;
    d.axes.techniques = {"none", "shadowmap:resolution=256,512"};
    d.axes.instances = {"2", "4"};
    d.axes.submit = {"retained", "immediate"};
    d.repeat = 2;
    d.commonArgs = {"--frames", "3"};
    return d;
}

std::string argValue(const SweepGroup& g, const std::string& option) {
    for (size_t i = 0; i + 1 < g.args.size(); ++i)
        if (g.args[i] == option) return g.args[i + 1];
    return "";
}

} // namespace

TEST(SweepPlanTest, CartesianProductRoundsAndIndices) {
    const SweepPlan plan = twoByTwo().expand();
    // 2 submit x 2 instances = 4 groups (instances innermost); 3 techniques x 2 rounds = 6 rows each.
    ASSERT_EQ(plan.groups.size(), 4u);
    EXPECT_EQ(plan.configCount(), 24u);
    const char* order[][2] = {{"retained", "2"}, {"retained", "4"}, {"immediate", "2"}, {"immediate", "4"}};
    size_t next = 0;
    for (size_t g = 0; g < 4; ++g) {
        const SweepGroup& group = plan.groups[g];
        EXPECT_EQ(argValue(group, "--submit"), order[g][0]);
        EXPECT_EQ(argValue(group, "--instances"), order[g][1]);
        ASSERT_EQ(group.rows.size(), 6u);
        const char* techniques[] = {"none", "shadowmap:resolution=256", "shadowmap:resolution=512"};
        for (size_t i = 0; i < 6; ++i) {
            EXPECT_EQ(group.rows[i].index, next++) << "indices run in execution order";
            EXPECT_EQ(group.rows[i].round, int(i / 3) + 1);
            EXPECT_EQ(group.rows[i].technique, techniques[i % 3]) << "baseline first in every round";
        }
    }
}

TEST(SweepPlanTest, ShardsPartitionTheGroupsRoundRobin) {
    const SweepPlan plan = twoByTwo().expand();
    std::set<size_t> seen;
    for (int s = 1; s <= 3; ++s)
        for (const SweepGroup* g : plan.shard(s, 3)) {
            EXPECT_EQ(int(g->index % 3) + 1, s);
            EXPECT_TRUE(seen.insert(g->index).second) << "group " << g->index << " in two shards";
        }
    EXPECT_EQ(seen.size(), 4u) << "every group in some shard";
    EXPECT_TRUE(plan.shard(5, 5).empty()) << "more shards than groups: some are empty";
    EXPECT_EQ(parseShard("2/7"), std::make_pair(2, 7));
    for (const char* bad : {"0/2", "3/2", "2", "a/b", "1/2/3", "2/0", "-1/2"})
        EXPECT_THROW(parseShard(bad), Error) << bad;
}

TEST(SweepPlanTest, IdentityChangesWithTheDefinitionOnly) {
    const std::string id = twoByTwo().expand().id();
    EXPECT_EQ(twoByTwo().expand().id(), id) << "deterministic";
    SweepDefinition frames = twoByTwo();
    frames.commonArgs = {"--frames", "4"};
    SweepDefinition rounds = twoByTwo();
    rounds.repeat = 3;
    SweepDefinition order = twoByTwo();
    order.axes.instances = {"4", "2"};
    for (const SweepDefinition* d : {&frames, &rounds, &order}) EXPECT_NE(d->expand().id(), id);
    SweepDefinition renamed = twoByTwo();
    renamed.name = "other";
    EXPECT_EQ(renamed.expand().id(), id) << "the name labels rows; it does not change what is measured";
}

TEST(SweepPlanTest, PropertyListsAndDefinitionFiles) {
    EXPECT_EQ(
        SweepDefinition::expandTechnique("shadowmap:resolution=512,1024:pcf=1,3"),
        (std::vector<std::string>{"shadowmap:resolution=512:pcf=1", "shadowmap:resolution=512:pcf=3",
                                  "shadowmap:resolution=1024:pcf=1", "shadowmap:resolution=1024:pcf=3"}));
    EXPECT_EQ(SweepDefinition::expandTechnique("none"), std::vector<std::string>{"none"});
    EXPECT_THROW(SweepDefinition::splitList("a,,b", "--scene"), Error);

    const std::string dir = test::freshDir("sweep-plan");
    const std::string file = dir + "/d.json";
    std::ofstream(file) << R"({"techniques": [{"name": "shadowmap", "properties": {"pcf": [1, 3]}}],
                              "scale": [0.5, 10], "repeat": 2, "frames": 7})";
    const SweepDefinition d = SweepDefinition::fromJsonFile(file);
    EXPECT_EQ(d.name, "d");
    EXPECT_EQ(d.axes.techniques, std::vector<std::string>{"shadowmap:pcf=1,3"});
    EXPECT_EQ(d.axes.scale, (std::vector<std::string>{"0.5", "10"}));
    EXPECT_EQ(d.commonArgs, (std::vector<std::string>{"--frames", "7"}));
    EXPECT_EQ(d.expand().configCount(), 2u * 2u * 2u); // 2 scales x 2 pcf x 2 rounds

    std::ofstream(file) << R"({"techniques": ["none"], "scael": [1]})";
    try {
        SweepDefinition::fromJsonFile(file);
        FAIL() << "typo accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/scael: unknown key"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    }
    SweepDefinition twice;
    twice.axes.techniques = {"none", "none"};
    EXPECT_THROW(twice.expand(), Error);
}

TEST(SweepPlanTest, BottleneckPerturbationsChangeOneThingEach) {
    SweepDefinition base;
    base.axes.techniques = {"none"};
    base.axes.scenes = {"aircraft"};
    base.axes.instances = {"10"};
    base.axes.size = {"512x256"};
    base.axes.scale = {"2"};
    const SweepPlan plan = BottleneckStudy::plan(base, true, {"aircraft"});
    ASSERT_EQ(plan.groups.size(), 9u);
    auto tag = [](const SweepGroup& g) { return g.tags.front().second; };
    const SweepGroup& baseline = plan.groups[0];
    EXPECT_EQ(tag(baseline), "baseline");
    // Each perturbation: the options it changes, to the values computed by hand from the base.
    const std::vector<std::tuple<std::string, std::string, std::string>> expected = {
        {"submit_immediate", "--submit", "immediate"}, {"scale_x10_near", "--scale", "20.0000"},
        {"scale_x0.01", "--scale", "0.0200"},          {"size_half", "--size", "256x128"},
        {"size_double", "--size", "1024x512"},         {"tess_half", "--tess-factor", "0.5000"},
        {"tess_double", "--tess-factor", "2.0000"}};
    for (size_t i = 0; i < expected.size(); ++i) {
        const SweepGroup& g = plan.groups[i + 1];
        const auto& [name, option, value] = expected[i];
        EXPECT_EQ(tag(g), name);
        EXPECT_EQ(argValue(g, option), value) << name;
        size_t differing = 0;
        for (const char* o : {"--submit", "--scale", "--size", "--tess-factor", "--camera", "--instances"})
            differing += argValue(g, o) != argValue(baseline, o);
        EXPECT_EQ(differing, name == "scale_x10_near" ? 2u : 1u) << name << ": only its own knob moves";
        EXPECT_TRUE(g.env.empty()) << name;
    }
    EXPECT_EQ(argValue(plan.groups[2], "--camera"), "near");
    const SweepGroup& noRast = plan.groups[8];
    EXPECT_EQ(tag(noRast), "lp_no_rast");
    EXPECT_EQ(noRast.env, (KeyValues{{"LP_NO_RAST", "1"}}));
    EXPECT_EQ(noRast.args, baseline.args);
    // Off llvmpipe, and for scenes without a 'near' camera, those runs are left out.
    EXPECT_EQ(BottleneckStudy::plan(base, false, {}).groups.size(), 7u);
    // An immediate base switches to retained instead.
    base.axes.submit = {"immediate"};
    EXPECT_EQ(tag(BottleneckStudy::plan(base, false, {}).groups[1]), "submit_retained");
}

TEST(SweepPlanTest, WorkerProtocolRoundTrips) {
    auto done = WorkerMessage::parse(WorkerMessage::done(17, 12.5));
    ASSERT_TRUE(done);
    EXPECT_EQ(done->kind, WorkerMessage::Kind::Done);
    EXPECT_EQ(done->index, 17u);
    EXPECT_DOUBLE_EQ(done->wallMs, 12.5);
    auto failed = WorkerMessage::parse(WorkerMessage::failed(3, 2, "bad\nthing: here"));
    ASSERT_TRUE(failed);
    EXPECT_EQ(failed->exitCode, 2);
    EXPECT_EQ(failed->message, "bad thing: here") << "one line";
    EXPECT_FALSE(WorkerMessage::parse("backend egl-surfaceless"));
    EXPECT_FALSE(WorkerMessage::parse("@sb nonsense 1"));
    EXPECT_EQ(ProgressBar::formatDuration(59.4), "59s");
    EXPECT_EQ(ProgressBar::formatDuration(185), "3m05s");
    EXPECT_EQ(ProgressBar::formatDuration(3725), "1h02m");
}

TEST(SweepPlanTest, TessellationFactorScalesEveryGeneratorButThePlane) {
    // aircraft: tessellation 16 -> 8 and 32; the ground plane keeps 16 (2 * 16^2 = 512 triangles).
    // MeshGenerators::aircraft has 2624 triangles at 16 (its header).
    SceneOptions o;
    o.instances = 1;
    const Scene base = SceneLoader::load("aircraft", o);
    ASSERT_EQ(base.totalTriangles(), 2624u + 512u);
    o.tessellationFactor = 0.5f;
    const Scene half = SceneLoader::load("aircraft", o);
    o.tessellationFactor = 2.0f;
    const Scene twice = SceneLoader::load("aircraft", o);
    EXPECT_EQ(half.meshes[1].triangleCount(), 512u);
    EXPECT_EQ(twice.meshes[1].triangleCount(), 512u);
    EXPECT_LT(half.meshes[0].triangleCount(), base.meshes[0].triangleCount() / 3);
    EXPECT_GT(twice.meshes[0].triangleCount(), base.meshes[0].triangleCount() * 3);
    // Clamped at the generator's minimum rather than rejected: a sphere (minimum 3) at factor 0.05.
    SceneOptions tiny;
    tiny.tessellationFactor = 0.05f;
    const Scene sphere = SceneLoader::load("sphere_plane", tiny);
    EXPECT_EQ(sphere.meshes[0].triangleCount(), MeshGenerators::sphere(3).triangleCount());
}
