#pragma once
// The command-line options of everything that builds a sweep (`bench sweep`, `bench bottleneck`): the
// axes as comma lists, the options passed through to every run, and how they land in a
// SweepDefinition. The command line replaces what the definition says: the file's value of an axis
// it names, its rounds, and its value of every pass-through option it gives (--frames, --warmup ...).
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/lib/sweep/SweepDefinition.h"

namespace sb {

class SweepOptions {
public:
    std::vector<std::string> techniques;
    std::string scenes, instances, scale, tess, tessFactor, submit, camera, size, light;
    std::vector<std::string> passThrough; ///< options given to every run, in command-line order
    std::optional<int> repeat;            ///< --repeat, set only when given

    /// Registers -t, --scene, --instances ... --light, --repeat and the pass-through options.
    void add(CLI::App& app);
    /// Writes what was given into `d`: given axes and --repeat replace d's (a --repeat outside 1..1000
    /// throws sb::Error naming it, as the definition file's "repeat" does); each given pass-through
    /// option first removes d's own occurrences of it from d.commonArgs ("--frames 20", "--frames=20";
    /// --frames and --seconds, two ways to set one budget, remove each other), then is appended.
    void applyTo(SweepDefinition& d) const;
    /// True when the pass-through options include `option` (e.g. "--frames").
    bool passes(const std::string& option) const;
};

} // namespace sb
