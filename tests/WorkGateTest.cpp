// Layer A of the perf gate (bench/lib/gate/WorkGate.h) on tables written by hand: which counts it compares,
// what it calls an increase, and what it refuses to compare. Every expected number is in the table.
#include <gtest/gtest.h>

#include "bench/lib/gate/Fingerprint.h"
#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/WorkColumns.h"
#include "bench/lib/gate/WorkGate.h"
#include "bench/lib/output/ResultColumns.h"

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

// A count on one side only is not read as 0 (a vanished pass would then be a passing decrease): both
// directions fail, and the text says which side lacks it.
TEST(WorkGateTest, ACountOnOneSideOnlyFailsEitherWay) {
    const WorkComparison appeared =
        WorkGate::compare(table({row("a", "", "2000")}), table({row("a", "50", "2000")}));
    EXPECT_FALSE(appeared.pass());
    ASSERT_EQ(appeared.missing.size(), 1u);
    EXPECT_EQ(appeared.missing[0].describe(), "a: depth_fragments absent -> 50 (new)");
    const WorkComparison vanished =
        WorkGate::compare(table({row("a", "50", "2000")}), table({row("a", "", "2000")}));
    EXPECT_FALSE(vanished.pass());
    ASSERT_EQ(vanished.missing.size(), 1u);
    EXPECT_EQ(vanished.missing[0].describe(), "a: depth_fragments 50 -> absent");
    EXPECT_TRUE(vanished.decreases.empty());
}

TEST(WorkGateTest, AConfigurationOnOneSideOnlyOrFailedFails) {
    const WorkComparison gone =
        WorkGate::compare(table({row("a", "1", "2"), row("b", "1", "2")}), table({row("a", "1", "2")}));
    EXPECT_FALSE(gone.pass());
    EXPECT_EQ(gone.onlyInBase, (std::vector<std::string>{"b"}));
    EXPECT_EQ(gone.cell("b").verdict, "FAIL");
    EXPECT_EQ(gone.cell("b").summary, "not compared: only in the base");
    const WorkComparison failed = WorkGate::compare(table({row("a", "1", "2")}),
                                                    table({row("a", "", "", "", "", "llvmpipe", "failed")}));
    EXPECT_FALSE(failed.pass());
    // A configuration missing from the baseline was never compared: it fails too (add it with --update).
    const WorkComparison added =
        WorkGate::compare(table({row("a", "1", "2")}), table({row("a", "1", "2"), row("c", "1", "2")}));
    EXPECT_FALSE(added.pass());
    EXPECT_EQ(added.onlyInHead, (std::vector<std::string>{"c"}));
    EXPECT_EQ(added.cell("c").summary, "not compared: not in the base");
    EXPECT_EQ(added.cell("a").verdict, "PASS");
    // Unsupported on both sides: skipped and said so, never PASS; a table with no ok row at all fails.
    const auto unsupported = row("u", "", "", "", "", "llvmpipe", "unsupported");
    const WorkComparison skipped =
        WorkGate::compare(table({row("a", "1", "2"), unsupported}), table({row("a", "1", "2"), unsupported}));
    EXPECT_EQ(skipped.cell("u").verdict, "SKIPPED");
    EXPECT_TRUE(skipped.pass());
    const WorkComparison none = WorkGate::compare(table({unsupported}), table({unsupported}));
    EXPECT_FALSE(none.pass());
    EXPECT_EQ(WorkGate::layer(none, "baseline").verdict, "FAIL");
    EXPECT_EQ(none.problems.at(0), "base: none of its 1 rows has status ok");
}

