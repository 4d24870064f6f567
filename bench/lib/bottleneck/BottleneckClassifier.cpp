#include "bench/lib/bottleneck/BottleneckClassifier.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "core/Error.h"

namespace sb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------------------
// NNLS by passive-set enumeration.
//
// With n <= 6 columns there are at most 64 passive sets, each a tiny linear solve, so the exact answer is
// cheaper to write correctly than an active-set iteration (Lawson-Hanson) and has no convergence or
// cycling questions. Exactness: the NNLS optimum point A x* is unique; by the conic Caratheodory theorem
// it is a positive combination of linearly independent columns S, and the KKT conditions make the
// residual orthogonal to those columns, so x*_S is the unconstrained least-squares solution on S. Hence
// some nonsingular passive set reproduces the optimum, and we only need to try them all.

// Pivots below this fraction of the largest entry of the (unit-diagonal) normal matrix mean singular:
// the subset's columns are (nearly) collinear and another subset reaches the same residual.
constexpr double kSingularPivot = 1e-12;
// Ties between subsets: a later subset (more columns, or higher indices) must beat the best residual by
// more than rounding. The relative part covers two routes to the same residual; the floor (relative to
// |b|^2, i.e. 1e-10 of |b| in norm) covers exact fits whose residuals are pure rounding noise.
constexpr double kTieRelative = 1e-10;
constexpr double kTieFloor = 1e-20;

/// Solves the k x k row-major system M y = r in place (y replaces r). False when a pivot is below
/// kSingularPivot times the largest entry of M.
bool solveSmallSystem(std::vector<double>& M, std::vector<double>& r, size_t k) {
    double scale = 0;
    for (double e : M) scale = std::max(scale, std::abs(e));
    if (scale == 0) return false;
    for (size_t col = 0; col < k; ++col) {
        size_t pivot = col;
        for (size_t row = col + 1; row < k; ++row)
            if (std::abs(M[row * k + col]) > std::abs(M[pivot * k + col])) pivot = row;
        if (std::abs(M[pivot * k + col]) < kSingularPivot * scale) return false;
        if (pivot != col) {
            for (size_t j = 0; j < k; ++j) std::swap(M[col * k + j], M[pivot * k + j]);
            std::swap(r[col], r[pivot]);
        }
        for (size_t row = col + 1; row < k; ++row) {
            double factor = M[row * k + col] / M[col * k + col];
            for (size_t j = col; j < k; ++j) M[row * k + j] -= factor * M[col * k + j];
            r[row] -= factor * r[col];
        }
    }
    for (size_t col = k; col-- > 0;) {
        double sum = r[col];
        for (size_t j = col + 1; j < k; ++j) sum -= M[col * k + j] * r[j];
        r[col] = sum / M[col * k + col];
    }
    return true;
}

/// The normal equations of the whole problem with every column scaled to unit norm (Jacobi scaling:
/// loads normalised to the baseline still span ratios of 1e4, e.g. immediate vs retained calls, and
/// unit columns keep that out of the condition number). A zero column keeps norm 0 and is never used.
struct ScaledNormal {
    size_t n = 0;
    std::vector<double> norm; ///< column norms
    std::vector<double> gram; ///< n x n, (A_i . A_j) / (|A_i| |A_j|)
    std::vector<double> atb;  ///< (A_i . b) / |A_i|
};

ScaledNormal buildScaledNormal(const std::vector<double>& A, size_t m, size_t n,
                               const std::vector<double>& b) {
    ScaledNormal s{n, std::vector<double>(n, 0.0), std::vector<double>(n * n, 0.0),
                   std::vector<double>(n, 0.0)};
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < n; ++j)
            for (size_t r = 0; r < m; ++r) s.gram[i * n + j] += A[r * n + i] * A[r * n + j];
        for (size_t r = 0; r < m; ++r) s.atb[i] += A[r * n + i] * b[r];
        s.norm[i] = std::sqrt(s.gram[i * n + i]);
    }
    for (size_t i = 0; i < n; ++i) {
        if (s.norm[i] == 0) continue;
        s.atb[i] /= s.norm[i];
        for (size_t j = 0; j < n; ++j)
            if (s.norm[j] != 0) s.gram[i * n + j] /= s.norm[i] * s.norm[j];
    }
    return s;
}

