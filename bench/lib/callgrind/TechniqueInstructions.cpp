#include "bench/lib/callgrind/TechniqueInstructions.h"

#include "core/Error.h"

namespace sb {

std::vector<FunctionIr> TechniqueInstructions::top(size_t n) const {
    return {functions.begin(), functions.begin() + std::min(n, functions.size())};
}

double TechniqueInstructions::fraction(CostCategory category) const {
    return totalIr == 0 ? 0.0 : double(byCategory[int(category)]) / double(totalIr);
}

nlohmann::json TechniqueInstructions::toJson(size_t topN) const {
    nlohmann::json categories = nlohmann::json::object();
    for (int c = 0; c < kCostCategoryCount; ++c)
        categories[costCategoryName(CostCategory(c))] = byCategory[c];
    nlohmann::json topFunctions = nlohmann::json::array();
    for (const FunctionIr& f : top(topN))
        topFunctions.push_back({{"object", f.object}, {"function", f.function}, {"ir", f.ir}});
    return {{"technique", technique},       {"properties", properties},   {"frames", frames},
            {"total_ir", totalIr},          {"ir_per_frame", irPerFrame}, {"categories", categories},
            {"top_functions", topFunctions}};
}

TechniqueInstructions TechniqueInstructions::fromJson(const nlohmann::json& j, const std::string& source) {
    try {
        TechniqueInstructions t;
        t.technique = j.at("technique").get<std::string>();
        t.properties = j.at("properties").get<std::string>();
        t.frames = j.at("frames").get<int>();
        t.totalIr = j.at("total_ir").get<uint64_t>();
        t.irPerFrame = j.at("ir_per_frame").get<double>();
        for (int c = 0; c < kCostCategoryCount; ++c)
            t.byCategory[c] = j.at("categories").value(costCategoryName(CostCategory(c)), uint64_t(0));
        for (const auto& f : j.at("top_functions"))
            t.functions.push_back({f.at("object").get<std::string>(), f.at("function").get<std::string>(),
                                   f.at("ir").get<uint64_t>()});
        return t;
    } catch (const nlohmann::json::exception& e) {
        throw Error(source + ": not an instruction record (" + e.what() + ")");
    }
}

TechniqueInstructions TechniqueInstructions::fromDump(const CallgrindDump& dump, const std::string& technique,
                                                      const std::string& properties, int frames,
                                                      const std::string& harness) {
    TechniqueInstructions t;
    t.technique = technique;
    t.properties = properties;
    t.frames = frames;
    t.totalIr = dump.totalIr;
    t.irPerFrame = frames > 0 ? double(dump.totalIr) / double(frames) : 0.0;
    t.functions = dump.functions;
    for (const FunctionIr& f : dump.functions) t.byCategory[int(classifyObject(f.object, harness))] += f.ir;
    return t;
}

} // namespace sb
