// TraceWriter (bench/lib/rows/TraceWriter.h) on hand-made runs, no GL: the positions and durations of
// the spans against hand-computed microseconds, the escaping of names, the order of the events, the GPU
// track under each verdict, an empty trace, and the atomic write.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/rows/TraceWriter.h"
#include "core/Error.h"

using namespace sb;
using json = nlohmann::json;

namespace {

// Values below are exact in binary or a few ulps from it; the writer keeps whole nanoseconds, so
// positions are compared to 1e-6 us.
constexpr double kUs = 1e-6;

/// A frame starting at `startMs` on the steady clock with CPU submit `cpuMs` and the passes given.
FrameSample frame(double startMs, double cpuMs, std::vector<CpuPassSpan> passes) {
    FrameSample s;
    s.startMs = startMs;
    s.cpuSubmitMs = cpuMs;
    s.wallMs = cpuMs + 1.0;
    s.cpuPasses = std::move(passes);
    return s;
}

CsvRow row(const std::string& technique, const std::string& verdict, const std::string& reason) {
    return {{"technique", technique},   {"properties", "pcf=3"},
            {"scene", "plate"},         {"api", "gl"},
            {"renderer", "llvmpipe"},   {"git_commit", "abc123"},
            {"timer_verdict", verdict}, {"timer_reason", reason}};
}

RunResult run(const std::string& technique, std::vector<FrameSample> samples) {
    RunResult r;
    r.technique = technique;
    r.properties = "pcf=3";
    r.samples = std::move(samples);
    r.counters = {{"triangles", 12.0}};
    return r;
}

std::vector<json> events(const json& trace, const std::string& phase, int tid) {
    std::vector<json> out;
    for (const json& e : trace["traceEvents"])
        if (e["ph"] == phase && e.value("tid", 0) == tid) out.push_back(e);
    return out;
}

TEST(TraceWriter, EmptyTraceIsAValidObjectWithNoEvents) {
    const json t = TraceWriter().toJson();
    EXPECT_TRUE(t["traceEvents"].is_array());
    EXPECT_TRUE(t["traceEvents"].empty());
    EXPECT_EQ(t["displayTimeUnit"], "ms");
    EXPECT_EQ(t["metadata"]["tool"], "shadowbench");
    EXPECT_TRUE(t["metadata"]["runs"].empty());
}

TEST(TraceWriter, SpansSitAtTheirMeasuredOffsetsInMicroseconds) {
    TraceWriter w;
    // Frame 0 at 1000 ms on the clock (the trace's origin), frame 1 at 1003.5 ms.
    w.addRun(run("shadowmap", {frame(1000.0, 2.0, {{"depth", 0.25, 0.5}, {"lighting", 0.75, 1.25}}),
                               frame(1003.5, 1.5, {{"depth", 0.125, 0.375}, {"lighting", 0.5, 1.0}})}),
             row("shadowmap", "untrusted", "timer/wall 0.1"));
    const json t = w.toJson();
    const std::vector<json> cpu = events(t, "X", 1);
    ASSERT_EQ(cpu.size(), 6u);
    // In order: frame, its passes, next frame, its passes.
    const struct {
        const char* name;
        double ts, dur;
    } expected[] = {{"frame 0", 0.0, 2000.0},    {"depth", 250.0, 500.0},  {"lighting", 750.0, 1250.0},
                    {"frame 1", 3500.0, 1500.0}, {"depth", 3625.0, 375.0}, {"lighting", 4000.0, 1000.0}};
    for (size_t i = 0; i < cpu.size(); ++i) {
        EXPECT_EQ(cpu[i]["name"], expected[i].name) << i;
        EXPECT_NEAR(cpu[i]["ts"].get<double>(), expected[i].ts, kUs) << i;
        EXPECT_NEAR(cpu[i]["dur"].get<double>(), expected[i].dur, kUs) << i;
        EXPECT_EQ(cpu[i]["pid"], 1);
    }
    // The technique's counters, once, at the last frame.
    int counters = 0;
    for (const json& e : t["traceEvents"])
        if (e["ph"] == "C" && e["name"] == "technique counters") {
            ++counters;
            EXPECT_EQ(e["args"]["triangles"], 12.0);
            EXPECT_NEAR(e["ts"].get<double>(), 3500.0, kUs);
        }
    EXPECT_EQ(counters, 1);
}

TEST(TraceWriter, NamesAreEscapedAndComeBackUnchanged) {
    const std::string odd = "sha\"dow\\map\n\t\x01 \xc3\xa9";
    TraceWriter w;
    w.addRun(run(odd, {frame(5.0, 1.0, {})}), row(odd, "unchecked", "--no-timer-check"));
    const std::string path = test::freshTestDir("trace-writer") + "/t.json";
    w.write(path);
    const std::string text = test::readFile(path);
    EXPECT_NE(text.find("sha\\\"dow\\\\map\\n\\t\\u0001"), std::string::npos) << text;
    const json t = json::parse(text);
    EXPECT_EQ(t["metadata"]["runs"][0]["technique"], odd);
    bool named = false;
    for (const json& e : t["traceEvents"])
        if (e["ph"] == "M" && e["name"] == "process_name") named = e["args"]["name"] == odd + " pcf=3";
    EXPECT_TRUE(named);
}

TEST(TraceWriter, EachRunIsAProcessWithItsNamesBeforeItsFrames) {
    TraceWriter w;
    w.addRun(run("none", {frame(10.0, 1.0, {{"lighting", 0.5, 0.5}})}), row("none", "untrusted", "r"));
    w.addRun(run("shadowmap", {frame(12.0, 1.0, {{"depth", 0.5, 0.5}})}), row("shadowmap", "untrusted", "r"));
    const json t = w.toJson();
    int lastPid = 0;
    bool framesSeen = false;
    for (const json& e : t["traceEvents"]) {
        const int pid = e["pid"];
        ASSERT_GE(pid, lastPid) << "processes in the order added";
        if (pid != lastPid) framesSeen = false;
        lastPid = pid;
        if (e["ph"] == "M")
            EXPECT_FALSE(framesSeen) << "names before frames: " << e.dump();
        else
            framesSeen = true;
    }
    EXPECT_EQ(lastPid, 2);
    for (const json& e : t["traceEvents"])
        if (e["ph"] == "M" && e["name"] == "process_name") {
            EXPECT_EQ(e["args"]["name"], e["pid"] == 1 ? "none pcf=3" : "shadowmap pcf=3")
                << "one round: no round";
        }
    EXPECT_EQ(t["metadata"]["runs"][1]["technique"], "shadowmap");
    // The origin is the earliest frame of the whole trace: the second process starts 2000 us later.
    for (const json& e : events(t, "X", 1))
        if (e["pid"] == 2 && e["name"] == "frame 0") {
            EXPECT_NEAR(e["ts"].get<double>(), 2000.0, kUs);
        }
}

TEST(TraceWriter, RoundsOfOneTechniqueAreNamedApart) {
    TraceWriter w;
    for (const char* round : {"1", "2"}) {
        CsvRow r = row("none", "untrusted", "r");
        r.emplace_back("repeat", round);
        w.addRun(run("none", {frame(1.0, 1.0, {})}), r);
    }
    std::vector<std::string> names;
    const json t = w.toJson();
    for (const json& e : t["traceEvents"])
        if (e["ph"] == "M" && e["name"] == "process_name") names.push_back(e["args"]["name"]);
    EXPECT_EQ(names, (std::vector<std::string>{"none pcf=3 (round 1)", "none pcf=3 (round 2)"}));
}

TEST(TraceWriter, GpuSpansOnlyUnderATrustedTimer) {
    FrameSample s = frame(0.0, 2.0, {{"depth", 0.0, 1.0}, {"lighting", 1.0, 1.0}});
    s.gpuPassMs = {{"depth", 0.75}, {"lighting", 0.5}};
    s.gpuTotalMs = 1.25;
    FrameSample lost = frame(3.0, 2.0, {}); // its queries never came back: no GPU span
    {
        TraceWriter w;
        w.addRun(run("shadowmap", {s, lost}), row("shadowmap", "trusted", "ok"));
        const std::vector<json> gpu = events(w.toJson(), "X", 2);
        ASSERT_EQ(gpu.size(), 3u);
        EXPECT_EQ(gpu[0]["name"], "frame 0");
        EXPECT_NEAR(gpu[0]["dur"].get<double>(), 1250.0, kUs);
        // Back to back from the frame's start, as the timestamps bound them.
        EXPECT_NEAR(gpu[1]["ts"].get<double>(), 0.0, kUs);
        EXPECT_NEAR(gpu[1]["dur"].get<double>(), 750.0, kUs);
        EXPECT_NEAR(gpu[2]["ts"].get<double>(), 750.0, kUs);
        EXPECT_NEAR(gpu[2]["dur"].get<double>(), 500.0, kUs);
        EXPECT_TRUE(events(w.toJson(), "i", 2).empty());
    }
    for (const char* verdict : {"untrusted", "unchecked"}) {
        TraceWriter w;
        w.addRun(run("shadowmap", {s, lost}), row("shadowmap", verdict, "timer/wall 0.02, outside 0.5..2"));
        const json t = w.toJson();
        EXPECT_TRUE(events(t, "X", 2).empty()) << verdict;
        const std::vector<json> notes = events(t, "i", 2);
        ASSERT_EQ(notes.size(), 1u) << verdict;
        EXPECT_EQ(notes[0]["args"]["timer_reason"], "timer/wall 0.02, outside 0.5..2");
        EXPECT_NE(t["metadata"]["runs"][0]["gpu_spans"].get<std::string>().find(verdict), std::string::npos);
    }
}

TEST(TraceWriter, WriteReplacesTheFileAndAFailedWriteLeavesNoFile) {
    const std::string dir = test::freshTestDir("trace-writer");
    TraceWriter w;
    w.addRun(run("none", {frame(1.0, 1.0, {})}), row("none", "untrusted", "r"));
    test::writeFile(dir + "/t.json", "old");
    w.write(dir + "/t.json");
    EXPECT_EQ(json::parse(test::readFile(dir + "/t.json"))["metadata"]["runs"].size(), 1u);
    EXPECT_THROW(w.write(dir + "/missing/t.json"), Error);
    EXPECT_FALSE(std::filesystem::exists(dir + "/missing"));
    EXPECT_THROW(TraceWriter::checkWritable(dir + "/missing/t.json"), Error);
}

} // namespace
