#include "bench/lib/gate/GateReport.h"

namespace sb {

namespace {

std::string cellText(const LayerCell& c) {
    if (c.verdict.empty()) return "-";
    return c.summary.empty() ? c.verdict : c.summary + " (" + c.verdict + ")";
}

nlohmann::json cellJson(const LayerCell& c) {
    if (c.verdict.empty()) return nullptr;
    return {{"summary", c.summary}, {"verdict", c.verdict}};
}

} // namespace

std::string GateReport::verdict() const {
    bool judged = false;
    for (const GateLayer& l : layers) {
        if (!l.ran || l.advisory) continue;
        const bool noVerdict = l.verdict == "NO VERDICT";
        if (l.verdict == "FAIL" || (noVerdict && !l.declined)) return "FAIL";
        judged |= !noVerdict;
    }
    return judged ? "PASS" : "NO VERDICT";
}

bool GateReport::failed() const {
    return verdict() != "PASS";
}

std::string GateReport::markdown() const {
    std::string out = "## " + title + ": " + verdict() + "\n\n";
    if (verdict() == "NO VERDICT") out += "No gating layer compared anything: this is not a pass.\n\n";
    for (const std::string& a : about) out += "- " + a + "\n";
    out += "\n| config | bound | A: exact work | B: instructions/frame | C: wall time ratio |\n";
    out += "|---|---|---|---|---|\n";
    for (const GateConfigRow& r : rows)
        out += "| " + r.config + " | " + r.bound + " | " + cellText(r.work) + " | " +
               cellText(r.instructions) + " | " + cellText(r.wall) + " |\n";
    for (const GateLayer& l : layers) {
        std::string note;
        if (l.ran && l.verdict == "NO VERDICT")
            note = l.declined ? " (declined: the instrument cannot judge here; not a failure)"
                              : " (nothing was compared: fails the gate)";
        out += "\n### " + l.name + ": " + (l.ran ? l.verdict : std::string("not run")) +
               (l.advisory ? " (advisory)" : "") + note + "\n\n";
        for (const std::string& d : l.details) out += "- " + d + "\n";
    }
    out += "\nReproduce: `" + reproduce + "`\n";
    return out;
}

nlohmann::json GateReport::json() const {
    nlohmann::json j;
    j["title"] = title;
    j["verdict"] = verdict();
    j["about"] = about;
    j["reproduce"] = reproduce;
    for (const GateConfigRow& r : rows)
        j["configs"].push_back({{"config", r.config},
                                {"bound", r.bound},
                                {"work", cellJson(r.work)},
                                {"instructions", cellJson(r.instructions)},
                                {"wall", cellJson(r.wall)}});
    for (const GateLayer& l : layers)
        j["layers"].push_back({{"name", l.name},
                               {"ran", l.ran},
                               {"advisory", l.advisory},
                               {"verdict", l.ran ? l.verdict : "not run"},
                               {"declined", l.declined},
                               {"details", l.details}});
    return j;
}

} // namespace sb
