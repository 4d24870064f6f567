// `bench ci --update` of some configurations (bench/lib/gate/BaselineUpdate.h) on tables and records made
// by hand: the other rows and counts of the committed baseline are kept as they were, in the suite's
// order; an update of everything writes what was measured alone; counts of another machine are not kept
// beside this one's; and layer B compares each configuration with the fingerprint it was counted under
// (bench/lib/gate/InstructionLayer.h), so a Vulkan configuration counted alone is judged against a record
// whose first configuration ran on GL.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/gate/BaselineUpdate.h"
#include "bench/lib/gate/InstructionLayer.h"
#include "core/Error.h"

using namespace sb;

namespace {

/// The suite's configurations a, b, c (in that order), none bound to a driver.
std::vector<CiConfig> suiteConfigs() {
    return {{"a", "balanced", {"-t", "none"}, {}, ""},
            {"b", "balanced", {"-t", "none"}, {}, ""},
            {"c", "balanced", {"-t", "none"}, {}, ""}};
}

std::vector<const CiConfig*> pointers(const std::vector<CiConfig>& configs) {
    std::vector<const CiConfig*> out;
    for (const CiConfig& c : configs) out.push_back(&c);
    return out;
}

TEST(BaselineUpdate, UpdatingOneConfigurationKeepsTheOtherRowsInTheSuitesOrder) {
    const CsvTable committed{{"ci_config", "status", "work_lighting_fragments"},
                             {{"a", "ok", "100"}, {"b", "ok", "200"}, {"c", "ok", "300"}}};
    // b measured again: its count changed and it has a counter the committed header lacks.
    const CsvTable fresh{{"ci_config", "status", "work_lighting_fragments", "counter_rays_traced"},
                         {{"b", "ok", "250", "4096"}}};
    const std::vector<CiConfig> configs = suiteConfigs();
    const CsvTable merged = BaselineUpdate::work(committed, fresh, pointers(configs));
    EXPECT_EQ(merged.header, (std::vector<std::string>{"ci_config", "status", "work_lighting_fragments",
                                                       "counter_rays_traced"}));
    ASSERT_EQ(merged.rows.size(), 3u);
    EXPECT_EQ(merged.rows[0], (std::vector<std::string>{"a", "ok", "100", ""}));
    EXPECT_EQ(merged.rows[1], (std::vector<std::string>{"b", "ok", "250", "4096"}));
    EXPECT_EQ(merged.rows[2], (std::vector<std::string>{"c", "ok", "300", ""}));
}

TEST(BaselineUpdate, UpdatingEveryConfigurationWritesWhatWasMeasuredAlone) {
    // The committed file had a column and a configuration ("gone") that no longer exist.
    const CsvTable committed{{"ci_config", "status", "work_old_fragments"},
                             {{"a", "ok", "1"}, {"gone", "ok", "2"}}};
    const CsvTable fresh{{"ci_config", "status", "work_lighting_fragments"},
                         {{"a", "ok", "10"}, {"b", "ok", "20"}, {"c", "ok", "30"}}};
    const std::vector<CiConfig> configs = suiteConfigs();
    const CsvTable merged = BaselineUpdate::work(committed, fresh, pointers(configs));
    EXPECT_EQ(merged.header, fresh.header);
    EXPECT_EQ(merged.rows, fresh.rows);
}

/// A record's fingerprint: GL or Vulkan on this machine, or GL on another CPU.
nlohmann::json fingerprint(bool vulkan, const std::string& cpu = "AMD EPYC") {
    Fingerprint f;
    f.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    f.glVersion = vulkan ? "" : "4.5 (Compatibility Profile) Mesa 25.0.7-2~bpo12+1";
    f.mesaVersion = "25.0.7-2~bpo12+1";
    f.backend = vulkan ? "" : "egl-surfaceless";
    f.cpuModel = cpu;
    f.valgrind = "valgrind-3.19.0";
    return f.toJson();
}

TechniqueInstructions counts(double irPerFrame) {
    TechniqueInstructions t;
    t.technique = "none";
    t.frames = 3;
    t.totalIr = uint64_t(irPerFrame * 3);
    t.irPerFrame = irPerFrame;
    t.byCategory[0] = t.totalIr;
    return t;
}

TEST(BaselineUpdate, AConfigurationOfAnotherApiJoinsTheRecordWithItsOwnFingerprint) {
    nlohmann::json committed;
    committed["fingerprint"] = fingerprint(false);
    committed["configs"]["a"] = counts(1000).toJson();
    committed["configs"]["b"] = counts(2000).toJson();
    nlohmann::json fresh; // b counted alone, on Vulkan
    fresh["fingerprint"] = fingerprint(true);
    fresh["configs"]["b"] = counts(2100).toJson();
    const std::vector<CiConfig> configs = suiteConfigs();
    const nlohmann::json merged =
        BaselineUpdate::instructions(committed, fresh, pointers(configs), "record.json");
    EXPECT_EQ(merged["fingerprint"], committed["fingerprint"]);
    EXPECT_EQ(merged["configs"]["a"], committed["configs"]["a"]);
    EXPECT_EQ(merged["configs"]["b"]["ir_per_frame"], 2100.0);
    EXPECT_EQ(merged["configs"]["b"]["fingerprint"], fingerprint(true));
    EXPECT_FALSE(merged["configs"].contains("c"));
    // Each configuration reads back under the fingerprint it was counted under.
    EXPECT_EQ(InstructionLayer::committed(merged, "a")->fingerprint.glVersion,
              "4.5 (Compatibility Profile) Mesa 25.0.7-2~bpo12+1");
    EXPECT_EQ(InstructionLayer::committed(merged, "b")->fingerprint.glVersion, "");
    EXPECT_FALSE(InstructionLayer::committed(merged, "c"));
}

TEST(BaselineUpdate, CountsOfAnotherMachineAreNotKeptBesideNewOnes) {
    nlohmann::json committed;
    committed["fingerprint"] = fingerprint(false, "Intel Xeon");
    committed["configs"]["a"] = counts(1000).toJson();
    nlohmann::json fresh;
    fresh["fingerprint"] = fingerprint(false);
    fresh["configs"]["b"] = counts(2000).toJson();
    const std::vector<CiConfig> configs = suiteConfigs();
    try {
        BaselineUpdate::instructions(committed, fresh, pointers(configs), "record.json");
        ADD_FAILURE() << "kept counts of another CPU";
    } catch (const Error& e) {
        EXPECT_NE(
            std::string(e.what()).find("record.json: a's instructions were counted under another fingerprint "
                                       "than this update's (cpu_model)"),
            std::string::npos)
            << e.what();
    }
}

InstructionSample sample(double irPerFrame, bool vulkan) {
    return {counts(irPerFrame), Fingerprint::fromJson(fingerprint(vulkan), "test")};
}

// Layer B judges a Vulkan configuration counted alone against the committed record whose first
// configuration ran on GL: the configuration's own fingerprint is compared, so a 1% growth fails and an
// unchanged count passes, where one fingerprint per record gave no verdict at all.
TEST(InstructionLayerJudge, EachConfigurationIsComparedUnderItsOwnFingerprint) {
    nlohmann::json record;
    record["fingerprint"] = fingerprint(false);
    record["configs"]["a"] = counts(1000).toJson();
    record["configs"]["rt"] = counts(5000).toJson();
    record["configs"]["rt"]["fingerprint"] = fingerprint(true);
    for (const auto& [head, verdict] : {std::pair{5000.0, "PASS"}, {5050.0, "FAIL"}}) {
        InstructionInputs in;
        in.configs = {"rt"};
        in.heads = {sample(head, true)};
        in.again = sample(head, true);
        in.haveRecord = true;
        in.bases = {InstructionLayer::committed(record, "rt")};
        const InstructionLayerResult r = InstructionLayer::judge(in);
        EXPECT_EQ(r.layer.verdict, verdict) << head;
        ASSERT_EQ(r.cells.size(), 1u);
        EXPECT_EQ(r.cells[0].second.verdict, verdict) << r.cells[0].second.summary;
    }
    // The same count judged against the record's GL fingerprint (no fingerprint of its own): no verdict,
    // declined, naming what differs.
    record["configs"]["rt"].erase("fingerprint");
    InstructionInputs in;
    in.configs = {"rt"};
    in.heads = {sample(5000, true)};
    in.again = sample(5000, true);
    in.haveRecord = true;
    in.bases = {InstructionLayer::committed(record, "rt")};
    const InstructionLayerResult r = InstructionLayer::judge(in);
    EXPECT_EQ(r.layer.verdict, "NO VERDICT");
    EXPECT_TRUE(r.layer.declined);
    std::string details;
    for (const std::string& d : r.layer.details) details += d + "\n";
    EXPECT_NE(
        details.find("rt: the baseline was counted on another machine or toolchain (gl_version, backend)"),
        std::string::npos)
        << details;
}

// Two configurations, one comparable and one counted under another fingerprint: the comparable one is
// judged and the layer passes on it; the other's cell says NO VERDICT and the details say why.
TEST(InstructionLayerJudge, AConfigurationOfAnotherFingerprintIsNotComparedAndSaysWhy) {
    InstructionInputs in;
    in.configs = {"a", "b"};
    in.heads = {sample(1000, false), sample(2000, false)};
    in.again = sample(1000, false);
    in.haveRecord = true;
    in.bases = {sample(1000, false), sample(2000, true)};
    const InstructionLayerResult r = InstructionLayer::judge(in);
    EXPECT_EQ(r.layer.verdict, "PASS");
    EXPECT_EQ(r.cells[0].second.verdict, "PASS");
    EXPECT_EQ(r.cells[1].second.verdict, "NO VERDICT");
    std::string details;
    for (const std::string& d : r.layer.details) details += d + "\n";
    EXPECT_NE(details.find("not compared: b: the baseline was counted on another machine"), std::string::npos)
        << details;
}

} // namespace
