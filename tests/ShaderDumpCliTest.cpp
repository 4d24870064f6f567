// bench --dump-shaders (gl/ProgramCache.h has the layout of the directory). The permutation test
// (ShaderPermutationsGLTest) walks every permutation through the same dump; this one pins the option.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;

namespace {

// bench --dump-shaders end to end: the file of the lighting program with pcf=3 holds the assembled
// source (version line, the selected defines, include bodies expanded), and glslang accepts it; a
// directory that cannot be created is the user's input (exit code 2).
TEST(DumpShaders, WritesTheAssembledStages) {
    ASSERT_EQ(test::runCommand("command -v glslangValidator").exitCode, 0)
        << "glslangValidator not found: install the Debian package `glslang-tools` (scripts/install-deps.sh)";
    const std::string dir = test::freshTestDir("dump");
    auto r = test::runCommand(std::string(SB_BENCH_BINARY) +
                              " -t shadowmap:pcf=3 --scene sphere_plane --frames 1 --warmup 0 --size 32x32 "
                              "--no-timer-check -q --dump-shaders " +
                              dir);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string program = dir + "/shadowmap/common-scene.vert+shadowmap-lighting.frag/";
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) found.push_back(entry.path().string());
    const std::string fragment =
        program + "HW_COMPARE,LIGHT_COUNT,PCF_SIZE=3,SB_AMBIENT=vec3(0.15),SB_LIGHT_COLORS=#53566dcb9c73b8ff,"
                  "SB_LIGHT_CONES=#45f3d0dc922a31db,SB_POSITIONAL_LIGHTS=0u,SB_RANGED_LIGHTS=0u,"
                  "SB_SPOT_LIGHTS=0u,SB_STATIC_LIGHTS,SHADOW_MAP/fragment.frag";
    ASSERT_TRUE(std::filesystem::exists(fragment)) << ::testing::PrintToString(found);
    const std::string text = test::readFile(fragment);
    EXPECT_EQ(text.rfind("#version 450 compatibility\n", 0), 0u);
    EXPECT_NE(text.find("#define PCF_SIZE 3\n"), std::string::npos);
    // The key hashes the light constants (shading/Defines.h); the dumped source spells them out.
    EXPECT_NE(text.find("#define SB_LIGHT_COLORS vec4[4](vec4("), std::string::npos);
    EXPECT_NE(text.find("#define SB_FRAGMENT_SHADER 1\n"), std::string::npos);
    EXPECT_EQ(text.find("#include"), std::string::npos) << "includes must be expanded";
    EXPECT_EQ(test::runCommand("glslangValidator '" + fragment + "'").exitCode, 0);
    // The depth pass, the lighting pass (two stages each); the timer check is off.
    EXPECT_EQ(found.size(), 4u) << ::testing::PrintToString(found);

    auto bad = test::runCommand(std::string(SB_BENCH_BINARY) +
                                " -t none --frames 1 --warmup 0 --size 32x32 --no-timer-check -q "
                                "--dump-shaders /proc/no-such-dir");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("/proc/no-such-dir"), std::string::npos) << bad.output;
}

} // namespace
