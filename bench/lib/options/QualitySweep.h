#pragma once
// Expands technique specs into the configurations of `bench accuracy --sweep`: the spec itself, then
// each quality knob the technique declares (TechniqueInfo::quality) varied alone over its values with
// every other property as given. One knob at a time keeps the sweep linear in the number of values
// (a full product of shadowmap's knobs would be 180 runs) while still drawing each knob's curve.
#include <vector>

#include "techniques/PropertySet.h"

namespace sb {

class QualitySweep {
public:
    /// Deduplicated by canonical properties; order: the base spec first, then knob by knob.
    static std::vector<TechniqueSpec> expand(const TechniqueSpec& spec);
    /// expand() of each spec in turn: the configurations `bench accuracy --sweep` runs.
    static std::vector<TechniqueSpec> expandAll(const std::vector<TechniqueSpec>& specs);
};

} // namespace sb
