#include "bench/lib/rows/TraceWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bench/lib/output/AtomicFile.h"
#include "bench/lib/output/ResultColumns.h"

namespace sb {

namespace {

using json = nlohmann::json;

constexpr int kCpuTrack = 1, kGpuTrack = 2;
constexpr const char* kTrusted = "trusted";
/// The row's columns copied into each process's metadata, under the row's own names.
constexpr const char* kIdentityColumns[] = {
    col::kTechnique, col::kProperties,   col::kScene,      col::kApi,    col::kApiVersion,
    col::kRenderer,  col::kGlVendor,     col::kBackend,    col::kDevice, col::kSubmit,
    col::kGitCommit, col::kTimerVerdict, col::kTimerReason};

std::string column(const CsvRow& row, const std::string& name) {
    for (const auto& [key, value] : row)
        if (key == name) return value;
    return "";
}

/// Milliseconds to whole nanoseconds: the harness's readings are steady-clock nanoseconds turned into
/// doubles, so rounding gives them back exactly.
int64_t toNs(double ms) {
    return int64_t(std::llround(ms * 1e6));
}

/// The format's unit is the microsecond; the decimals keep the nanoseconds.
double toUs(int64_t ns) {
    return double(ns) / 1000.0;
}

json metadataEvent(int pid, int tid, const char* name, json args) {
    json e{{"ph", "M"}, {"pid", pid}, {"name", name}, {"args", std::move(args)}};
    if (tid) e["tid"] = tid;
    return e;
}

json completeEvent(int pid, int tid, const std::string& name, const char* category, int64_t tsNs,
                   int64_t durNs) {
    return {{"ph", "X"},       {"pid", pid},       {"tid", tid},        {"name", name},
            {"cat", category}, {"ts", toUs(tsNs)}, {"dur", toUs(durNs)}};
}

json counterEvent(int pid, const char* name, int64_t tsNs, json args) {
    return {{"ph", "C"}, {"pid", pid}, {"name", name}, {"ts", toUs(tsNs)}, {"args", std::move(args)}};
}

/// `rounds`: the run measured its techniques in several rounds (--repeat), so the round tells apart the
/// processes of one technique.
void addNames(json& events, int pid, const RunResult& r, const CsvRow& row, bool rounds) {
    std::string name = r.properties.empty() ? r.technique : r.technique + " " + r.properties;
    if (rounds) name += " (round " + column(row, col::kRepeat) + ")";
    events.push_back(metadataEvent(pid, 0, "process_name", {{"name", name}}));
    events.push_back(metadataEvent(pid, 0, "process_sort_index", {{"sort_index", pid}}));
    events.push_back(metadataEvent(pid, kCpuTrack, "thread_name", {{"name", "CPU submit"}}));
    events.push_back(metadataEvent(pid, kCpuTrack, "thread_sort_index", {{"sort_index", kCpuTrack}}));
    events.push_back(metadataEvent(pid, kGpuTrack, "thread_name", {{"name", "GPU"}}));
    events.push_back(metadataEvent(pid, kGpuTrack, "thread_sort_index", {{"sort_index", kGpuTrack}}));
}

/// The frame's CPU span and its passes inside it. The last pass ends at the frame's end by
/// construction (CpuPassSpan); the min() only guards that against a rounding of the last nanosecond.
void addCpuFrame(json& events, int pid, size_t index, const FrameSample& s, int64_t startNs) {
    const int64_t endNs = startNs + toNs(s.cpuSubmitMs);
    json frame =
        completeEvent(pid, kCpuTrack, "frame " + std::to_string(index), "frame", startNs, endNs - startNs);
    frame["args"] = {{"frame", index}, {"cpu_submit_ms", s.cpuSubmitMs}, {"wall_ms", s.wallMs}};
    events.push_back(std::move(frame));
    for (const CpuPassSpan& p : s.cpuPasses) {
        const int64_t passNs = startNs + toNs(p.startMs);
        const int64_t passEndNs = std::min(endNs, passNs + toNs(p.durationMs));
        events.push_back(completeEvent(pid, kCpuTrack, p.pass, "pass", passNs, passEndNs - passNs));
    }
}

/// The frame's GPU times, drawn from the CPU frame's start (the GPU clock is another clock); the passes
/// back to back, as the rings stamp them.
void addGpuFrame(json& events, int pid, size_t index, const FrameSample& s, int64_t startNs) {
    if (s.gpuTotalMs < 0.0) return; // its queries never came back
    events.push_back(completeEvent(pid, kGpuTrack, "frame " + std::to_string(index), "frame", startNs,
                                   toNs(s.gpuTotalMs)));
    int64_t at = startNs;
    for (const auto& [pass, ms] : s.gpuPassMs) {
        events.push_back(completeEvent(pid, kGpuTrack, pass, "pass", at, toNs(ms)));
        at += toNs(ms);
    }
}

json frameCounters(const FrameSample& s, bool moving) {
    json args{{"cpu_submit", s.cpuSubmitMs}, {"wall", s.wallMs}};
    if (moving) args["motion"] = s.motionMs;
    return args;
}

json censusCounters(const FrameLoads& loads) {
    json args{{"draws", loads.submitted.drawCalls},
              {"triangles", loads.submitted.triangles},
              {"api_calls", loads.submitted.glCalls}};
    if (loads.pipeline) {
        args["vertices"] = loads.pipeline->vertexShaderInvocations;
        args["primitives"] = loads.pipeline->primitivesSubmitted;
        args["clipped_primitives"] = loads.pipeline->clippingOutputPrimitives;
        args["fragments"] = loads.pipeline->fragmentShaderInvocations;
    }
    return args;
}

/// The whole run's events after its names: frames (CPU, then GPU where trusted) and counters.
void addRunEvents(json& events, int pid, const RunResult& r, const CsvRow& row, double originMs) {
    const bool trusted = column(row, col::kTimerVerdict) == kTrusted;
    const bool moving = column(row, col::kPathTime) == "moving";
    int64_t lastNs = 0;
    for (size_t i = 0; i < r.samples.size(); ++i) {
        const FrameSample& s = r.samples[i];
        const int64_t startNs = toNs(s.startMs - originMs);
        addCpuFrame(events, pid, i, s, startNs);
        if (trusted) addGpuFrame(events, pid, i, s, startNs);
        events.push_back(counterEvent(pid, "frame ms", startNs, frameCounters(s, moving)));
        lastNs = startNs;
    }
    if (r.samples.empty()) return;
    const int64_t firstNs = toNs(r.samples.front().startMs - originMs);
    if (!trusted)
        events.push_back({{"ph", "i"},
                          {"s", "t"},
                          {"pid", pid},
                          {"tid", kGpuTrack},
                          {"name", "no GPU spans: timer " + column(row, col::kTimerVerdict)},
                          {"ts", toUs(firstNs)},
                          {"args", {{col::kTimerReason, column(row, col::kTimerReason)}}}});
    json counters = json::object();
    for (const auto& [name, value] : r.counters) counters[name] = value;
    if (!counters.empty())
        events.push_back(counterEvent(pid, "technique counters", lastNs, std::move(counters)));
    events.push_back(counterEvent(pid, "census work", lastNs, censusCounters(r.loads)));
}

json runMetadata(int pid, const CsvRow& row) {
    json m{{"pid", pid}};
    for (const char* name : kIdentityColumns) m[name] = column(row, name);
    const bool trusted = column(row, col::kTimerVerdict) == kTrusted;
    m["gpu_spans"] =
        trusted ? "written"
                : "omitted: the GPU timer is " + column(row, col::kTimerVerdict) + " (timer_reason says why)";
    return m;
}

} // namespace

void TraceWriter::addRun(const RunResult& run, const CsvRow& row) {
    mRuns.push_back({run, row});
}

json TraceWriter::toJson() const {
    // Every frame's ts counts from the earliest frame of the trace, so the timeline starts at 0.
    double originMs = std::numeric_limits<double>::infinity();
    for (const Run& run : mRuns)
        for (const FrameSample& s : run.result.samples) originMs = std::min(originMs, s.startMs);
    if (!std::isfinite(originMs)) originMs = 0.0;
    const bool rounds = std::any_of(mRuns.begin(), mRuns.end(), [](const Run& run) {
        const std::string round = column(run.row, col::kRepeat);
        return !round.empty() && round != "1";
    });
    json events = json::array();
    json runs = json::array();
    for (size_t i = 0; i < mRuns.size(); ++i) {
        const int pid = int(i) + 1;
        addNames(events, pid, mRuns[i].result, mRuns[i].row, rounds);
        addRunEvents(events, pid, mRuns[i].result, mRuns[i].row, originMs);
        runs.push_back(runMetadata(pid, mRuns[i].row));
    }
    json metadata{{"tool", "shadowbench"}, {"runs", std::move(runs)}};
    if (!mRuns.empty()) metadata[col::kGitCommit] = column(mRuns.front().row, col::kGitCommit);
    return {{"traceEvents", std::move(events)}, {"displayTimeUnit", "ms"}, {"metadata", std::move(metadata)}};
}

void TraceWriter::write(const std::string& path) const {
    // Built completely before the file is opened: an error here leaves the old file as it was.
    const std::string text = toJson().dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
    AtomicFile file(path, "trace");
    file.replace(text);
}

void TraceWriter::checkWritable(const std::string& path) {
    AtomicFile::checkWritable(path, "--trace");
}

} // namespace sb