/// Unconstrained least squares restricted to the columns in `mask` (x = 0 elsewhere), in original units.
/// Empty when the subset is singular or holds a zero column.
std::optional<std::vector<double>> solvePassiveSet(const ScaledNormal& s, unsigned mask) {
    std::vector<size_t> cols;
    for (size_t j = 0; j < s.n; ++j)
        if (mask & (1u << j)) {
            if (s.norm[j] == 0) return std::nullopt;
            cols.push_back(j);
        }
    size_t k = cols.size();
    std::vector<double> M(k * k), y(k);
    for (size_t i = 0; i < k; ++i) {
        y[i] = s.atb[cols[i]];
        for (size_t j = 0; j < k; ++j) M[i * k + j] = s.gram[cols[i] * s.n + cols[j]];
    }
    if (!solveSmallSystem(M, y, k)) return std::nullopt;
    std::vector<double> x(s.n, 0.0);
    for (size_t i = 0; i < k; ++i) x[cols[i]] = y[i] / s.norm[cols[i]];
    return x;
}

/// |A x - b|^2 from the residuals themselves (the normal-equation shortcut b.b - x.A^T b cancels badly
/// for good fits).
double residualSumOfSquares(const std::vector<double>& A, size_t m, size_t n, const std::vector<double>& b,
                            const std::vector<double>& x) {
    double ssr = 0;
    for (size_t r = 0; r < m; ++r) {
        double fit = 0;
        for (size_t j = 0; j < n; ++j) fit += A[r * n + j] * x[j];
        ssr += (fit - b[r]) * (fit - b[r]);
    }
    return ssr;
}

/// All subsets of n columns, fewest columns first, then by mask: the tie-break order of solveNnls.
std::vector<unsigned> passiveSetOrder(size_t n) {
    std::vector<unsigned> masks(size_t(1) << n);
    for (unsigned i = 0; i < masks.size(); ++i) masks[i] = i;
    std::stable_sort(masks.begin(), masks.end(),
                     [](unsigned x, unsigned y) { return std::popcount(x) < std::popcount(y); });
    return masks;
}

void checkNnlsArguments(const std::vector<double>& A, size_t m, size_t n, const std::vector<double>& b) {
    if (n > BottleneckClassifier::kMaxNnlsColumns)
        throw std::invalid_argument("solveNnls: " + std::to_string(n) + " columns, at most " +
                                    std::to_string(BottleneckClassifier::kMaxNnlsColumns));
    if (A.size() != m * n || b.size() != m)
        throw std::invalid_argument("solveNnls: A has " + std::to_string(A.size()) + " entries and b " +
                                    std::to_string(b.size()) + ", expected " + std::to_string(m * n) +
                                    " and " + std::to_string(m));
    auto finite = [](double e) { return std::isfinite(e); };
    if (!std::all_of(A.begin(), A.end(), finite) || !std::all_of(b.begin(), b.end(), finite))
        throw std::invalid_argument("solveNnls: A or b has a non-finite entry");
}

// ---------------------------------------------------------------------------------------------------
// The classifier.

enum Stage : size_t { kCpu = 0, kVertex = 1, kFill = 2, kStageCount = 3 };
constexpr std::array<const char*, kStageCount> kStageLabels = {
    BottleneckClassifier::kLabelCpu, BottleneckClassifier::kLabelVertex, BottleneckClassifier::kLabelFill};

std::array<double, kStageCount> toArray(const StageLoads& l) {
    return {l.cpu, l.vertex, l.fill};
}
StageLoads toLoads(const std::array<double, kStageCount>& a) {
    return {a[kCpu], a[kVertex], a[kFill]};
}

bool hasUsableTime(const BottleneckRun& run) {
    return std::isfinite(run.wallMs) && run.wallMs > 0;
}
bool hasUsableLoads(const BottleneckRun& run) {
    for (double l : toArray(run.loads))
        if (!std::isfinite(l) || l < 0) return false;
    return true;
}
bool isUsable(const BottleneckRun& run) {
    return hasUsableTime(run) && hasUsableLoads(run);
}

std::string listPerturbations(const std::vector<const BottleneckRun*>& runs) {
    std::string out;
    for (const BottleneckRun* r : runs) out += (out.empty() ? "" : ", ") + r->perturbation;
    return out.empty() ? "none" : out;
}

std::string formatLoads(const StageLoads& l) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "cpu=%g vertex=%g fill=%g", l.cpu, l.vertex, l.fill);
    return buf;
}

