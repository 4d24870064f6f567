// libFuzzer target: a sweep definition file's text (bench/lib/sweep/SweepDefinition.h) as
// SweepDefinition::fromJsonFile reads it (plain JSON, then fromJson), and the plan it expands to
// (expand(): every technique spec, scene, camera and combination of run options validated). Bad input
// must end in sb::Error. Seeds: fuzz/corpus/sweep_definition/ (sweeps/*.json and the tests' sweeps).
//
// expand() loads every scene of the "scenes" axis and visits every combination of the axes, so it runs
// only where that stays cheap and in memory: the scenes named are built-in ones (a name can also be a
// file path: see SceneLoaderFuzz.cpp for why paths stay out) and the product, techniques included, is
// at most kMaxCombinations. Larger inputs still go through fromJson.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/lib/sweep/SweepDefinition.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "fuzz/FuzzReach.h"
#include "scenes/SceneLoader.h"

namespace {

constexpr size_t kMaxCombinations = 8;

/// The number of runs expand() would visit, saturating above kMaxCombinations.
size_t combinations(const sb::SweepDefinition& d) {
    const sb::SweepAxes& a = d.axes;
    size_t n = 1;
    for (const auto* axis : {&a.techniques, &a.scenes, &a.instances, &a.scale, &a.tess, &a.tessFactor,
                             &a.submit, &a.camera, &a.size, &a.light}) {
        n *= std::max<size_t>(axis->size(), 1);
        if (n > kMaxCombinations) return kMaxCombinations + 1;
    }
    // A comma list inside a technique spec is an axis of its own: "shadowmap:pcf=1,3" counts twice.
    for (const std::string& t : a.techniques) {
        n *= std::max<size_t>(1, size_t(std::count(t.begin(), t.end(), ',')) + 1);
        if (n > kMaxCombinations) return kMaxCombinations + 1;
    }
    return n;
}

bool onlyBuiltinScenes(const sb::SweepDefinition& d) {
    static const std::vector<std::string> builtin = sb::SceneLoader::listBuiltinScenes();
    return std::all_of(d.axes.scenes.begin(), d.axes.scenes.end(), [](const std::string& s) {
        return std::find(builtin.begin(), builtin.end(), s) != builtin.end();
    });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text = sb::fuzz::text(data, size);
    const char* const source = "fuzz-sweep.json";
    try {
        // What fromJsonFile does with the file's text (it takes only a path).
        const nlohmann::json doc = sb::JsonReader::parse(text, source);
        const sb::SweepDefinition definition = sb::SweepDefinition::fromJson(doc, source, "", "fuzz-sweep");
        if (combinations(definition) > kMaxCombinations || !onlyBuiltinScenes(definition)) {
            sb::fuzz::reached(sb::fuzz::Outcome::Parsed, "definition only (not expanded)");
            return 0;
        }
        const sb::SweepPlan plan = definition.expand();
        sb::fuzz::reached(sb::fuzz::Outcome::Parsed, std::to_string(plan.configCount()) + " configurations");
    } catch (const sb::Error& e) {
        sb::fuzz::reached(sb::fuzz::Outcome::Rejected, e.what());
    }
    return 0;
}
