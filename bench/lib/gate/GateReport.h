#pragma once
// What the perf gate found, per layer and per configuration, as one Markdown block (for a CI log or a
// pull-request comment) and as JSON (for dashboards). Layers named advisory are reported the same way
// but cannot fail the gate. The gate's verdict:
// - FAIL when a gating layer failed, or a gating layer gave NO VERDICT (it compared nothing: its inputs
//   held nothing comparable, which is never a pass) unless the layer `declined` (its instrument cannot
//   judge on this machine, e.g. layer B against an instruction baseline counted on another CPU: said so,
//   never an alarm);
// - NO VERDICT when no gating layer judged anything (all declined, advisory or not run): this also exits
//   as a failure, since nothing was compared;
// - PASS otherwise: at least one gating layer compared and none failed.
// A configuration's cell reads PASS only when that configuration was compared; otherwise it says what
// happened ("not compared: only in the base", "driver work differs (explained)").
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
    /// With NO VERDICT: the instrument cannot judge here (see the header comment), so it does not fail.
    bool declined = false;
};

struct GateReport {
    std::string title;              ///< "shadowbench perf gate"
    std::vector<std::string> about; ///< suite, base, head, fingerprint lines
    std::vector<GateConfigRow> rows;
    std::vector<GateLayer> layers;
    std::string reproduce; ///< the command line

    /// "FAIL", "NO VERDICT" or "PASS" (see the header comment).
    std::string verdict() const;
    /// verdict() is not PASS.
    bool failed() const;
    std::string markdown() const;
    nlohmann::json json() const;
};

} // namespace sb
