#pragma once
// What the perf gate found, per layer and per configuration, as one Markdown block (for a CI log or a
// pull-request comment) and as JSON (for dashboards). The verdict of the gate is FAIL when a gating
// layer failed; layers named advisory are reported the same way but cannot fail it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sb {

/// One layer's judgement of one configuration.
struct LayerCell {
    std::string summary; ///< short: "+12.0% depth_fragments", "-0.3%", "1.21 [0.95, 1.40] p=0.004"
    std::string verdict; ///< PASS, FAIL, INCONCLUSIVE, NO VERDICT, "" when the layer did not run it
};

struct GateConfigRow {
    std::string config, bound;
    LayerCell work, instructions, wall;
};

/// One layer's overall result with its detail lines (the diff per pass, top functions, the control).
struct GateLayer {
    std::string name; ///< "A: exact work", "B: instructions per frame", "C: wall time"
    bool ran = false;
    bool advisory = false;
    std::string verdict; ///< PASS, FAIL, INCONCLUSIVE, NO VERDICT
    std::vector<std::string> details;
};

struct GateReport {
    std::string title;              ///< "shadowbench perf gate"
    std::vector<std::string> about; ///< suite, base, head, fingerprint lines
    std::vector<GateConfigRow> rows;
    std::vector<GateLayer> layers;
    std::string reproduce; ///< the command line

    /// FAIL when a non-advisory layer failed, else PASS.
    bool failed() const;
    std::string markdown() const;
    nlohmann::json json() const;
};

} // namespace sb
