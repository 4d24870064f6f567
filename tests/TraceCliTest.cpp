// `bench --trace FILE` end to end (bench/lib/rows/TraceWriter.h): the file is a trace-event JSON object
// whose frames and passes are the ones the CSV row summarises. Each run's trace is checked against its
// own row, an independent output of the same run: one "CPU submit" span per measured frame, the passes
// nested inside their frames, the per-pass medians equal to the row's cpu_<pass>_ms_median, and GPU
// spans only where the row's timer verdict is "trusted" (then equal to its gpu_<pass>_ms_median),
// otherwise none and the row's reason recorded. On GL (two techniques, two processes) and on Vulkan.
#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using json = nlohmann::json;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
// The cheapest measured run: 5 frames (an odd count: the median is one frame's value), one warm-up.
const std::string kQuick = " --frames 5 --warmup 1 --size 64x64 --instances 4";
constexpr int kFrames = 5;
constexpr int kCpuTrack = 1, kGpuTrack = 2;
// The CSV writes milliseconds with 4 decimals (bench/lib/output/CsvNumber.h), so a cell is within
// 0.00005 ms of the value; the trace keeps whole nanoseconds (1e-6 ms). Together: 0.000051 ms.
constexpr double kMedianToleranceMs = 0.00005 + 1e-6;
// The trace writes microseconds with nanosecond decimals; printing and reading a double back can add a
// last-digit error far below a nanosecond. Containment is checked to 1e-4 us.
constexpr double kContainToleranceUs = 1e-4;

using Row = std::map<std::string, std::string>;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

std::vector<json> eventsOf(const json& trace, int pid, int tid, const std::string& phase) {
    std::vector<json> out;
    for (const json& e : trace["traceEvents"])
        if (e["ph"] == phase && e["pid"] == pid && e.value("tid", 0) == tid) out.push_back(e);
    return out;
}

std::string metadataName(const json& trace, int pid, int tid, const std::string& kind) {
    for (const json& e : trace["traceEvents"])
        if (e["ph"] == "M" && e["pid"] == pid && e.value("tid", 0) == tid && e["name"] == kind)
            return e["args"]["name"];
    return "";
}

/// Per pass name: its total duration in each frame (ms). Every pass span must lie inside exactly one
/// frame, and a frame's passes must not sum to more than the frame.
std::map<std::string, std::vector<double>> passesPerFrame(const std::vector<json>& frames,
                                                          const std::vector<json>& spans) {
    std::map<std::string, std::vector<double>> perPass;
    std::vector<int> homes(spans.size(), 0);
    for (const json& f : frames) {
        const double start = f["ts"], end = start + f["dur"].get<double>();
        std::map<std::string, double> inFrame;
        double sum = 0.0;
        for (size_t i = 0; i < spans.size(); ++i) {
            const double ts = spans[i]["ts"], dur = spans[i]["dur"];
            if (ts < start - kContainToleranceUs || ts >= end) continue;
            EXPECT_LE(ts + dur, end + kContainToleranceUs) << spans[i].dump() << " leaves " << f.dump();
            ++homes[i];
            inFrame[spans[i]["name"]] += dur / 1000.0;
            sum += dur;
        }
        EXPECT_LE(sum, f["dur"].get<double>() + kContainToleranceUs) << f.dump();
        for (const auto& [name, ms] : inFrame) perPass[name].push_back(ms);
    }
    for (size_t i = 0; i < spans.size(); ++i) EXPECT_EQ(homes[i], 1) << "in one frame: " << spans[i].dump();
    return perPass;
}

/// The row's columns of `family` (col::kCpuPassMsMedian, col::kGpuPassMsMedian) that have a value, by
/// pass. ResultColumns::find takes fixed names first, so cpu_submit_ms_median is not a pass.
std::map<std::string, double> passColumns(const Row& row, std::string_view family) {
    const size_t lt = family.find('<'), tail = family.size() - family.find('>') - 1;
    std::map<std::string, double> out;
    for (const auto& [name, value] : row) {
        const ColumnInfo* info = ResultColumns::find(name);
        if (!info || info->name != family || value.empty()) continue;
        out[name.substr(lt, name.size() - lt - tail)] = std::stod(value);
    }
    return out;
}

void expectPassMediansMatch(const std::map<std::string, std::vector<double>>& perPass,
                            const std::map<std::string, double>& columns, size_t frames,
                            const std::string& what) {
    ASSERT_FALSE(columns.empty()) << what << ": the row has no per-pass column";
    for (const auto& [pass, expected] : columns) {
        ASSERT_TRUE(perPass.count(pass)) << what << ": no span for pass " << pass;
        EXPECT_EQ(perPass.at(pass).size(), frames) << what << " " << pass;
        EXPECT_NEAR(median(perPass.at(pass)), expected, kMedianToleranceMs) << what << " " << pass;
    }
}

