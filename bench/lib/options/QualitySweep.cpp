#include "bench/lib/options/QualitySweep.h"

#include <set>

#include "registry/TechniqueRegistry.h"

namespace sb {

std::vector<TechniqueSpec> QualitySweep::expand(const TechniqueSpec& spec) {
    auto base = TechniqueRegistry::describe(spec); // validates the spec's own properties
    std::vector<TechniqueSpec> out{spec};
    std::set<std::string> seen{base->properties().toString()};
    for (const QualityKnob& knob : base->info().quality)
        for (const std::string& value : knob.values) {
            TechniqueSpec variant = spec;
            variant.properties.emplace_back(knob.property, value); // later entries win
            auto t = TechniqueRegistry::describe(variant);
            if (seen.insert(t->properties().toString()).second) out.push_back(variant);
        }
    return out;
}

std::vector<TechniqueSpec> QualitySweep::expandAll(const std::vector<TechniqueSpec>& specs) {
    std::vector<TechniqueSpec> out;
    for (const TechniqueSpec& spec : specs) {
        const std::vector<TechniqueSpec> expanded = expand(spec);
        out.insert(out.end(), expanded.begin(), expanded.end());
    }
    return out;
}

} // namespace sb
