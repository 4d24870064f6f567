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

InstructionSample measureOne(const CiSuite& suite, const CiConfig& c, const CiSide& side,
                             const std::string& dir) {
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

InstructionSample measure(const CiSuite& suite, const CiConfig& c, const CiSide& side, const std::string& dir,
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
std::string abMismatch(const Fingerprint& base, const Fingerprint& head,
                       const std::set<std::string>& tested) {
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

std::string listed(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& i : items) out += (out.empty() ? "" : ", ") + i;
    return out;
}

/// Why configuration `i` is not compared ("" when it is): its base's fingerprint differs from its head's.
/// `invalidAB` is set when the sides of a measured base differ beyond the driver (a failure, not the
/// instrument's limit).
std::string fingerprintMismatch(const InstructionInputs& in, size_t i, std::vector<std::string>& details,
                                bool& invalidAB) {
    const Fingerprint& head = in.heads[i].fingerprint;
    const Fingerprint& base = in.bases[i]->fingerprint;
    const std::vector<std::string> differences = base.differences(head);
    if (differences.empty()) return "";
    if (!in.measuredBase)
        return "the baseline was counted on another machine or toolchain (" + listed(differences) +
               "): instructions are compared on one fingerprint only";
    details.push_back(in.configs[i] + ": base and head fingerprints differ in: " + listed(differences));
    const std::string mismatch = abMismatch(base, head, in.tested);
    invalidAB |= !mismatch.empty();
    return mismatch;
}

} // namespace

std::optional<InstructionSample> InstructionLayer::committed(const nlohmann::json& record,
                                                             const std::string& config) {
    if (record.is_null() || !record.contains("configs") || !record["configs"].contains(config)) return {};
    const nlohmann::json& entry = record["configs"][config];
    const nlohmann::json& fingerprint =
        entry.contains("fingerprint") ? entry["fingerprint"] : record.at("fingerprint");
    return InstructionSample{TechniqueInstructions::fromJson(entry, "the instruction baseline, " + config),
                             Fingerprint::fromJson(fingerprint, "the instruction baseline, " + config)};
}

InstructionLayerResult InstructionLayer::judge(const InstructionInputs& in) {
    InstructionLayerResult out;
    out.layer.name = "B: instructions per frame";
    out.layer.ran = true;
    const double aa = std::abs(in.again.counts.irPerFrame / in.heads.front().counts.irPerFrame - 1.0);
    const bool unstable = aa > kUnstableAbove;
    const double threshold = std::max(kFloor, aa);
    char aaText[160];
    std::snprintf(aaText, sizeof aaText,
                  "A/A pair (%s twice): %.3g relative difference of Ir per frame (limit %.0e); threshold %s",
                  in.configs.front().c_str(), aa, kUnstableAbove, pct(threshold).c_str());
    out.layer.details.push_back(aaText);
    // The record: the first configuration's fingerprint for the whole, and each configuration's own where
    // it differs (another API, a configuration counted in a job of its own).
    out.record["fingerprint"] = in.heads.front().fingerprint.toJson();
    for (size_t i = 0; i < in.configs.size(); ++i) {
        out.record["configs"][in.configs[i]] = in.heads[i].counts.toJson(60);
        if (!in.heads[i].fingerprint.differences(in.heads.front().fingerprint).empty())
            out.record["configs"][in.configs[i]]["fingerprint"] = in.heads[i].fingerprint.toJson();
    }

    std::string noVerdict; // of the whole layer
    if (unstable)
        noVerdict = "instrument unstable: the A/A pair disagrees by more than " + pct(kUnstableAbove);
    if (!in.measuredBase && !in.haveRecord)
        noVerdict = "no instruction baseline yet (bench ci --update writes one)";
    bool failed = false, invalidAB = false;
    size_t compared = 0;
    std::vector<std::string> notCompared;
    for (size_t i = 0; i < in.configs.size(); ++i) {
        LayerCell cell;
        const TechniqueInstructions& h = in.heads[i].counts;
        char perFrame[64];
        std::snprintf(perFrame, sizeof perFrame, "%.4g Ir/frame", h.irPerFrame);
        const std::string mismatch =
            noVerdict.empty() && in.bases[i] ? fingerprintMismatch(in, i, out.layer.details, invalidAB) : "";
        if (!noVerdict.empty() || !mismatch.empty()) {
            cell = {perFrame, "NO VERDICT"};
            if (!mismatch.empty()) notCompared.push_back(in.configs[i] + ": " + mismatch);
        } else if (!in.bases[i]) {
            // Not compared, and the record could have held it: like a configuration missing from layer A's
            // baseline, a failure with its reason rather than a silent gap.
            cell = {std::string(perFrame) + "; not in the instruction baseline", "FAIL"};
            failed = true;
            out.layer.details.push_back(in.configs[i] +
                                        ": not in the instruction baseline (add it with bench ci --update)");
        } else {
            ++compared;
            const TechniqueInstructions& b = in.bases[i]->counts;
            const InstructionDiff d = InstructionDiff::compare(b, in.measuredBase ? h : cutLike(h, b), 5);
            const double change = d.relativeChange();
            const bool fail = change > threshold;
            failed |= fail;
            cell = {pct(change) + ", " + perFrame, fail ? "FAIL" : "PASS"};
            out.layer.details.push_back(in.configs[i] + ": " + pct(change) +
                                        " Ir per frame; by where (Ir/frame): " + categoryChanges(b, h) +
                                        "; top functions: " + topChanges(d, 5));
        }
        out.cells.emplace_back(in.configs[i], cell);
    }
    // A layer that compared nothing gives no verdict, with every reason; one that compared some judges
    // those, and the others' cells say NO VERDICT with their reasons listed.
    if (noVerdict.empty() && compared == 0 && !failed && !notCompared.empty())
        noVerdict = listed(notCompared);
    else
        for (const std::string& n : notCompared) out.layer.details.push_back("not compared: " + n);
    if (!noVerdict.empty()) out.layer.details.push_back("no verdict: " + noVerdict);
    out.layer.verdict = failed ? "FAIL" : !noVerdict.empty() || invalidAB ? "NO VERDICT" : "PASS";
    // The instrument's reasons (unstable, no record, another machine's record) are reported, never an
    // alarm (GateReport.h); an A/B whose sides differ beyond the driver compared nothing and fails.
    out.layer.declined = out.layer.verdict == "NO VERDICT" && !invalidAB;
    return out;
}

InstructionLayerResult InstructionLayer::run(const CiSuite& suite,
                                             const std::vector<const CiConfig*>& configs,
                                             const std::optional<CiSide>& base, const CiSide& head,
                                             const nlohmann::json& baseline, const std::string& workDir) {
    if (!InstructionCount::valgrindAvailable())
        throw Error(
            "layer B needs valgrind (scripts/install-deps.sh installs it); run --layers A,C without it",
            ExitCode::Unsupported);
    InstructionInputs in;
    // Every configuration on the head, the A/A pair's second run, and with a base each on the base.
    ProgressBar bar(stderr, configs.size() * (base ? 2 : 1) + 1, 0);
    for (const CiConfig* c : configs) {
        in.configs.push_back(c->name);
        in.heads.push_back(measure(suite, *c, head, workDir + "/" + c->name, bar));
    }
    // The A/A pair: the first configuration again, in the same job.
    in.again = measure(suite, *configs.front(), head, workDir + "/" + configs.front()->name + "_again", bar);
    in.bases.resize(configs.size());
    if (base) {
        in.measuredBase = true;
        for (const CiSide* side : {&*base, &head})
            for (const auto& [k, v] : side->env) in.tested.insert(k);
        for (size_t i = 0; i < configs.size(); ++i)
            in.bases[i] = measure(suite, *configs[i], *base, workDir + "/" + configs[i]->name + "_base", bar);
    } else if (!baseline.is_null()) {
        in.haveRecord = true;
        for (size_t i = 0; i < configs.size(); ++i) in.bases[i] = committed(baseline, configs[i]->name);
    }
    bar.close();
    return judge(in);
}

} // namespace sb
