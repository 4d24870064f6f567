#include "bench/lib/gate/InstructionLayer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "bench/lib/callgrind/InstructionCount.h"
#include "bench/lib/callgrind/InstructionDiff.h"
#include "bench/lib/gate/Fingerprint.h"
#include "bench/lib/output/ProgressBar.h"
#include "core/Error.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

struct Measured {
    TechniqueInstructions counts;
    Fingerprint fingerprint;
};

Measured measureOne(const CiSuite& suite, const CiConfig& c, const CiSide& side, const std::string& dir) {
    InstructionCount::Options o;
    o.bench = side.bench;
    o.benchArgs = SuiteRunner::benchArgs(suite, c, suite.instructions.frames, suite.instructions.warmup);
    o.outDir = dir;
    for (const auto& [k, v] : side.env) o.environment[k] = v; // a driver A/B's variable wins over the pin
    const InstructionRun run = InstructionCount(o).run();
    if (run.techniques.size() != 1 || run.rows.empty())
        throw Error("ci config '" + c.name + "': expected one technique under valgrind", ExitCode::Failure);
    return {run.techniques[0],
            Fingerprint::capture(run.rows[0], InstructionCount::valgrindVersion(), o.environment)};
}

Measured measure(const CiSuite& suite, const CiConfig& c, const CiSide& side, const std::string& dir,
                 ProgressBar& bar) {
    return bar.step("instructions " + c.name + " (" + side.describe() + ", under valgrind)",
                    [&] { return measureOne(suite, c, side, dir); });
}

std::string pct(double fraction) {
    char b[32];
    std::snprintf(b, sizeof b, "%+.3f%%", 100.0 * fraction);
    return b;
}

std::string topChanges(const InstructionDiff& d, size_t n) {
    std::string out;
    size_t shown = 0;
    for (const FunctionDelta& f : d.functions) {
        if (shown == n || f.deltaIrPerFrame() == 0.0) continue; // unchanged functions say nothing
        ++shown;
        char b[64];
        std::snprintf(b, sizeof b, "%+.0f", f.deltaIrPerFrame());
        out +=
            (out.empty() ? "" : "; ") + f.function + " (" + fs::path(f.object).filename().string() + ") " + b;
    }
    return out.empty() ? "none" : out;
}

/// A committed record keeps only its top functions. The head's functions are cut the same way before
/// the diff: those the record has, and those at least as large as its smallest (they would be in it had
/// they been as large in the base); else every small function outside the record reads as "new".
TechniqueInstructions cutLike(TechniqueInstructions head, const TechniqueInstructions& record) {
    if (record.functions.empty()) return head;
    uint64_t smallest = record.functions.front().ir;
    for (const FunctionIr& f : record.functions) smallest = std::min(smallest, f.ir);
    const double scale = record.frames > 0 && head.frames > 0 ? double(head.frames) / record.frames : 1.0;
    std::erase_if(head.functions, [&](const FunctionIr& f) {
        const bool inRecord =
            std::any_of(record.functions.begin(), record.functions.end(), [&](const FunctionIr& r) {
                return r.function == f.function &&
                       fs::path(r.object).filename() == fs::path(f.object).filename();
            });
        return !inRecord && double(f.ir) < double(smallest) * scale;
    });
    return head;
}

/// Ir per frame change by where the code lives: "shader_jit +1200, mesa -30".
std::string categoryChanges(const TechniqueInstructions& base, const TechniqueInstructions& head) {
    std::string out;
    for (int c = 0; c < kCostCategoryCount; ++c) {
        const double b = base.frames > 0 ? double(base.byCategory[c]) / base.frames : 0.0;
        const double h = head.frames > 0 ? double(head.byCategory[c]) / head.frames : 0.0;
        if (b == h) continue;
        char text[64];
        std::snprintf(text, sizeof text, "%s %+.0f", costCategoryName(CostCategory(c)), h - b);
        out += (out.empty() ? "" : ", ") + std::string(text);
    }
    return out.empty() ? "none" : out;
}

/// Why a base measured now cannot be compared with the head ("" when it can): their fingerprints may
/// differ in the driver and the variables the sides set, nothing else. Seen: Mesa 25.0.7's EGL does not
/// load under the pinned LD_BIND_NOW=1, so its side fell back to the osmesa backend and would have been
/// compared with 22.3.6 on egl-surfaceless.
std::string abMismatch(const Fingerprint& base, const Fingerprint& head, const CiSide& baseSide,
                       const CiSide& headSide) {
    std::set<std::string> tested;
    for (const CiSide* side : {&baseSide, &headSide})
        for (const auto& [k, v] : side->env) tested.insert(k);
    const std::vector<std::string> besides = base.differencesBesidesDriver(head, tested);
    if (besides.empty()) return "";
    std::string list;
    for (const std::string& d : besides) list += (list.empty() ? "" : ", ") + d;
    // The pin's LD_BIND_NOW=1 is what made 25.0.7's EGL fail to load; unset on both sides it loads.
    const std::string backends =
        base.backend == head.backend
            ? ""
            : " (backend " + base.backend + " against " + head.backend +
                  "; a driver whose EGL does not load under the pinned LD_BIND_NOW=1 "
                  "falls back to osmesa: try --base-env LD_BIND_NOW= --head-env "
                  "LD_BIND_NOW=)";
    return "base and head differ in " + list + backends +
           " besides the driver and the variables under test: their instructions would be of different "
           "code paths";
}

} // namespace

