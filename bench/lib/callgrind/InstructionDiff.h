#pragma once
// What changed between a base and a new instruction count of one technique: the per-frame totals and
// the functions whose per-frame instructions moved most. Per frame, so that runs of different lengths
// compare. Functions are matched by object file name (not path: two build trees' bench binaries are
// the same harness) and function name; JIT code has no stable name (callgrind names it by address), so
// all of it is one entry "[shader JIT]".
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/lib/callgrind/TechniqueInstructions.h"

namespace sb {

struct FunctionDelta {
    std::string object;   ///< file name of the object, "???" for JIT code
    std::string function; ///< "[shader JIT]" for all JIT code together
    double baseIrPerFrame = 0;
    double newIrPerFrame = 0;
    double deltaIrPerFrame() const { return newIrPerFrame - baseIrPerFrame; }
};

struct InstructionDiff {
    std::string technique;
    double baseIrPerFrame = 0;
    double newIrPerFrame = 0;
    std::vector<FunctionDelta> functions; ///< the largest |delta| first

    /// (new - base) / base, 0 when base is 0.
    double relativeChange() const;
    /// {"technique", "base_ir_per_frame", "new_ir_per_frame", "relative_change", "functions": [...]}
    nlohmann::json toJson() const;

    /// The `topN` functions by |change in Ir per frame|; functions present in only one side count with 0
    /// on the other. Both sides must have frames > 0 (Error, BadInput otherwise).
    static InstructionDiff compare(const TechniqueInstructions& base, const TechniqueInstructions& current,
                                   size_t topN = 20);
};

} // namespace sb
