#pragma once
// Layer B of the perf gate: instructions per frame of the suite's instruction configurations, each run
// once under callgrind (InstructionCount.h) with llvmpipe pinned, plus an A/A pair (the first
// configuration run a second time) in every job. The A/A pair is the instrument's check: if it
// disagrees by more than 1e-3 the layer gives no verdict ("instrument unstable"); pinned runs agree to
// the instruction outside libc, whose calloc follows the heap's history (2.8e-4 seen, all in libc). Otherwise
// a configuration fails when its instructions per frame grew by more than max(0.5%, the A/A difference).
// Against the committed baseline (results/ci/baseline/instructions.json) the fingerprints must match
// (Fingerprint.h): another CPU, Mesa (on either API), LLVM, valgrind or glibc gives no verdict, marked
// declined (GateReport.h: reported, never a false alarm); a configuration the record lacks fails. Against
// a base measured now, the differences of the fingerprints are listed and the layer judges: in a driver
// A/B (--base-env/--head-env, or each side's driver) the driver is the variable under test.
//
// Fingerprints are compared configuration by configuration: a suite mixes APIs (a Vulkan row has no GL
// version and another backend) and a driver-bound configuration may be counted alone (bench ci
// --driver-bound), so a record keeps, beside the fingerprint of its first configuration, the fingerprint
// of each configuration whose run differs from it ("configs": {name: {..., "fingerprint": {...}}}). A
// configuration whose fingerprint differs from its base's is NO VERDICT in its own cell; the layer judges
// the others, and gives no verdict only when it compared none.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/callgrind/TechniqueInstructions.h"
#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/gate/Fingerprint.h"
#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/SuiteRunner.h"

namespace sb {

struct InstructionLayerResult {
    GateLayer layer;
    std::vector<std::pair<std::string, LayerCell>> cells;
    nlohmann::json
        record; ///< {"fingerprint", "configs": {name: TechniqueInstructions::toJson}}: the baseline format
};

/// One configuration's count under callgrind and the fingerprint of its run.
struct InstructionSample {
    TechniqueInstructions counts;
    Fingerprint fingerprint;
};

/// What layer B judges once everything is counted (InstructionLayer::judge).
struct InstructionInputs {
    std::vector<std::string> configs;     ///< names, in the suite's order
    std::vector<InstructionSample> heads; ///< one per configuration
    InstructionSample again;              ///< the A/A pair: configs.front() counted a second time
    /// The base of each configuration: measured now (`measuredBase`), or the committed record's with the
    /// fingerprint it was counted under; empty where the record lacks the configuration.
    std::vector<std::optional<InstructionSample>> bases;
    bool measuredBase = false;
    bool haveRecord = false; ///< a committed record was given (without one and no base: no verdict)
    /// The variables either side of a measured base set (a driver A/B's): what may differ besides the driver.
    std::set<std::string> tested;
};

class InstructionLayer {
public:
    static constexpr double kFloor = 0.005; ///< 0.5%: the smallest change that fails
    static constexpr double kUnstableAbove =
        1e-3; ///< A/A disagreement that voids the layer (5x below kFloor)

    /// Measures `head` (and `base` when given) and judges against `base`, else against `baseline`
    /// (the committed record; null: none yet, the layer reports the counts and gives no verdict).
    /// `workDir` receives the callgrind files. Throws Error(Unsupported) when valgrind is missing.
    static InstructionLayerResult run(const CiSuite& suite, const std::vector<const CiConfig*>& configs,
                                      const std::optional<CiSide>& base, const CiSide& head,
                                      const nlohmann::json& baseline, const std::string& workDir);
    /// The verdict, cells, details and record of what run() counted: no valgrind, so the rules can be
    /// tested on counts made by hand.
    static InstructionLayerResult judge(const InstructionInputs& in);
    /// The base of `config` in a committed record: its counts and the fingerprint it was counted under
    /// (its own where the record keeps one, else the record's); empty when the record lacks it.
    static std::optional<InstructionSample> committed(const nlohmann::json& record,
                                                      const std::string& config);
};

} // namespace sb
