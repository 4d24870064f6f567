// The depth passes of the shadow-map family on Vulkan are pipelines without a fragment stage
// (techniques/vulkan/VulkanDepthMapSet.h, kDepthFragment): they write depth only, so a driver need not
// launch any fragment work for them. Observed through `--dump-shaders` (shading/ShaderDump.h), which writes
// every stage a technique's compile hands to the compiler, one folder per program: a depth program's folder
// must hold its vertex (and geometry) stage and no fragment stage. (The GL forms keep the empty
// shaders/common/depth.frag: on Mesa a GL program without it draws exactly the same work, as that file
// says, so there is nothing to pin there.)
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;

namespace {

/// Program folder ("<technique>/<program>") -> the stage files dumped under it (every permutation).
using Programs = std::map<std::string, std::set<std::string>>;

/// Runs one frame of `techniques` at 32x32 with --dump-shaders and returns the depth programs it compiled
/// (those whose program name holds "depth"), with their stages.
Programs dumpedDepthPrograms(const std::string& api, const std::string& scene,
                             const std::string& techniques) {
    const std::string dir = test::freshTestDir("depth-only-" + api);
    const test::CommandResult r = test::runCommand(
        std::string(SB_BENCH_BINARY) + " --api " + api + " " + techniques + " --scene " + scene +
        " --frames 1 --warmup 0 --size 32x32 --no-timer-check -q --dump-shaders " + dir);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    Programs programs;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        // DIR/<label>/<program>/<permutation>/<stage>.<ext>
        const std::filesystem::path relative = std::filesystem::relative(entry.path(), dir);
        auto part = relative.begin();
        const std::string label = (part++)->string();
        const std::string program = (part++)->string();
        if (program.find("depth") == std::string::npos) continue;
        programs[label + "/" + program].insert(entry.path().stem().string());
    }
    return programs;
}

/// Every depth program holds a vertex stage and no fragment stage.
void expectNoFragmentStage(const Programs& programs) {
    for (const auto& [program, stages] : programs) {
        EXPECT_TRUE(stages.count("vertex")) << program;
        EXPECT_FALSE(stages.count("fragment")) << program << ": " << ::testing::PrintToString(stages);
    }
}

// The directional and spot members on the aircraft scene, the omnidirectional ones on point_light (every
// depth pipeline they can build is compiled up front: cubemap's layered one with its geometry stage,
// paraboloid's flat, plain and split ones).
const char* const kFlat = "-t shadowmap -t pcss -t cascaded";
const char* const kOmni = "-t cubemap -t cubemap:layered=false -t paraboloid";

TEST(DepthOnlyPipelines, VulkanDepthPassesHaveNoFragmentStage) {
    Programs programs = dumpedDepthPrograms("vulkan", "aircraft", kFlat);
    const Programs omni = dumpedDepthPrograms("vulkan", "point_light", kOmni);
    programs.insert(omni.begin(), omni.end());
    // shadowmap, pcss, cascaded: depth.vert; cubemap: depth.vert and the layered cube_depth.vert+geom;
    // paraboloid: depth.vert, paraboloid_depth.vert and the split cube_depth.vert+paraboloid_split.geom.
    EXPECT_EQ(programs.size(), 8u) << ::testing::PrintToString(programs);
    expectNoFragmentStage(programs);
}

} // namespace
