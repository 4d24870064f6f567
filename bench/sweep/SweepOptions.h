#pragma once
// The command-line options of everything that builds a sweep (`bench sweep`, `bench bottleneck`): the
// axes as comma lists, the options passed through to every run, and how they land in a
// SweepDefinition (the command line replaces the file's value of an axis it names).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/sweep/SweepDefinition.h"

namespace sb {

class SweepOptions {
public:
    std::vector<std::string> techniques;
    std::string scenes, instances, scale, tess, tessFactor, submit, camera, size, light;
    std::vector<std::string> passThrough; ///< options given to every run, in command-line order
    int repeat = 0;                       ///< 0: not given

    /// Registers -t, --scene, --instances ... --light, --repeat and the pass-through options.
    void add(CLI::App& app);
    /// Writes what was given into `d`.
    void applyTo(SweepDefinition& d) const;
    /// True when the pass-through options include `option` (e.g. "--frames").
    bool passes(const std::string& option) const;
};

} // namespace sb
