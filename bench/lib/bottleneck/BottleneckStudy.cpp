#include "bench/lib/bottleneck/BottleneckStudy.h"

#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/output/TextColumns.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <ostream>

#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/statistics/Statistics.h"
#include "core/Error.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/SceneLoader.h"
#include "vk/VulkanContext.h"

namespace sb {

namespace {

namespace p = perturbation;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A group's settings as the perturbations read and change them: the worker's options and the
/// identity columns of its failed rows, kept in step.
struct Setting {
    std::vector<std::string> args;
    KeyValues columns, env;

    std::string get(const std::string& column) const {
        for (const auto& [k, v] : columns)
            if (k == column) return v;
        return "";
    }
    void set(const std::string& option, const std::string& column, const std::string& value) {
        const auto it = std::find(args.begin(), args.end(), option);
        if (it != args.end() && it + 1 != args.end())
            *(it + 1) = value;
        else
            args.insert(args.end(), {option, value});
        for (auto& [k, v] : columns)
            if (k == column) v = value;
    }
    void setSize(int w, int h) {
        set("--size", col::kWidth, std::to_string(w) + "x" + std::to_string(h));
        for (auto& [k, v] : columns) {
            if (k == col::kWidth) v = std::to_string(w);
            if (k == col::kHeight) v = std::to_string(h);
        }
    }
    double number(const std::string& column) const { return std::stod(get(column)); }
};

struct Perturbation {
    std::string name;
    std::function<void(Setting&)> apply;
};

/// The submission switch: CPU load up (immediate) or, on Vulkan, which has no immediate mode, down
/// (instanced); back to retained from a base that is already there.
Perturbation submissionSwitch(const Setting& base, bool vulkan) {
    const std::string mode = base.get(col::kSubmit);
    const bool switchBack = mode == (vulkan ? "instanced" : "immediate");
    const std::string to = switchBack ? "retained" : vulkan ? "instanced" : "immediate";
    const char* name = switchBack ? p::kSubmitRetained : vulkan ? p::kSubmitInstanced : p::kSubmitImmediate;
    return {name, [=](Setting& s) { s.set("--submit", col::kSubmit, to); }};
}

std::vector<Perturbation> perturbationsFor(const Setting& base, bool llvmpipe, bool hasNear, bool vulkan) {
    const double scale = base.number(col::kScale), factor = base.number(col::kTessFactor);
    const int w = int(base.number(col::kWidth)), h = int(base.number(col::kHeight));
    std::vector<Perturbation> out{{p::kBaseline, [](Setting&) {}}, submissionSwitch(base, vulkan)};
    if (hasNear)
        out.push_back({p::kScaleNear, [=](Setting& s) {
                           s.set("--scale", col::kScale, csvNumber(scale * 10.0));
                           s.set("--camera", col::kCamera, "near");
                       }});
    out.push_back(
        {p::kScaleSmall, [=](Setting& s) { s.set("--scale", col::kScale, csvNumber(scale * 0.01)); }});
    out.push_back({p::kSizeHalf, [=](Setting& s) { s.setSize(std::max(16, w / 2), std::max(16, h / 2)); }});
    out.push_back({p::kSizeDouble, [=](Setting& s) { s.setSize(w * 2, h * 2); }});
    out.push_back({p::kTessHalf,
                   [=](Setting& s) { s.set("--tess-factor", col::kTessFactor, csvNumber(factor * 0.5)); }});
    out.push_back({p::kTessDouble,
                   [=](Setting& s) { s.set("--tess-factor", col::kTessFactor, csvNumber(factor * 2.0)); }});
    if (llvmpipe)
        out.push_back({p::kNoRasterizer, [](Setting& s) { s.env.emplace_back("LP_NO_RAST", "1"); }});
    return out;
}

// ---- reading rows back -------------------------------------------------------------------------

class Rows {
public:
    explicit Rows(const CsvTable& t) : mTable(t) {}
    std::string get(const std::vector<std::string>& row, const std::string& column) const {
        const auto it = std::find(mTable.header.begin(), mTable.header.end(), column);
        return it == mTable.header.end() ? "" : row[size_t(it - mTable.header.begin())];
    }
    double number(const std::vector<std::string>& row, const std::string& column) const {
        const std::string s = get(row, column);
        if (s.empty()) return kNaN;
        try {
            return std::stod(s);
        } catch (const std::logic_error&) {
            return kNaN;
        }
    }
    bool has(const std::string& column) const {
        return std::find(mTable.header.begin(), mTable.header.end(), column) != mTable.header.end();
    }

private:
    const CsvTable& mTable;
};

/// The loads of a row: the census frame's, with fallbacks where the context could not count (vertex:
/// the technique's triangle counter; fill: the pixel count, unknown for the scale runs and 0 without a
/// rasteriser).
/// The vertex stage's load is the primitives submitted, not the vertex shader invocations: the
/// submission perturbation changes the invocations by itself (immediate mode has no post-transform
/// cache, so a mesh that shades 0.7 vertices per triangle retained shades 3 immediate), which would make
/// the CPU test a vertex test too; triangles are the same in every mode. And the work behind them is
/// per triangle as much as per vertex: on llvmpipe, setting up and binning a million tiny triangles
/// costs far more than shading their vertices (measured: immediate mode quadruples the invocations of
/// synthetic_triangles and adds 16% to the frame; doubling the tessellation quadruples the triangles
/// and the frame).
StageLoads loadsOf(const Rows& rows, const std::vector<std::string>& row) {
    StageLoads l;
    l.cpu = rows.number(row, col::kLoadGlCalls);
    l.vertex = rows.number(row, col::kLoadPrimitives);
    if (!std::isfinite(l.vertex)) l.vertex = rows.number(row, col::member(col::kCounter, "triangles"));
    l.fill = rows.number(row, col::kLoadFragments);
    if (!std::isfinite(l.fill)) {
        const std::string what = rows.get(row, col::kPerturbation);
        if (what == p::kNoRasterizer)
            l.fill = 0.0;
        else if (what != p::kScaleNear && what != p::kScaleSmall)
            l.fill = rows.number(row, col::kWidth) * rows.number(row, col::kHeight);
    }
    return l;
}

struct Collected {
    BottleneckEntry entry;
    std::map<std::string, std::vector<double>> walls; ///< per perturbation, over rounds
    std::map<std::string, StageLoads> loads;
    std::vector<std::string> order;
};

const char* kIdentity[] = {col::kScene,      col::kInstances, col::kScale,   col::kTessellation,
                           col::kTessFactor, col::kSubmit,    col::kCamera,  col::kWidth,
                           col::kHeight,     col::kLights,    col::kRenderer};

/// Missing evidence (a failed run) prints as "-".
std::string fmt(const char* f, double v) {
    return std::isfinite(v) ? formatNumber(f, v) : "-";
}

const char* shortName(const std::string& perturbation) {
    static const std::map<std::string, const char*> names{
        {p::kBaseline, "base"},        {p::kSubmitImmediate, "imm"}, {p::kSubmitRetained, "ret"},
        {p::kSubmitInstanced, "inst"}, {p::kScaleNear, "x10near"},   {p::kScaleSmall, "x0.01"},
        {p::kSizeHalf, "res/2"},       {p::kSizeDouble, "res*2"},    {p::kTessHalf, "tess/2"},
        {p::kTessDouble, "tess*2"},    {p::kNoRasterizer, "norast"}};
    const auto it = names.find(perturbation);
    return it == names.end() ? "?" : it->second;
}

/// The scenes of the axes that have a 'near' camera (the thesis's fill test needs one).
std::vector<std::string> scenesWithNear(const SweepDefinition& d) {
    std::vector<std::string> out;
    for (const std::string& name :
         d.axes.scenes.empty() ? std::vector<std::string>{"aircraft"} : d.axes.scenes)
        if (SceneLoader::load(name).findCamera("near")) out.push_back(name);
    return out;
}

/// Whether the workers draw with Vulkan (--api vulkan among the common arguments).
bool onVulkan(const SweepDefinition& d) {
    return RunOptions::parseArgs(d.commonArgs, RunConfig::Mode::Measure).api == RunConfig::Api::Vulkan;
}

/// Whether the workers will run on Mesa llvmpipe, or on Vulkan lavapipe, which rasterises with
/// llvmpipe's code and honours LP_NO_RAST too (measured: a fill-bound frame drops from 89 ms to 0.1 ms
/// and its fragment count to 0): then the study adds LP_NO_RAST=1.
bool onLlvmpipe(const SweepDefinition& d) {
    const RunConfig config = RunOptions::parseArgs(d.commonArgs, RunConfig::Mode::Measure);
    if (config.api != RunConfig::Api::Vulkan)
        return createContext(config.context)->renderer.find("llvmpipe") != std::string::npos;
    const std::vector<VulkanDeviceInfo> devices = VulkanContext::listDevices();
    for (const VulkanDeviceInfo& device : devices) // the harness's choice: the index, else lavapipe
        if (config.vulkan.device < 0 ? device.name.find("llvmpipe") != std::string::npos
                                     : device.index == config.vulkan.device)
            return device.name.find("llvmpipe") != std::string::npos;
    return false;
}

} // namespace

SweepPlan BottleneckStudy::plan(const SweepDefinition& base) {
    return plan(base, onLlvmpipe(base), scenesWithNear(base));
}

const std::vector<std::string>& BottleneckStudy::perturbations() {
    static const std::vector<std::string> kAll{p::kBaseline,       p::kSubmitImmediate, p::kSubmitInstanced,
                                               p::kSubmitRetained, p::kScaleNear,       p::kScaleSmall,
                                               p::kSizeHalf,       p::kSizeDouble,      p::kTessHalf,
                                               p::kTessDouble,     p::kNoRasterizer};
    return kAll;
}

SweepPlan BottleneckStudy::plan(const SweepDefinition& base, bool llvmpipe,
                                const std::vector<std::string>& scenesWithNear) {
    const SweepPlan bases = base.expand(); // validates every base combination
    const bool vulkan = onVulkan(base);
    SweepPlan out;
    out.name = bases.name;
    out.mode = bases.mode;
    out.commonArgs = bases.commonArgs;
    for (const SweepGroup& b : bases.groups) {
        const Setting setting{b.args, b.columns, {}};
        const bool hasNear =
            std::count(scenesWithNear.begin(), scenesWithNear.end(), setting.get(col::kScene)) > 0;
        for (const Perturbation& pert : perturbationsFor(setting, llvmpipe, hasNear, vulkan)) {
            Setting s = setting;
            pert.apply(s);
            out.addGroup(s.args, s.columns, b.techniques, base.repeat, s.env,
                         {{col::kPerturbation, pert.name}, {col::kStudyBase, b.describe()}});
        }
    }
    return out;
}

std::vector<BottleneckEntry> BottleneckStudy::analyse(const CsvTable& table) {
    const Rows rows(table);
    if (!rows.has(col::kPerturbation) || !rows.has(col::kStudyBase))
        throw Error("no bottleneck rows (columns 'perturbation' and 'study_base' missing)");
    std::vector<std::string> order;
    std::map<std::string, Collected> groups;
    for (const auto& row : table.rows) {
        const std::string what = rows.get(row, col::kPerturbation);
        if (what.empty()) continue;
        const std::string key = rows.get(row, col::kSweepId) + "/" + rows.get(row, col::kStudyBase) + "/" +
                                rows.get(row, col::kTechniqueSpec);
        auto [it, fresh] = groups.try_emplace(key);
        Collected& c = it->second;
        if (fresh) {
            order.push_back(key);
            c.entry.sweepId = rows.get(row, col::kSweepId);
            c.entry.studyBase = rows.get(row, col::kStudyBase);
            c.entry.techniqueSpec = rows.get(row, col::kTechniqueSpec);
        }
        if (!std::count(c.order.begin(), c.order.end(), what)) c.order.push_back(what);
        if (rows.get(row, col::kStatus) != col::kStatusOk) continue;
        c.walls[what].push_back(rows.number(row, col::kWallMsMedian));
        if (!c.loads.count(what)) c.loads[what] = loadsOf(rows, row);
        if (what == p::kBaseline && c.entry.identity.empty())
            for (const char* name : kIdentity) c.entry.identity.emplace_back(name, rows.get(row, name));
    }
    if (order.empty()) throw Error("no bottleneck rows (no row has a 'perturbation')");
    std::vector<BottleneckEntry> out;
    for (const std::string& key : order) {
        Collected& c = groups[key];
        std::vector<BottleneckRun> runs;
        for (const std::string& what : perturbations()) {
            if (!std::count(c.order.begin(), c.order.end(), what)) continue;
            const auto w = c.walls.find(what);
            // Several rounds: the median of their medians (a failed perturbation keeps NaN: reported).
            const double wall = w == c.walls.end() ? kNaN : Statistics::compute(w->second).median;
            runs.push_back({what, wall, c.loads.count(what) ? c.loads[what] : StageLoads{kNaN, kNaN, kNaN}});
            if (what == p::kBaseline) c.entry.baselineWallMs = wall;
        }
        try {
            c.entry.result = BottleneckClassifier::classify(runs);
        } catch (const Error& e) {
            c.entry.result.label = std::string("unclassified: ") + e.what();
        }
        out.push_back(std::move(c.entry));
    }
    return out;
}

void BottleneckStudy::printTable(std::ostream& os, const std::vector<BottleneckEntry>& entries) {
    TextColumns table;
    table.addRow(
        {"technique", "scene", "class", "cpu", "vert", "fill", "resid", "base ms", "T/T0 per perturbation"});
    for (const BottleneckEntry& e : entries) {
        std::string where;
        for (const auto& [k, v] : e.identity)
            if (k == "scene" || (k == "instances" && v != "0")) where += (where.empty() ? "" : " x") + v;
        const BottleneckResult& r = e.result;
        std::string evidence;
        for (const RunEvidence& ev : r.evidence)
            if (ev.perturbation != p::kBaseline)
                evidence += std::string(evidence.empty() ? "" : "  ") + shortName(ev.perturbation) + " " +
                            fmt("%.2f", ev.timeRatio) +
                            (ev.heldOut     ? "*"
                             : ev.usedInFit ? ""
                                            : "!");
        table.addRow({e.techniqueSpec, where.empty() ? "-" : where, r.label + (r.poorFit ? "?" : ""),
                      fmt("%.2f", r.shareCpu), fmt("%.2f", r.shareVertex), fmt("%.2f", r.shareFill),
                      fmt("%.0f%%", 100.0 * r.rmsRelResidual), fmt("%.2f", e.baselineWallMs), evidence});
    }
    os << "\n";
    table.print(os);
    os << "\nshares: each stage's part of the baseline frame time in the fitted model T = a + c*calls + "
          "v*vertices + f*fragments\n(cpu includes the fixed part a); class: the stage with >= 0.5 of it, "
          "else mixed; resid = rms residual of the fit relative to max(T, T0), ? = over 15%;\n* = predicted, "
          "not "
          "fitted (the scale runs: they change more than the measured loads); ! = failed or loads unknown. "
          "Abbreviations: imm/inst/ret submission switched, x10near/x0.01 scale,\nres resolution per axis, "
          "tess "
          "tessellation factor, norast LP_NO_RAST=1.\n";
}

CsvTable BottleneckStudy::summary(const CsvTable& classes) {
    // What printTable shows, in its order: who and where, the class, the shares, the fit's quality, and
    // the measured time ratio of every perturbation; the renderer last (it is long and the same in
    // every row, so the Markdown export lists it above the table).
    std::vector<std::string> columns{col::kTechniqueSpec};
    for (const char* name : kIdentity)
        if (std::string(name) != col::kRenderer) columns.push_back(name);
    columns.insert(columns.end(), {"wall_ms_baseline", "class", "share_cpu", "share_vertex", "share_fill",
                                   "rms_rel_residual", "poor_fit", "held_out_rel_error"});
    for (const std::string& what : perturbations()) columns.push_back("time_ratio_" + what);
    columns.push_back(col::kRenderer);
    CsvTable out;
    std::vector<size_t> from;
    for (const std::string& name : columns) {
        const auto it = std::find(classes.header.begin(), classes.header.end(), name);
        if (it == classes.header.end()) continue; // a perturbation this study did not run
        out.header.push_back(name);
        from.push_back(size_t(it - classes.header.begin()));
    }
    for (const auto& row : classes.rows) {
        std::vector<std::string> cells;
        for (size_t i : from) cells.push_back(i < row.size() ? row[i] : "");
        out.rows.push_back(std::move(cells));
    }
    return out;
}

CsvTable BottleneckStudy::table(const std::vector<BottleneckEntry>& entries) {
    std::vector<CsvRow> rows;
    for (const BottleneckEntry& e : entries) {
        const BottleneckResult& r = e.result;
        CsvRow row{{col::kSweepId, e.sweepId},
                   {col::kStudyBase, e.studyBase},
                   {col::kTechniqueSpec, e.techniqueSpec}};
        row.insert(row.end(), e.identity.begin(), e.identity.end());
        row.insert(row.end(), {{"wall_ms_baseline", csvNumber(e.baselineWallMs)},
                               {"class", r.label},
                               {"share_cpu", csvNumber(r.shareCpu)},
                               {"share_vertex", csvNumber(r.shareVertex)},
                               {"share_fill", csvNumber(r.shareFill)},
                               {"share_fixed", csvNumber(r.shareFixed)},
                               {"r2", csvNumber(r.r2)},
                               {"rms_rel_residual", csvNumber(r.rmsRelResidual)},
                               {"max_rel_residual", csvNumber(r.maxRelResidual)},
                               {"poor_fit", r.poorFit ? "true" : "false"},
                               {"runs_in_fit", std::to_string(r.runsInFit)},
                               {"held_out_rel_error",
                                std::isfinite(r.heldOutRelError) ? csvNumber(r.heldOutRelError) : ""}});
        auto number = [](double v) { return std::isfinite(v) ? csvNumber(v) : std::string(); };
        for (const RunEvidence& ev : r.evidence) {
            row.emplace_back("time_ratio_" + ev.perturbation, number(ev.timeRatio));
            row.emplace_back("fitted_ratio_" + ev.perturbation, number(ev.fittedTimeRatio));
            row.emplace_back("cpu_ratio_" + ev.perturbation, number(ev.loadRatio.cpu));
            row.emplace_back("vertex_ratio_" + ev.perturbation, number(ev.loadRatio.vertex));
            row.emplace_back("fill_ratio_" + ev.perturbation, number(ev.loadRatio.fill));
        }
        rows.push_back(std::move(row));
    }
    return CsvWriter::toTable(rows);
}

} // namespace sb
