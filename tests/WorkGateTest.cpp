// Layer A of the perf gate (bench/lib/gate/WorkGate.h) on tables written by hand: which counts it compares,
// what it calls an increase, and what it refuses to compare. Every expected number is in the table.
#include <gtest/gtest.h>

#include "bench/lib/gate/WorkGate.h"

using namespace sb;

namespace {

const std::vector<std::string> kHeader = {"ci_config",
                                          "status",
                                          "renderer",
                                          "gl_version",
                                          "work_depth_fragments",
                                          "load_fragments",
                                          "counter_draw_calls",
                                          "counter_rays_per_second_per_thread",
                                          "wall_ms_median"};

CsvTable table(std::vector<std::vector<std::string>> rows) {
    return {kHeader, std::move(rows)};
}

std::vector<std::string> row(const std::string& config, const std::string& depth, const std::string& load,
                             const std::string& rate = "100", const std::string& wall = "5",
                             const std::string& renderer = "llvmpipe", const std::string& status = "ok") {
    return {config, status, renderer, "4.5 Mesa 22.3.6", depth, load, "11", rate, wall};
}

TEST(WorkGateTest, IdenticalWorkPassesWhateverTheTimes) {
    // Times and rates differ (5 vs 9 ms, 100 vs 300 rays/s): they are not work and must not count.
    const WorkComparison w =
        WorkGate::compare(table({row("a", "1000", "2000")}), table({row("a", "1000", "2000", "300", "9")}));
    EXPECT_TRUE(w.pass());
    EXPECT_EQ(w.configs, 1u);
    EXPECT_EQ(w.metrics, 3u); // depth fragments, load fragments, draw calls; not the rate, not the time
}

TEST(WorkGateTest, AnIncreaseFailsAndIsNamedWithItsPass) {
    const WorkComparison w =
        WorkGate::compare(table({row("a", "1000", "2000")}), table({row("a", "1120", "2120")}));
    EXPECT_FALSE(w.pass());
    ASSERT_EQ(w.increases.size(), 2u);
    EXPECT_EQ(w.increases[1].describe(), "a: depth_fragments 1000 -> 1120 (+12.0%)");
    EXPECT_EQ(w.increases[0].describe(), "a: load_fragments 2000 -> 2120 (+6.0%)");
}

TEST(WorkGateTest, ADecreasePassesAndIsReported) {
    const WorkComparison w =
        WorkGate::compare(table({row("a", "1000", "2000")}), table({row("a", "900", "2000")}));
    EXPECT_TRUE(w.pass());
    ASSERT_EQ(w.decreases.size(), 1u);
    EXPECT_EQ(w.decreases[0].describe(), "a: depth_fragments 1000 -> 900 (-10.0%)");
}

TEST(WorkGateTest, APassThatAppearsIsAnIncreaseFromZero) {
    const WorkComparison w =
        WorkGate::compare(table({row("a", "", "2000")}), table({row("a", "50", "2000")}));
    ASSERT_EQ(w.increases.size(), 1u);
    EXPECT_EQ(w.increases[0].describe(), "a: depth_fragments 0 -> 50 (new)");
}

TEST(WorkGateTest, AConfigurationThatVanishedOrFailedFails) {
    const WorkComparison gone =
        WorkGate::compare(table({row("a", "1", "2"), row("b", "1", "2")}), table({row("a", "1", "2")}));
    EXPECT_FALSE(gone.pass());
    EXPECT_EQ(gone.onlyInBase, (std::vector<std::string>{"b"}));
    const WorkComparison failed = WorkGate::compare(table({row("a", "1", "2")}),
                                                    table({row("a", "", "", "", "", "llvmpipe", "failed")}));
    EXPECT_FALSE(failed.pass());
    const WorkComparison added =
        WorkGate::compare(table({row("a", "1", "2")}), table({row("a", "1", "2"), row("c", "1", "2")}));
    EXPECT_TRUE(added.pass()); // a new configuration is reported, not a failure
    EXPECT_EQ(added.onlyInHead, (std::vector<std::string>{"c"}));
}

TEST(WorkGateTest, AnotherRasteriserOrDisagreeingRoundsAreNotCompared) {
    const WorkComparison other =
        WorkGate::compare(table({row("a", "1", "2")}), table({row("a", "1", "2", "1", "1", "NVIDIA H200")}));
    EXPECT_FALSE(other.pass());
    ASSERT_EQ(other.notComparable.size(), 1u);
    EXPECT_NE(other.notComparable[0].find("another rasteriser"), std::string::npos);
    const WorkComparison rounds =
        WorkGate::compare(table({row("a", "1", "2"), row("a", "1", "3")}), table({row("a", "1", "2")}));
    EXPECT_FALSE(rounds.pass());
    ASSERT_EQ(rounds.notComparable.size(), 1u);
    EXPECT_NE(rounds.notComparable[0].find("not exact"), std::string::npos);
}

TEST(WorkGateTest, WithoutCiConfigRowsAreMatchedByTheirConfigurationColumns) {
    const CsvTable base{{"status", "technique", "instances", "renderer", "gl_version", "load_fragments"},
                        {{"ok", "none", "10", "r", "v", "100"}, {"ok", "none", "20", "r", "v", "200"}}};
    const CsvTable head{{"status", "technique", "instances", "renderer", "gl_version", "load_fragments"},
                        {{"ok", "none", "20", "r", "v", "200"}, {"ok", "none", "10", "r", "v", "150"}}};
    const WorkComparison w = WorkGate::compare(base, head);
    EXPECT_EQ(w.configs, 2u);
    ASSERT_EQ(w.increases.size(), 1u);
    EXPECT_NE(w.increases[0].config.find("instances=10"), std::string::npos);
    EXPECT_EQ(w.increases[0].base, 100.0);
    EXPECT_EQ(w.increases[0].head, 150.0);
}

} // namespace