/// The single usable "baseline" run; everything is normalised by it, so its absence is an input error.
const BottleneckRun& findBaseline(const std::vector<BottleneckRun>& runs) {
    std::vector<const BottleneckRun*> all, baselines;
    for (const BottleneckRun& r : runs) {
        all.push_back(&r);
        if (r.perturbation == perturbation::kBaseline) baselines.push_back(&r);
    }
    const std::string prefix = "bottleneck classification: ";
    if (baselines.empty())
        throw Error(prefix + "no \"baseline\" run among the " + std::to_string(runs.size()) + " given (" +
                    listPerturbations(all) + "); every ratio is taken to the baseline");
    if (baselines.size() > 1)
        throw Error(prefix + std::to_string(baselines.size()) + " \"baseline\" runs; exactly one is needed");
    const BottleneckRun& base = *baselines.front();
    if (!hasUsableTime(base))
        throw Error(prefix + "the \"baseline\" run has no finite positive frame time (wallMs = " +
                    std::to_string(base.wallMs) + ")");
    if (!hasUsableLoads(base))
        throw Error(prefix + "the \"baseline\" run has a non-finite or negative load (" +
                    formatLoads(base.loads) + ")");
    return base;
}

std::vector<const BottleneckRun*> usableRuns(const std::vector<BottleneckRun>& runs) {
    std::vector<const BottleneckRun*> usable;
    for (const BottleneckRun& r : runs)
        if (isUsable(r) && !BottleneckClassifier::isHeldOut(r.perturbation)) usable.push_back(&r);
    if (usable.size() < BottleneckClassifier::kMinRuns)
        throw Error("bottleneck classification: needs at least " +
                    std::to_string(BottleneckClassifier::kMinRuns) +
                    " runs with a finite positive frame time and finite non-negative loads, got " +
                    std::to_string(usable.size()) + " (" + listPerturbations(usable) + ")");
    return usable;
}

/// The fitted model in normalised units: t = fixed + sum over included stages of coef_k * L_k / L_k0.
struct Model {
    StageLoads baseLoads;
    double baseMs = 0;
    std::array<bool, kStageCount> included{}; ///< baseline load > 0
    double fixed = 0;
    std::array<double, kStageCount> coef{};

    /// L / L0 per stage, NaN where L0 = 0.
    std::array<double, kStageCount> ratios(const StageLoads& loads) const {
        std::array<double, kStageCount> l = toArray(loads), l0 = toArray(baseLoads), out{};
        for (size_t k = 0; k < kStageCount; ++k) out[k] = included[k] ? l[k] / l0[k] : kNaN;
        return out;
    }
    double predict(const StageLoads& loads) const {
        std::array<double, kStageCount> x = ratios(loads);
        double t = fixed;
        for (size_t k = 0; k < kStageCount; ++k)
            if (included[k]) t += coef[k] * x[k];
        return t;
    }
    double baselineTime() const { return fixed + coef[kCpu] + coef[kVertex] + coef[kFill]; }
};

/// Columns: the constant (fixed cost), then each included stage's normalised load. Rows: usable runs.
Model fitModel(const BottleneckRun& base, const std::vector<const BottleneckRun*>& usable) {
    Model model;
    model.baseLoads = base.loads;
    model.baseMs = base.wallMs;
    std::array<double, kStageCount> l0 = toArray(base.loads);
    std::vector<size_t> stages;
    for (size_t k = 0; k < kStageCount; ++k) {
        model.included[k] = l0[k] > 0;
        if (model.included[k]) stages.push_back(k);
    }
    size_t n = 1 + stages.size(), m = usable.size();
    std::vector<double> A, t;
    for (const BottleneckRun* r : usable) {
        std::array<double, kStageCount> x = model.ratios(r->loads);
        A.push_back(1.0);
        for (size_t k : stages) A.push_back(x[k]);
        t.push_back(r->wallMs / base.wallMs);
    }
    std::vector<double> coef = BottleneckClassifier::solveNnls(A, m, n, t);
    model.fixed = coef[0];
    for (size_t i = 0; i < stages.size(); ++i) model.coef[stages[i]] = coef[1 + i];
    return model;
}

/// "cpu" / "vertex" / "fill" when one share reaches kDominantShare, else "mixed:<largest>+<second>".
std::string labelFor(const std::array<double, kStageCount>& shares) {
    std::array<size_t, kStageCount> order = {kCpu, kVertex, kFill};
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return shares[x] > shares[y]; });
    if (shares[order[0]] >= BottleneckClassifier::kDominantShare) return kStageLabels[order[0]];
    return std::string(BottleneckClassifier::kLabelMixedPrefix) + kStageLabels[order[0]] + "+" +
           kStageLabels[order[1]];
}