TEST(WorkGateTest, DisagreeingRoundsAreNotCompared) {
    const WorkComparison rounds =
        WorkGate::compare(table({row("a", "1", "2"), row("a", "1", "3")}), table({row("a", "1", "2")}));
    EXPECT_FALSE(rounds.pass());
    ASSERT_EQ(rounds.notComparable.size(), 1u);
    EXPECT_NE(rounds.notComparable[0].find("not exact"), std::string::npos);
    EXPECT_EQ(rounds.cell("a").verdict, "FAIL");
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

// Which count is whose (bench/lib/gate/WorkColumns.h): every census family of the column table, by
// what its query counts. The submitter's counts and the primitives the draws assemble are the
// application's; shader invocations and the clipper's output are the driver's.
TEST(WorkGateTest, EveryWorkColumnIsTheApplicationsOrTheDrivers) {
    const std::vector<std::pair<std::string, WorkClass>> expected = {
        {"load_gl_calls", WorkClass::Application},
        {"load_primitives", WorkClass::Application},
        {"load_vertices", WorkClass::Driver},
        {"load_clipped_primitives", WorkClass::Driver},
        {"load_fragments", WorkClass::Driver},
        {"work_shadow_fill_gl_calls", WorkClass::Application}, // a pass name with an underscore
        {"work_depth_draws", WorkClass::Application},
        {"work_depth_triangles", WorkClass::Application},
        {"work_depth_primitives", WorkClass::Application},
        {"work_depth_vertices", WorkClass::Driver},
        {"work_depth_clipped_primitives", WorkClass::Driver},
        {"work_depth_fragments", WorkClass::Driver},
        {"counter_draw_calls", WorkClass::Application},
        {"counter_shadow_map_texels", WorkClass::Application},
        {"counter_casters_culled", WorkClass::Application},
        {"counter_rays_per_second_per_thread", WorkClass::None}, // a rate: time, not work
        {"counter_top_level_build_ms", WorkClass::None},         // a time (raytraced's build)
        {"counter_structure_bytes", WorkClass::Application},
        {"wall_ms_median", WorkClass::None},
        {"gl_version", WorkClass::None}};
    for (const auto& [column, cls] : expected) EXPECT_EQ(WorkColumns::classOf(column), cls) << column;
    // The column table (and docs/CSV.md through CsvDocTest) says the same of every work family.
    size_t families = 0;
    for (const ColumnInfo& c : ResultColumns::all()) {
        const std::string name(c.name), member = c.isFamily() ? col::member(name, "depth") : name;
        const WorkClass cls = WorkColumns::classOf(member);
        if (cls == WorkClass::None) continue;
        ++families;
        const std::string says = std::string(WorkColumns::name(cls)) + " work";
        EXPECT_NE(std::string(c.meaning).find(says), std::string::npos) << name << " should say: " << says;
    }
    EXPECT_EQ(families, 13u); // counter_<name>, load_* (5), work_<pass>_* (7)
}

// The driver A/B (the first "done when" of the two-driver work): two tables with two driver_versions.
// The application's work equal and the fragments different: a pass, with each driver-work difference
// reported with both values and the ratio, and a cell that says so instead of PASS. Draws different: a
// failure naming the column, whichever way it moved.
CsvTable driverTable(const std::string& version, const std::string& draws, const std::string& fragments) {
    return {
        {"ci_config", "status", "api", "renderer", "gl_version", "gl_vendor", "driver", "driver_version",
         "work_depth_draws", "work_depth_fragments", "load_fragments"},
        {{"shadowmap_vulkan", "ok", "vulkan", "llvmpipe (LLVM 15.0.6, 256 bits)", "", "",
          version == "25.0.7" ? "mesa-25.0.7" : "system", "Mesa " + version, draws, fragments, fragments}}};
}

TEST(WorkGateTest, AcrossDriversApplicationWorkIsJudgedAndDriverWorkReported) {
    const CsvTable base = driverTable("22.3.6", "40", "2884128");
    const WorkComparison same = WorkGate::compare(base, driverTable("25.0.7", "40", "0"));
    EXPECT_TRUE(same.pass());
    EXPECT_EQ(same.configs, 1u);
    EXPECT_EQ(same.acrossDrivers, 1u);
    EXPECT_TRUE(same.decreases.empty()); // not judged as a decrease on one driver
    ASSERT_EQ(same.driverDifferences.size(), 2u);
    EXPECT_EQ(same.driverDifferences[1].describeRatio(),
              "shadowmap_vulkan: depth_fragments 2884128 -> 0 (head/base 0.000)");
    EXPECT_EQ(same.cell("shadowmap_vulkan").verdict, "EXPLAINED");
    const GateLayer layer = WorkGate::layer(same, "base");
    EXPECT_EQ(layer.verdict, "PASS");
    const auto has = [&](const GateLayer& l, const std::string& text) {
        return std::any_of(l.details.begin(), l.details.end(),
                           [&](const std::string& d) { return d.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(
        has(layer, "driver work (explained, not judged): shadowmap_vulkan: depth_fragments 2884128 -> 0"));
    EXPECT_TRUE(has(layer, "head on llvmpipe (LLVM 15.0.6, 256 bits), Mesa 25.0.7"));

    for (const std::string draws : {"41", "39"}) {
        const WorkComparison other = WorkGate::compare(base, driverTable("25.0.7", draws, "0"));
        EXPECT_FALSE(other.pass()) << draws;
        ASSERT_EQ(other.applicationChanges.size(), 1u) << draws;
        EXPECT_EQ(other.applicationChanges[0].metric, "depth_draws");
        EXPECT_EQ(other.cell("shadowmap_vulkan").verdict, "FAIL");
        EXPECT_TRUE(
            has(WorkGate::layer(other, "base"),
                "application work differs across drivers: shadowmap_vulkan: depth_draws 40 -> " + draws));
    }
    // The same driver on both sides keeps the exact rule: more fragments fail.
    EXPECT_FALSE(WorkGate::compare(base, driverTable("22.3.6", "40", "2884129")).pass());
}

// Rows without the driver columns: GL rows carry the version in gl_version, Vulkan rows (gl_version
// empty, the renderer string the same on both Mesas) only in gl_vendor. Before, two Vulkan rows of
// 22.3.6 and 25.0.7 were compared as one driver and the lost fragments passed as a decrease.
TEST(WorkGateTest, VulkanRowsAreMatchedOnTheirVendorsMesaVersion) {
    auto vulkan = [](const std::string& vendor, const std::string& fragments) {
        return CsvTable{
            {"ci_config", "status", "renderer", "gl_version", "gl_vendor", "work_depth_fragments"},
            {{"shadowmap_vulkan", "ok", "llvmpipe (LLVM 15.0.6, 256 bits)", "", vendor, fragments}}};
    };
    const WorkComparison w = WorkGate::compare(vulkan("llvmpipe Mesa 22.3.6 (LLVM 15.0.6)", "59072"),
                                               vulkan("llvmpipe Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)", "0"));
    EXPECT_EQ(w.acrossDrivers, 1u);
    EXPECT_TRUE(w.decreases.empty());
    ASSERT_EQ(w.driverDifferences.size(), 1u);
    EXPECT_EQ(w.driverDifferences[0].describeRatio(),
              "shadowmap_vulkan: depth_fragments 59072 -> 0 (head/base 0.000)");
    // Another rasteriser altogether is another driver too: its application work is still compared.
    const WorkComparison gpu =
        WorkGate::compare(table({row("a", "1", "2")}), table({row("a", "1", "2", "1", "1", "NVIDIA H200")}));
    EXPECT_TRUE(gpu.pass());
    EXPECT_EQ(gpu.acrossDrivers, 1u);
    EXPECT_EQ(gpu.cell("a").summary, "exact on both drivers");
}

// The fingerprint carries the driver version on both APIs: a Vulkan row's from its vendor string.
TEST(WorkGateTest, TheFingerprintNamesTheDriverOnBothApis) {
    const nlohmann::json v22 = {{"renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"},
                                {"gl_version", ""},
                                {"gl_vendor", "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"}};
    nlohmann::json v25 = v22;
    v25["gl_vendor"] = "llvmpipe Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)";
    const Fingerprint a = Fingerprint::capture(v22, "", {}), b = Fingerprint::capture(v25, "", {});
    EXPECT_EQ(a.mesaVersion, "22.3.6");
    EXPECT_EQ(b.mesaVersion, "25.0.7-2~bpo12+1");
    EXPECT_EQ(a.differences(b), (std::vector<std::string>{"mesa_version"}));
    // The driver table's columns are compared where both sides have them (older records lack them).
    nlohmann::json named = v22;
    named["driver"] = "/opt/mesa-dev";
    named["driver_version"] = "Mesa 22.3.6";
    const Fingerprint built = Fingerprint::capture(named, "", {});
    EXPECT_TRUE(a.differences(built).empty());
    named["driver"] = "system";
    EXPECT_EQ(Fingerprint::capture(named, "", {}).differences(built), (std::vector<std::string>{"driver"}));
    // A driver A/B may differ in the driver and the variables its sides set, nothing else: a side that
    // fell back to another backend (Mesa 25.0.7's EGL does not load under LD_BIND_NOW=1) is left over.
    Fingerprint osmesa = Fingerprint::capture(v25, "", {{"LD_LIBRARY_PATH", "/opt/mesa/lib"}});
    osmesa.backend = "osmesa";
    Fingerprint egl = Fingerprint::capture(v22, "", {});
    egl.backend = "egl-surfaceless";
    EXPECT_EQ(egl.differencesBesidesDriver(osmesa, {"LD_LIBRARY_PATH"}),
              (std::vector<std::string>{"backend"}));
    osmesa.backend = egl.backend;
    EXPECT_TRUE(egl.differencesBesidesDriver(osmesa, {"LD_LIBRARY_PATH"}).empty());
    EXPECT_EQ(egl.differencesBesidesDriver(osmesa, {}),
              (std::vector<std::string>{"environment.LD_LIBRARY_PATH"}));
}

// The gate's verdict: a NO VERDICT layer (it compared nothing) never hides a FAIL and never makes the
// gate PASS; a layer that declined (its instrument cannot judge here) is reported without failing.
TEST(WorkGateTest, NoVerdictNeverPassesTheGate) {
    auto report = [](std::vector<GateLayer> layers) {
        GateReport r;
        r.layers = std::move(layers);
        return r;
    };
    const GateLayer pass{"A", true, false, "PASS", {}}, fail{"A", true, false, "FAIL", {}},
        nothing{"A", true, false, "NO VERDICT", {}};
    GateLayer declined{"B", true, false, "NO VERDICT", {}};
    declined.declined = true;
    EXPECT_EQ(report({pass}).verdict(), "PASS");
    EXPECT_EQ(report({fail, nothing}).verdict(), "FAIL");
    EXPECT_EQ(report({nothing, fail}).verdict(), "FAIL");
    EXPECT_EQ(report({nothing}).verdict(), "FAIL");
    EXPECT_TRUE(report({nothing}).failed());
    EXPECT_EQ(report({pass, declined}).verdict(), "PASS");
    EXPECT_EQ(report({declined}).verdict(), "NO VERDICT");
    EXPECT_TRUE(report({declined}).failed());
    EXPECT_NE(report({declined}).markdown().find("this is not a pass"), std::string::npos);
    GateLayer advisoryFail = fail;
    advisoryFail.advisory = true;
    EXPECT_EQ(report({pass, advisoryFail}).verdict(), "PASS");
    EXPECT_EQ(report({advisoryFail}).verdict(), "NO VERDICT");
    // The table never shows PASS for a configuration the layer did not compare.
    GateReport r = report({pass});
    r.rows.push_back({"only_in_base", "balanced", {"not compared: only in the base", "FAIL"}, {}, {}});
    EXPECT_NE(r.markdown().find("| only_in_base | balanced | not compared: only in the base (FAIL) |"),
              std::string::npos);
}

} // namespace
