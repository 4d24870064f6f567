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
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/callgrind/TechniqueInstructions.h"
#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/SuiteRunner.h"

namespace sb {

struct InstructionLayerResult {
    GateLayer layer;
    std::vector<std::pair<std::string, LayerCell>> cells;
    nlohmann::json
        record; ///< {"fingerprint", "configs": {name: TechniqueInstructions::toJson}}: the baseline format
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
};

} // namespace sb
