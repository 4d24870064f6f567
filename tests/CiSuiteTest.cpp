// The perf gate's suite file (bench/lib/gate/CiSuite.h): the committed suite covers every technique of the
// registry, -t auto and a scene in motion, and a wrong suite is refused naming the file and the JSON path.
#include <set>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/gate/CiSuite.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

TEST(CiSuiteTest, CommittedSuiteRunsEveryTechniqueAndEveryBound) {
    const CiSuite s = CiSuite::load(std::string(SB_SOURCE_DIR) + "/results/ci/suite.json");
    std::set<std::string> techniques, bounds;
    for (const CiConfig& c : s.configs) {
        bounds.insert(c.bound);
        for (size_t i = 0; i + 1 < c.args.size(); ++i)
            if (c.args[i] == "-t") techniques.insert(c.args[i + 1].substr(0, c.args[i + 1].find(':')));
    }
    for (const std::string& t : TechniqueRegistry::names())
        EXPECT_TRUE(techniques.count(t)) << "technique " << t << " is not in results/ci/suite.json";
    EXPECT_TRUE(techniques.count("auto")) << "-t auto is not in results/ci/suite.json";
    bool moving = false; // a scene in motion: the per-frame work a static frame hides
    for (const CiConfig& c : s.configs)
        for (size_t i = 0; i + 1 < c.args.size(); ++i)
            moving = moving || (c.args[i] == "--scene" && c.args[i + 1] == "aircraft_day");
    EXPECT_TRUE(moving) << "no configuration of results/ci/suite.json moves (aircraft_day)";
    EXPECT_EQ(bounds, (std::set<std::string>{"balanced", "cpu", "fill", "vertex"}));
    EXPECT_FALSE(s.instructions.configs.empty());
    EXPECT_FALSE(s.wall.configs.empty());
}

void expectRefused(const std::string& text, const std::string& needle) {
    const std::string dir = test::freshTestDir("cisuite");
    const std::string path = dir + "/suite.json";
    test::writeFile(path, text);
    try {
        CiSuite::load(path);
        ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(CiSuiteTest, WrongSuitesAreRefusedNamingWhere) {
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none"]},
                                               {"name": "a", "args": ["-t", "none"]}]})",
                  "'a' is given twice");
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none", "-t", "volume"]}]})",
                  "exactly one technique");
    expectRefused(R"({"name": "s", "configs": [{"name": "A b", "args": ["-t", "none"]}]})",
                  "/configs/0/name");
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none"]}],
                      "wall": {"configs": ["b"]}})",
                  "'b', which is not a configuration");
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "bound": "gpu", "args": ["-t", "none"]}]})",
                  "not one of cpu, vertex, fill, balanced");
    expectRefused(R"({"name": "s", "config": []})", "config");
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none"], "drivers": ["mesa-9"],
                                                "why": "w"}]})",
                  "/configs/0/drivers: \"mesa-9\" is not a driver of the driver table (system, mesa-25.0.7)");
    expectRefused(
        R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none"], "drivers": ["mesa-25.0.7"]}]})",
        "says why the others cannot run it");
    expectRefused(R"({"name": "s", "configs": [{"name": "a", "args": ["-t", "none"], "why": "w"}]})",
                  "no \"drivers\" name those that can");
}

// A configuration bound to a driver runs where every side's driver is one of its drivers; --driver-bound
// keeps only the bound ones; the committed suite's bound configurations each name a driver of the table
// and say why.
TEST(CiSuiteTest, DriverBoundConfigurationsRunOnTheirDriversOnly) {
    const std::string path = test::freshTestDir("cisuite") + "/suite.json";
    test::writeFile(path, R"({"name": "s", "configs": [
        {"name": "a", "args": ["-t", "none"]},
        {"name": "rt", "args": ["--api", "vulkan", "-t", "none"], "drivers": ["mesa-25.0.7"],
         "why": "VK_KHR_ray_query: the system's lavapipe lacks it"}],
        "instructions": {"configs": ["a", "rt"]}})");
    const CiSuite s = CiSuite::load(path);
    auto names = [](const std::vector<const CiConfig*>& configs) {
        std::vector<std::string> out;
        for (const CiConfig* c : configs) out.push_back(c->name);
        return out;
    };
    using V = std::vector<std::string>;
    EXPECT_EQ(names(s.selectOn({}, {}, {"system"}, false)), V{"a"});
    EXPECT_EQ(names(s.selectOn({}, {}, {"mesa-25.0.7"}, false)), (V{"a", "rt"}));
    EXPECT_EQ(names(s.selectOn(s.instructions, {}, {"mesa-25.0.7"}, true)), V{"rt"});
    EXPECT_EQ(names(s.selectOn({}, {}, {"system", "mesa-25.0.7"}, false)), V{"a"}); // an A/B of the two
    EXPECT_TRUE(s.selectOn({}, {}, {"system"}, true).empty());
    EXPECT_EQ(s.config("rt").notRunReason(),
              "runs on mesa-25.0.7 only: VK_KHR_ray_query: the system's lavapipe lacks it");

    const CiSuite committed = CiSuite::load(std::string(SB_SOURCE_DIR) + "/results/ci/suite.json");
    for (const CiConfig& c : committed.configs)
        if (!c.drivers.empty()) {
            EXPECT_FALSE(c.why.empty()) << c.name;
            EXPECT_FALSE(c.runsOn("system")) << c.name << ": bound to drivers that include the system's";
        }
}

} // namespace
