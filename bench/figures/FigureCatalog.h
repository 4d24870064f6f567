#pragma once
// The reproduced figures, each declared once in results/figures/figures.json: the sweep
// behind it, how to plot it, and the claim of the source document it tests. `bench figures` reruns
// the sweeps and replots; a new technique adds its figure by adding a declaration.
//
//   [ { "name": "instances_aircraft",                 (folder under results/figures/, unique)
//       "title": "Draw time against instances, aircraft",
//       "seed": "Coleman thesis, section 6.2, Figure 25",
//       "claim": "draw time grows about linearly with the instance count ...",
//       "kind": "sweep",                              ("sweep" or "bottleneck")
//       "sweep": { ...a sweep definition, SweepDefinition.h... },
//       "plot": { "kind": "lines", "args": ["--x", "instances", "--y", "wall_ms_median"] },
//       "reduced": { ...keys replacing the sweep's for --reduced (CI: few configurations, small) } } ]
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/sweep/SweepDefinition.h"

namespace sb {

struct FigureDeclaration {
    std::string name, title, seed, claim;
    enum class Kind { Sweep, Bottleneck } kind = Kind::Sweep;
    nlohmann::json sweep;   ///< the definition as written, or an array of them (unlike workloads)
    nlohmann::json reduced; ///< keys replacing the sweep's with --reduced
    std::string plotKind;   ///< tools/plot.py subcommand: lines, pareto, bottleneck
    std::vector<std::string> plotArgs;

    /// The sweep definitions, reduced (CI) or as declared. Errors name the catalog and the figure.
    std::vector<SweepDefinition> definitions(bool reduced, const std::string& catalogPath) const;
    /// The plan of all of them (a bottleneck figure: each definition's perturbation study).
    SweepPlan plan(bool reduced, const std::string& catalogPath) const;
};

class FigureCatalog {
public:
    /// Reads and checks every declaration (unique names, known kinds, sweeps that parse).
    static std::vector<FigureDeclaration> load(const std::string& path);
    /// results/figures/figures.json of the source tree.
    static std::string defaultPath();
};

} // namespace sb
