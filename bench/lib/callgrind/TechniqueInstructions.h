#pragma once
// The instructions one technique's measured frames retired under callgrind: layer B of the performance
// gate. llvmpipe runs on the CPU, so this count is a near-deterministic cost (two identical runs differ
// by about 1e-6), unlike wall time.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/lib/callgrind/CallgrindDump.h"
#include "bench/lib/callgrind/CostCategory.h"

namespace sb {

struct TechniqueInstructions {
    std::string technique;   ///< the row's technique (and the dump's name)
    std::string properties;  ///< the row's properties ("" when none)
    int frames = 0;          ///< measured frames of the row (the frames between the client requests)
    uint64_t totalIr = 0;    ///< instructions retired in those frames, every thread, every object
    double irPerFrame = 0;   ///< totalIr / frames
    CategoryIr byCategory{}; ///< totalIr split by where the code lives (sums to totalIr)
    std::vector<FunctionIr> functions; ///< every function's self Ir, descending

    /// The `n` functions with the most self Ir.
    std::vector<FunctionIr> top(size_t n) const;
    /// Fraction of totalIr in `category` (0 when totalIr is 0).
    double fraction(CostCategory category) const;
    /// {"technique", "properties", "frames", "total_ir", "ir_per_frame", "categories": {name: Ir},
    ///  "top_functions": [{"object", "function", "ir"}...] (the first `topN`)}.
    nlohmann::json toJson(size_t topN = 20) const;

    /// The inverse of toJson (a committed baseline): `functions` holds the top functions it kept.
    /// A missing or mistyped field is sb::Error(BadInput) naming `source`.
    static TechniqueInstructions fromJson(const nlohmann::json& j, const std::string& source);
    /// One technique's numbers from its dump: `harness` is the bench binary's path (CostCategory).
    static TechniqueInstructions fromDump(const CallgrindDump& dump, const std::string& technique,
                                          const std::string& properties, int frames,
                                          const std::string& harness);
};

} // namespace sb
