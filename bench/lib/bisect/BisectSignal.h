#pragma once
// What `bench bisect` measures of one commit's build, and when two measurements differ:
//   work          layer A's census: the row's exact-work columns (work_*, load_*, counter_*;
//                 WorkGate::isWorkColumn), one run; any column that differs is a change (these counts
//                 were bit-identical across runs on llvmpipe, WorkGate.h).
//   instructions  layer B's count: instructions per frame under callgrind (InstructionCount.h), one
//                 pinned run; a change is a relative difference above `irThreshold` (default the gate's
//                 0.5%, InstructionLayer::kFloor: pinned runs of one build agree within 2.8e-4).
//   image         the `--screenshot` of the last frame: an FNV-1a hash of its pixels, one run; any
//                 pixel that differs is a change.
// A value is a map of named cells (column -> count, "ir_per_frame" -> Ir, "image_fnv1a" -> hash), so
// that the report and the JSON print every signal the same way.
#include <map>
#include <string>
#include <vector>

#include "bench/lib/gate/CiSuite.h"

namespace sb {

using SignalValue = std::map<std::string, std::string>;

class BisectSignal {
public:
    enum class Kind { Work, Instructions, Image };
    /// "work", "instructions" or "image"; Error(BadInput) otherwise.
    static Kind parse(const std::string& name);
    static const char* name(Kind kind);

    /// The configuration `config` of `suite` (frames and warm-up from the suite's layer of the signal).
    BisectSignal(Kind kind, CiSuite suite, CiConfig config, double irThreshold);
    /// Throws Error(Unsupported) when the machine lacks what the signal needs (valgrind).
    void requireTools() const;
    /// Runs the configuration once with `bench` and reads the signal; `workDir` receives its files.
    /// Error(Failure) when the run fails (the commit is then skipped).
    SignalValue measure(const std::string& bench, const std::string& workDir) const;
    /// How `head` differs from `base`, one line per changed cell ("depth_fragments 59072 -> 0");
    /// empty when they are the same signal.
    std::vector<std::string> differences(const SignalValue& base, const SignalValue& head) const;
    Kind kind() const { return mKind; }
    /// The argv of one run (bench options only), for the report.
    std::vector<std::string> benchArgs() const;

private:
    SignalValue measureWork(const std::string& bench) const;
    SignalValue measureInstructions(const std::string& bench, const std::string& workDir) const;
    SignalValue measureImage(const std::string& bench, const std::string& workDir) const;
    Kind mKind;
    CiSuite mSuite;
    CiConfig mConfig;
    double mIrThreshold;
};

} // namespace sb
