#include "bench/golden/MatrixCheck.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "bench/golden/GoldenImage.h"
#include "bench/golden/MatrixVariants.h"
#include "core/Error.h"

namespace sb {

namespace {

/// Float visibility of two modes: the share of samples that differ by more than 0.01.
ImageDiffResult compareVisibility(const std::vector<float>& expected, const std::vector<float>& actual) {
    ImageDiffResult r;
    if (expected.size() != actual.size()) {
        r.mismatch = "visibility sizes differ";
        return r;
    }
    r.comparable = true;
    r.pixels = expected.size();
    for (size_t i = 0; i < expected.size(); ++i) {
        const float d = std::fabs(expected[i] - actual[i]);
        const bool fails = !(d <= 0.01f); // NaN fails
        r.failingPixels += fails;
        r.maxChannelDiff = std::max(r.maxChannelDiff, std::isfinite(d) ? int(std::lround(d * 255.0f)) : 255);
    }
    return r;
}

void checkModes(const std::vector<MatrixCell>& cells, const MatrixCell& cell, CellVerdict& v) {
    // Every other mode, and every other API's cell, against the technique's golden cell (GL retained,
    // or Vulkan retained for a technique with no GL form).
    const MatrixCell* retained = GoldenMatrix::goldenCellOf(cells, cell);
    if (retained == &cell) return;
    // -t auto on Vulkan chooses among the Vulkan forms by Vulkan's measurements: where it chose another
    // technique than GL's auto, the images differ by design and its own golden holds it (checkGolden).
    if (retained && cell.vulkan() && cell.judgedAs() != retained->judgedAs()) return;
    const std::string against = retained && retained->vulkan() ? "Vulkan retained" : "retained";
    if (!retained || !retained->ran()) {
        v.failures.push_back("runs in this mode but not in " + against + " mode");
        return;
    }
    const ImageDiffResult vis = compareVisibility(retained->visibilityFloat, cell.visibilityFloat);
    const ImageDiffResult col =
        ImageDiff::compare(retained->colour, cell.colour, MatrixCheck::kModeTolerance);
    const std::string visText =
        "visibility vs " + against + ": " + vis.describe({3, MatrixCheck::kModeTolerance.maxFailingFraction});
    const std::string colText = "colour vs " + against + ": " + col.describe(MatrixCheck::kModeTolerance);
    (vis.passes(MatrixCheck::kModeTolerance) ? v.details : v.failures).push_back(visText);
    (col.passes(MatrixCheck::kModeTolerance) ? v.details : v.failures).push_back(colText);
}

/// Goldens read so far, by path: the four modes of a cell share one golden, read once. An empty image
/// stands for a missing file.
using GoldenCache = std::map<std::string, Image8>;

void checkGolden(const MatrixCell& cell, const std::string& dir, const std::string& kind, const Image8& image,
                 GoldenCache& goldens, CellVerdict& v) {
    const std::string path = MatrixCheck::goldenPath(dir, cell.scene, cell.judgedAs(), kind);
    auto [it, fresh] = goldens.try_emplace(path);
    if (fresh && std::filesystem::exists(path)) {
        // An unreadable golden (truncated by a kill, a forged header) fails this cell, naming the file
        // and why, and the matrix goes on: the other cells' verdicts still count. It is not cached, so
        // every mode that needs it says so.
        try {
            it->second = GoldenImage::read(path);
        } catch (const Error& e) {
            goldens.erase(it);
            v.failures.push_back(kind + ": " + e.what() + " (bench golden --update replaces it)");
            return;
        }
    }
    if (it->second.empty()) {
        v.failures.push_back("no golden " + path + " (bench golden --update writes it)");
        return;
    }
    const ImageDiffResult d = ImageDiff::compare(it->second, image, MatrixCheck::kGoldenTolerance);
    const std::string text = kind + " vs golden: " + d.describe(MatrixCheck::kGoldenTolerance);
    (d.passes(MatrixCheck::kGoldenTolerance) ? v.details : v.failures).push_back(text);
    if (d.comparable && !d.passes(MatrixCheck::kGoldenTolerance))
        v.changed.push_back({kind, path, it->second, image});
}

std::string number(double v) {
    std::ostringstream out;
    out.precision(4);
    out << v;
    return out.str();
}

void checkAccuracy(const MatrixCell& cell, const std::map<std::string, AccuracyBound>& bounds,
                   CellVerdict& v) {
    for (size_t l = 0; l < cell.lights.size(); ++l) {
        const AccuracyBound rule = AccuracyBounds::derive(cell, l);
        if (!rule.judged()) continue;
        auto it = bounds.find(rule.cell);
        if (it == bounds.end()) {
            v.failures.push_back(rule.cell +
                                 ": no committed accuracy bound (bench golden --update writes it)");
            continue;
        }
        const AccuracyBound& committed = it->second;
        // The committed bound may be tighter than the rule's, never looser (0.05 points for the
        // reference's own variation between modes: its G-buffer is rendered by each mode's submitter).
        if (committed.metric != rule.metric || committed.max > rule.max + 0.05)
            v.failures.push_back(rule.cell + ": committed bound " + committed.metric +
                                 " <= " + number(committed.max) + " is looser than the rule's " +
                                 rule.metric + " <= " + number(rule.max) + " (" + rule.why + ")");
        // no_shadow, approximate and soft_approximate bound the error by no shadow's error in that cell
        // (the reference's shadowed fraction or its RMSE). A Vulkan cell's reference is traced at its own
        // G-buffer, whose coverage differs from GL's by an edge pixel or two (the two clip-space
        // conversions round differently): it is held to its own reference's value (measured on
        // painting_machine: none and occluder 4.766% against GL's 4.760%).
        const bool ownReference =
            rule.rule == "no_shadow" || rule.rule == "approximate" || rule.rule == "soft_approximate";
        const AccuracyBound& held =
            cell.vulkan() && ownReference && committed.rule == rule.rule ? rule : committed;
        const double measured = held.measured(cell.lights[l]);
        const std::string text = rule.cell + " " + held.metric + " " + number(measured) + " (bound " +
                                 number(held.min) + ".." + number(held.max) + ", " + held.rule + ": " +
                                 held.why + ")";
        (measured <= held.max && measured >= held.min ? v.details : v.failures).push_back(text);
    }
}

/// The `auto` cell's own rule: the technique it chose delivers what the scene asks for and was within
/// the bound in auto's calibration (its image and accuracy here are held to that technique's golden and
/// bound like its own cell).
void checkAutoPick(const MatrixCell& cell, CellVerdict& v) {
    if (!cell.autoPick) return;
    const AutoPick& p = *cell.autoPick;
    const EffectMask missing = p.request & ~p.effects;
    std::vector<std::string>& sink = missing ? v.failures : v.details;
    sink.push_back("auto chose " + p.spec + " (" + p.reason + ")" +
                   (missing ? ", which lacks " + effectMaskToString(missing) : ""));
    if (p.request && p.wrongPct > p.bound)
        v.failures.push_back("auto's choice was " + number(p.wrongPct) +
                             "% wrong in its calibration, over the " + number(p.bound) + "% bound");
}

} // namespace

std::string MatrixCheck::goldenPath(const std::string& dir, const std::string& scene,
                                    const std::string& technique, const std::string& kind) {
    return dir + "/" + scene + "/" + MatrixVariants::key(technique) + "." + kind + ".png";
}

CellVerdict MatrixCheck::checkCell(const std::vector<MatrixCell>& cells, size_t index,
                                   const std::string& goldenDir,
                                   const std::map<std::string, AccuracyBound>& bounds, GoldenCache& goldens) {
    const MatrixCell& cell = cells[index];
    CellVerdict v;
    v.cell = cell.name();
    if (!cell.failure.empty()) {
        v.failures.push_back("threw: " + cell.failure);
    } else if (cell.refusal == MatrixCell::Refusal::Driver) {
        v.notRun = cell.unsupported; // judged where the driver has what the form needs
    } else if (!cell.unsupported.empty()) {
        v.unsupported = cell.unsupported;
        if (cell.refusal == MatrixCell::Refusal::Scene && !cell.autoPick &&
            GoldenMatrix::goldenCellOf(cells, cell) == &cell &&
            std::filesystem::exists(goldenPath(goldenDir, cell.scene, cell.technique, "visibility")))
            v.failures.push_back("refuses the scene but has a golden: " + cell.unsupported);
    } else {
        if (cell.sanity.total())
            v.failures.push_back("visibility has " + std::to_string(cell.sanity.nan) + " NaN, " +
                                 std::to_string(cell.sanity.inf) + " Inf, " +
                                 std::to_string(cell.sanity.outOfRange) + " out of [0, 1]");
        checkModes(cells, cell, v);
        checkGolden(cell, goldenDir, "visibility", cell.visibility, goldens, v);
        checkGolden(cell, goldenDir, "colour", cell.colour, goldens, v);
        checkAccuracy(cell, bounds, v);
        checkAutoPick(cell, v);
    }
    return v;
}

std::vector<CellVerdict> MatrixCheck::check(const std::vector<MatrixCell>& cells,
                                            const std::string& goldenDir,
                                            const std::map<std::string, AccuracyBound>& bounds) {
    std::vector<CellVerdict> verdicts;
    GoldenCache goldens;
    for (size_t i = 0; i < cells.size(); ++i)
        verdicts.push_back(checkCell(cells, i, goldenDir, bounds, goldens));
    return verdicts;
}

} // namespace sb