/// The GPU track: spans matching the row where it trusts the timer; otherwise none, and the reason.
void checkGpuTrack(const json& trace, int pid, const Row& row) {
    const std::vector<json> spans = eventsOf(trace, pid, kGpuTrack, "X");
    const json& meta = trace["metadata"]["runs"][size_t(pid - 1)];
    EXPECT_EQ(meta[col::kTimerVerdict], row.at(col::kTimerVerdict));
    if (row.at(col::kTimerVerdict) != "trusted") {
        EXPECT_TRUE(spans.empty()) << "GPU spans under a " << row.at(col::kTimerVerdict) << " timer";
        const std::vector<json> notes = eventsOf(trace, pid, kGpuTrack, "i");
        ASSERT_EQ(notes.size(), 1u);
        EXPECT_NE(notes[0]["name"].get<std::string>().find(row.at(col::kTimerVerdict)), std::string::npos);
        EXPECT_EQ(notes[0]["args"][col::kTimerReason], row.at(col::kTimerReason));
        EXPECT_EQ(meta[col::kTimerReason], row.at(col::kTimerReason));
        return;
    }
    std::vector<json> frames, passes;
    for (const json& e : spans) (e["cat"] == "frame" ? frames : passes).push_back(e);
    // Frames whose queries never came back have no GPU span; the row's medians are of the others.
    ASSERT_GE(frames.size(), 1u);
    EXPECT_LE(frames.size(), size_t(kFrames));
    expectPassMediansMatch(passesPerFrame(frames, passes), passColumns(row, col::kGpuPassMsMedian),
                           frames.size(), "GPU");
}

/// Everything one process of the trace must show, against the row of the same run.
void checkRun(const json& trace, int pid, const Row& row) {
    const std::string what = row.at(col::kTechnique) + " (pid " + std::to_string(pid) + ")";
    const std::string process = metadataName(trace, pid, 0, "process_name");
    EXPECT_TRUE(process == row.at(col::kTechnique) ||
                process == row.at(col::kTechnique) + " " + row.at(col::kProperties))
        << what << ": " << process;
    EXPECT_EQ(metadataName(trace, pid, kCpuTrack, "thread_name"), "CPU submit") << what;
    EXPECT_EQ(metadataName(trace, pid, kGpuTrack, "thread_name"), "GPU") << what;
    const json& meta = trace["metadata"]["runs"][size_t(pid - 1)];
    for (const char* c : {col::kTechnique, col::kProperties, col::kScene, col::kApi, col::kRenderer,
                          col::kDevice, col::kGitCommit})
        EXPECT_EQ(meta[c], row.at(c)) << what << " " << c;

    std::vector<json> frames, passes;
    for (const json& e : eventsOf(trace, pid, kCpuTrack, "X"))
        (e["cat"] == "frame" ? frames : passes).push_back(e);
    ASSERT_EQ(frames.size(), size_t(kFrames)) << what;
    std::vector<double> frameMs;
    for (const json& f : frames) frameMs.push_back(f["dur"].get<double>() / 1000.0);
    EXPECT_NEAR(median(frameMs), std::stod(row.at(col::kCpuSubmitMsMedian)), kMedianToleranceMs) << what;
    expectPassMediansMatch(passesPerFrame(frames, passes), passColumns(row, col::kCpuPassMsMedian),
                           frames.size(), what + " CPU");

    // One "frame ms" counter per frame, its cpu_submit the frame span's duration.
    std::vector<json> counters;
    for (const json& e : eventsOf(trace, pid, 0, "C"))
        if (e["name"] == "frame ms") counters.push_back(e);
    ASSERT_EQ(counters.size(), frames.size()) << what;
    for (size_t i = 0; i < frames.size(); ++i) {
        EXPECT_DOUBLE_EQ(counters[i]["ts"].get<double>(), frames[i]["ts"].get<double>());
        EXPECT_NEAR(counters[i]["args"]["cpu_submit"].get<double>(), frames[i]["dur"].get<double>() / 1000.0,
                    1e-6);
    }
    checkGpuTrack(trace, pid, row);
}

json runAndRead(const std::string& args, const std::string& dir, std::vector<Row>& rows) {
    const std::string trace = dir + "/t.json", csv = dir + "/r.csv";
    const auto r = runCommand(kBench + args + kQuick + " --trace " + trace + " --csv " + csv);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    rows = test::csvRowMaps(csv);
    const json doc = json::parse(test::readFile(trace)); // throws (and fails the test) when not JSON
    EXPECT_EQ(doc["displayTimeUnit"], "ms");
    EXPECT_TRUE(doc["traceEvents"].is_array());
    EXPECT_EQ(doc["metadata"]["runs"].size(), rows.size());
    return doc;
}

TEST(TraceCli, GlTwoTechniquesAreTwoProcessesMatchingTheirRows) {
    std::vector<Row> rows;
    const json trace = runAndRead(" -t none -t shadowmap", test::freshTestDir("trace"), rows);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].at(col::kTechnique), "none");
    EXPECT_EQ(rows[1].at(col::kTechnique), "shadowmap");
    for (size_t i = 0; i < rows.size(); ++i) checkRun(trace, int(i) + 1, rows[i]);
}

TEST(TraceCli, VulkanRunMatchesItsRow) {
    std::vector<Row> rows;
    const json trace = runAndRead(" --api vulkan -t shadowmap", test::freshTestDir("trace"), rows);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at(col::kApi), "vulkan");
    checkRun(trace, 1, rows[0]);
}

TEST(TraceCli, AFailedRunKeepsTheExistingTraceAndABadPathFailsBeforeAnyFrame) {
    const std::string dir = test::freshTestDir("trace");
    const std::string trace = dir + "/t.json";
    test::writeFile(trace, "previous\n");
    // Wrong input after the outputs are known: nothing is measured and the old file stays.
    auto r = runCommand(kBench + " -t no_such_technique --no-timer-check" + kQuick + " --trace " + trace);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(test::readFile(trace), "previous\n");
    r = runCommand(kBench + " -t none --no-timer-check" + kQuick + " --trace " + dir + "/missing/t.json");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--trace"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("frames, median"), std::string::npos) << "measured before failing:\n" << r.output;
}

} // namespace