void setShares(const Model& model, BottleneckResult& result) {
    result.coefFixed = model.fixed;
    result.coefCpu = model.coef[kCpu];
    result.coefVertex = model.coef[kVertex];
    result.coefFill = model.coef[kFill];
    // t0 > 0 always: every t_i > 0, so the constant alone (a = mean t) beats x = 0.
    double t0 = model.baselineTime();
    result.shareFixed = model.fixed / t0;
    result.shareCpu = (model.fixed + model.coef[kCpu]) / t0;
    result.shareVertex = model.coef[kVertex] / t0;
    result.shareFill = model.coef[kFill] / t0;
    result.label = labelFor({result.shareCpu, result.shareVertex, result.shareFill});
}

void setFitQuality(const Model& model, const std::vector<const BottleneckRun*>& usable,
                   BottleneckResult& result) {
    double mean = 0;
    for (const BottleneckRun* r : usable) mean += r->wallMs / model.baseMs;
    mean /= double(usable.size());
    double ssRes = 0, ssTot = 0, maxRel = 0, ssRel = 0;
    for (const BottleneckRun* r : usable) {
        double t = r->wallMs / model.baseMs, fit = model.predict(r->loads);
        ssRes += (t - fit) * (t - fit);
        ssTot += (t - mean) * (t - mean);
        const double rel = std::abs(t - fit) / std::max(t, 1.0);
        maxRel = std::max(maxRel, rel);
        ssRel += rel * rel;
    }
    result.r2 = ssTot == 0 ? 1.0 : 1.0 - ssRes / ssTot;
    result.maxRelResidual = maxRel;
    result.rmsRelResidual = std::sqrt(ssRel / double(usable.size()));
    result.poorFit = result.rmsRelResidual > BottleneckClassifier::kPoorFitRmsRel;
    result.runsInFit = usable.size();
}

RunEvidence evidenceFor(const Model& model, const BottleneckRun& run) {
    RunEvidence e;
    e.perturbation = run.perturbation;
    e.timeRatio = std::isfinite(run.wallMs) ? run.wallMs / model.baseMs : kNaN;
    e.loadRatio = toLoads(model.ratios(run.loads));
    e.fittedTimeRatio = hasUsableLoads(run) ? model.predict(run.loads) : kNaN;
    e.heldOut = BottleneckClassifier::isHeldOut(run.perturbation) && isUsable(run);
    e.usedInFit = isUsable(run) && !e.heldOut;
    return e;
}

} // namespace

std::vector<double> BottleneckClassifier::solveNnls(const std::vector<double>& A, size_t m, size_t n,
                                                    const std::vector<double>& b) {
    checkNnlsArguments(A, m, n, b);
    ScaledNormal normal = buildScaledNormal(A, m, n, b);
    double btb = 0;
    for (double e : b) btb += e * e;

    std::vector<double> best(n, 0.0); // the empty passive set: always feasible
    double bestSsr = btb;
    for (unsigned mask : passiveSetOrder(n)) {
        if (mask == 0) continue;
        std::optional<std::vector<double>> x = solvePassiveSet(normal, mask);
        if (!x || std::any_of(x->begin(), x->end(), [](double e) { return e < 0; })) continue;
        double ssr = residualSumOfSquares(A, m, n, b, *x);
        if (ssr < bestSsr - (kTieRelative * bestSsr + kTieFloor * btb)) {
            best = std::move(*x);
            bestSsr = ssr;
        }
    }
    return best;
}

BottleneckResult BottleneckClassifier::classify(const std::vector<BottleneckRun>& runs) {
    const BottleneckRun& base = findBaseline(runs);
    std::vector<const BottleneckRun*> usable = usableRuns(runs);
    Model model = fitModel(base, usable);

    BottleneckResult result;
    setShares(model, result);
    setFitQuality(model, usable, result);
    result.heldOutRelError = kNaN;
    for (const BottleneckRun& r : runs) {
        result.evidence.push_back(evidenceFor(model, r));
        const RunEvidence& e = result.evidence.back();
        if (!e.heldOut) continue;
        const double err = std::abs(e.timeRatio - e.fittedTimeRatio) / std::max(e.timeRatio, 1.0);
        result.heldOutRelError =
            std::isnan(result.heldOutRelError) ? err : std::max(result.heldOutRelError, err);
    }
    return result;
}

bool BottleneckClassifier::isHeldOut(const std::string& perturbation) {
    return perturbation == perturbation::kScaleNear || perturbation == perturbation::kScaleSmall;
}

} // namespace sb
