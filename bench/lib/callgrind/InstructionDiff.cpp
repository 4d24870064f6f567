#include "bench/lib/callgrind/InstructionDiff.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/Error.h"

namespace sb {

namespace {

using Key = std::pair<std::string, std::string>;

std::map<Key, double> perFrame(const TechniqueInstructions& t, const char* side) {
    if (t.frames <= 0)
        throw Error("InstructionDiff: " + std::string(side) + " count of '" + t.technique +
                    "' has no frames");
    std::map<Key, double> out;
    for (const FunctionIr& f : t.functions) {
        const bool jit = classifyObject(f.object, "") == CostCategory::ShaderJit;
        const Key key = jit ? Key{"???", "[shader JIT]"}
                            : Key{std::filesystem::path(f.object).filename().string(), f.function};
        out[key] += double(f.ir) / double(t.frames);
    }
    return out;
}

} // namespace

double InstructionDiff::relativeChange() const {
    return baseIrPerFrame == 0 ? 0.0 : (newIrPerFrame - baseIrPerFrame) / baseIrPerFrame;
}

nlohmann::json InstructionDiff::toJson() const {
    nlohmann::json list = nlohmann::json::array();
    for (const FunctionDelta& f : functions)
        list.push_back({{"object", f.object},
                        {"function", f.function},
                        {"base_ir_per_frame", f.baseIrPerFrame},
                        {"new_ir_per_frame", f.newIrPerFrame},
                        {"delta_ir_per_frame", f.deltaIrPerFrame()}});
    return {{"technique", technique},
            {"base_ir_per_frame", baseIrPerFrame},
            {"new_ir_per_frame", newIrPerFrame},
            {"relative_change", relativeChange()},
            {"functions", list}};
}

InstructionDiff InstructionDiff::compare(const TechniqueInstructions& base,
                                         const TechniqueInstructions& current, size_t topN) {
    InstructionDiff d;
    d.technique = current.technique;
    const std::map<Key, double> a = perFrame(base, "base"), b = perFrame(current, "new");
    d.baseIrPerFrame = base.irPerFrame;
    d.newIrPerFrame = current.irPerFrame;
    std::map<Key, FunctionDelta> all;
    for (const auto& [key, ir] : a) all[key] = {key.first, key.second, ir, 0.0};
    for (const auto& [key, ir] : b) {
        auto [it, inserted] = all.try_emplace(key, FunctionDelta{key.first, key.second, 0.0, ir});
        if (!inserted) it->second.newIrPerFrame = ir;
    }
    for (auto& [key, delta] : all) d.functions.push_back(delta);
    // Ties (equal |delta|) keep the map's name order, so the list is the same on every run.
    std::stable_sort(d.functions.begin(), d.functions.end(),
                     [](const FunctionDelta& x, const FunctionDelta& y) {
                         return std::abs(x.deltaIrPerFrame()) > std::abs(y.deltaIrPerFrame());
                     });
    if (d.functions.size() > topN) d.functions.resize(topN);
    return d;
}

} // namespace sb