InstructionLayerResult InstructionLayer::run(const CiSuite& suite,
                                             const std::vector<const CiConfig*>& configs,
                                             const std::optional<CiSide>& base, const CiSide& head,
                                             const nlohmann::json& baseline, const std::string& workDir) {
    InstructionLayerResult out;
    out.layer.name = "B: instructions per frame";
    out.layer.ran = true;
    if (!InstructionCount::valgrindAvailable())
        throw Error(
            "layer B needs valgrind (scripts/install-deps.sh installs it); run --layers A,C without it",
            ExitCode::Unsupported);
    std::vector<Measured> heads;
    // Every configuration on the head, the A/A pair's second run, and with a base each on the base.
    ProgressBar bar(stderr, configs.size() * (base ? 2 : 1) + 1, 0);
    for (const CiConfig* c : configs) heads.push_back(measure(suite, *c, head, workDir + "/" + c->name, bar));
    // The A/A pair: the first configuration again, in the same job.
    const Measured again =
        measure(suite, *configs.front(), head, workDir + "/" + configs.front()->name + "_again", bar);
    const double aa = std::abs(again.counts.irPerFrame / heads.front().counts.irPerFrame - 1.0);
    const bool unstable = aa > kUnstableAbove;
    const double threshold = std::max(kFloor, aa);
    char aaText[160];
    std::snprintf(aaText, sizeof aaText,
                  "A/A pair (%s twice): %.3g relative difference of Ir per frame (limit %.0e); threshold %s",
                  configs.front()->name.c_str(), aa, kUnstableAbove, pct(threshold).c_str());
    out.layer.details.push_back(aaText);
    out.record["fingerprint"] = heads.front().fingerprint.toJson();
    for (size_t i = 0; i < configs.size(); ++i)
        out.record["configs"][configs[i]->name] = heads[i].counts.toJson(60);

    std::optional<Fingerprint> baseFingerprint;
    std::vector<std::optional<TechniqueInstructions>> bases(configs.size());
    if (base) {
        for (size_t i = 0; i < configs.size(); ++i) {
            const Measured m =
                measure(suite, *configs[i], *base, workDir + "/" + configs[i]->name + "_base", bar);
            bases[i] = m.counts;
            baseFingerprint = m.fingerprint;
        }
    } else if (!baseline.is_null()) {
        baseFingerprint = Fingerprint::fromJson(baseline.at("fingerprint"), "the instruction baseline");
        for (size_t i = 0; i < configs.size(); ++i)
            if (baseline.contains("configs") && baseline["configs"].contains(configs[i]->name))
                bases[i] = TechniqueInstructions::fromJson(baseline["configs"][configs[i]->name],
                                                           "the instruction baseline, " + configs[i]->name);
    }
    bar.close();
    std::string noVerdict;
    bool invalidAB = false; // base and head differ beyond the driver: not the instrument's doing
    if (unstable)
        noVerdict = "instrument unstable: the A/A pair disagrees by more than " + pct(kUnstableAbove);
    if (!baseFingerprint) noVerdict = "no instruction baseline yet (bench ci --update writes one)";
    const auto differences = baseFingerprint ? baseFingerprint->differences(heads.front().fingerprint)
                                             : std::vector<std::string>{};
    if (!differences.empty()) {
        std::string list;
        for (const std::string& d : differences) list += (list.empty() ? "" : ", ") + d;
        if (base) out.layer.details.push_back("base and head fingerprints differ in: " + list);
        if (base && noVerdict.empty())
            noVerdict = abMismatch(*baseFingerprint, heads.front().fingerprint, *base, head);
        invalidAB = base && !noVerdict.empty() && !unstable;
        if (!base && noVerdict.empty())
            noVerdict = "the baseline was counted on another machine or toolchain (" + list +
                        "): instructions are compared on one fingerprint only";
    }
    bool failed = false;
    for (size_t i = 0; i < configs.size(); ++i) {
        LayerCell cell;
        const TechniqueInstructions& h = heads[i].counts;
        char perFrame[64];
        std::snprintf(perFrame, sizeof perFrame, "%.4g Ir/frame", h.irPerFrame);
        if (!noVerdict.empty()) {
            cell = {perFrame, "NO VERDICT"};
        } else if (!bases[i]) {
            // Not compared, and the record could have held it: like a configuration missing from layer A's
            // baseline, a failure with its reason rather than a silent gap.
            cell = {std::string(perFrame) + "; not in the instruction baseline", "FAIL"};
            failed = true;
            out.layer.details.push_back(configs[i]->name +
                                        ": not in the instruction baseline (add it with bench ci --update)");
        } else {
            const InstructionDiff d =
                InstructionDiff::compare(*bases[i], base ? h : cutLike(h, *bases[i]), 5);
            const double change = d.relativeChange();
            const bool fail = change > threshold;
            failed |= fail;
            cell = {pct(change) + ", " + perFrame, fail ? "FAIL" : "PASS"};
            out.layer.details.push_back(
                configs[i]->name + ": " + pct(change) + " Ir per frame; by where (Ir/frame): " +
                categoryChanges(*bases[i], h) + "; top functions: " + topChanges(d, 5));
        }
        out.cells.emplace_back(configs[i]->name, cell);
    }
    if (!noVerdict.empty()) out.layer.details.push_back("no verdict: " + noVerdict);
    out.layer.verdict = !noVerdict.empty() ? "NO VERDICT" : failed ? "FAIL" : "PASS";
    // The instrument's reasons (unstable, no record, another machine's record) are reported, never an
    // alarm (GateReport.h); an A/B whose sides differ beyond the driver compared nothing and fails.
    out.layer.declined = !noVerdict.empty() && !invalidAB;
    return out;
}

} // namespace sb
