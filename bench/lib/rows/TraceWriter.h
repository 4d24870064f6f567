#pragma once
// --trace FILE: the measured frames of a run as a timeline, in the Chrome trace-event "JSON Object
// Format" that ui.perfetto.dev and chrome://tracing open:
//   {"traceEvents": [...], "displayTimeUnit": "ms", "metadata": {...}}
//
// Built after the run from what the harness already kept per frame (bench/lib/harness/FrameSample.h), so
// tracing adds nothing to the measured frames. Layout:
//   - one process per measured run (pid 1, 2, ... in the order the runs were added; a technique measured
//     in several rounds is one process per round), named "<technique> <properties>" (the technique alone
//     where it has no properties; " (round N)" added where the row's `repeat` shows several rounds) by
//     "M" events;
//   - thread 1, "CPU submit": a complete event ("X") per measured frame, its duration the frame's CPU
//     submit time, and inside it one "X" per pass the frame began (CpuPassSpan: begin to the next pass's
//     begin, the last to the end of submission), at its measured offset from the frame's start;
//   - thread 2, "GPU": only where the row's timer verdict is "trusted", an "X" per frame whose GPU times
//     came back (its GPU total) and its passes' GPU times inside. The GPU clock is not the CPU clock: the
//     frame's GPU span is drawn from the CPU frame's start, and its passes back to back from there, as
//     the timestamp rings stamp them (each pass runs from its stamp to the next one). Where the verdict
//     is anything else no GPU span is written; an instant event ("i") on the GPU track and the run's
//     metadata say why (the verdict and its reason);
//   - counters ("C"), per process: "frame ms" (cpu_submit, wall, and motion for a scene in motion) at
//     each frame, "technique counters" (the technique's counters of the last measured frame) and
//     "census work" (the untimed census frame's totals) at the last frame.
// Times are microseconds from the earliest frame of the whole trace, written with nanosecond decimals
// (the steady clock's resolution), so a pass span always lies inside its frame and the durations are
// the measured ones to 1 ns. Top-level "metadata" holds the tool and, per process, the row's technique,
// properties, scene, API, renderer, device, driver, commit and timer verdict.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/harness/RunResult.h"
#include "bench/lib/output/CsvWriter.h"

namespace sb {

class TraceWriter {
public:
    /// Adds one measured run: its frames (`run.samples`) and its CSV row (identity, device, commit and
    /// timer verdict are read from the row's columns, so the trace says what the row says).
    void addRun(const RunResult& run, const CsvRow& row);
    /// The trace as the JSON object format (an empty trace has no events, and its metadata still names the
    /// tool).
    nlohmann::json toJson() const;
    /// Writes toJson() to `path` atomically (bench/lib/output/AtomicFile.h): on any error the file that
    /// was there is kept. Throws sb::Error as AtomicFile does.
    void write(const std::string& path) const;
    /// The up-front check before the first frame (AtomicFile::checkWritable).
    static void checkWritable(const std::string& path);

private:
    struct Run {
        RunResult result;
        CsvRow row;
    };
    std::vector<Run> mRuns;
};

} // namespace sb
