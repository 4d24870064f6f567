#pragma once
// Where is a technique's bottleneck: CPU submission, vertex work or fill? The automated form of the
// perturbation study of Coleman's thesis (section 6.2), run by `bench bottleneck`.
//
// Input: one BottleneckRun per perturbation of the same technique on the same scene: the median frame
// time T (ms) and the load each pipeline stage carried in an untimed census frame:
//   cpu load C    GL API calls issued for the frame (immediate mode: one per vertex attribute),
//   vertex load V primitives submitted (GL_ARB_pipeline_statistics_query; BottleneckStudy.cpp says why
//                 primitives rather than vertex shader invocations),
//   fill load F   fragment shader invocations (same query).
//
// Model. Frame time is linear in the stage loads,
//   T = a + c*C + v*V + f*F,   a, c, v, f >= 0   (a: fixed per-frame cost),
// fitted by non-negative least squares (unweighted) over all usable runs. The fit is done in normalised
// units, x_k = L_k / L_k(baseline) and t = T / T(baseline), which changes nothing about the optimum (a
// positive rescaling of columns and target) but keeps the normal equations well conditioned; the
// coefficients reported are in these units (coefFill = f * F0 / T0, ...). A stage whose baseline load is
// 0 cannot be normalised: it is left out of the fit and gets coefficient and share 0.
//
// Shares are the point elasticities of frame time at the baseline under the fitted model,
// d ln T / d ln L_k = k * L_k / T. With the fitted baseline time t0 = a + c + v + f (all x_k = 1 there):
//   shareVertex = v / t0,  shareFill = f / t0,  shareCpu = (a + c) / t0,  shareFixed = a / t0.
// Everything that does not scale with vertex or fill work is the CPU's (API calls, per-draw driver work,
// per-frame overhead): "if shrinking GPU work does not speed the frame up, it is CPU-limited". The three
// shares sum to 1.
//
// Label: the stage with the largest share, "cpu", "vertex" or "fill", when that share is >= 0.5;
// otherwise "mixed:<largest>+<second>" (e.g. "mixed:fill+vertex"). Equal shares rank cpu, vertex, fill.
//
// Which perturbation moves which load (so which coefficient it identifies):
//   submit_immediate / submit_retained  C only (separates c from a, and c from v in immediate mode)
//   scale_x10_near, scale_x0.01          F up / down at equal V
//   size_half, size_double               F x1/4, x4 (resolution)
//   tess_half, tess_double               V down / up (C with it in immediate mode)
//   lp_no_rast                           F = 0 (llvmpipe with LP_NO_RAST=1)
// Any run may be missing. Terms that no present run moves apart are collinear (C with the constant when
// there is no submit run; C with V in immediate mode without submit_retained): their joint cost goes to
// the first of fixed, cpu, vertex, fill, so the shares are only as resolved as the runs allow.
#include <cstddef>
#include <string>
#include <vector>

namespace sb {

/// The fixed perturbation names of the bottleneck study (the `perturbation` tag of its rows).
namespace perturbation {
inline constexpr const char* kBaseline = "baseline";
inline constexpr const char* kSubmitImmediate = "submit_immediate"; ///< baseline retained
inline constexpr const char* kSubmitRetained = "submit_retained";   ///< baseline immediate or instanced
/// Vulkan (no immediate mode), baseline retained: the per-instance draws become one per mesh and run,
/// CPU load down at equal vertex and fill load.
inline constexpr const char* kSubmitInstanced = "submit_instanced";
inline constexpr const char* kScaleNear = "scale_x10_near";
inline constexpr const char* kScaleSmall = "scale_x0.01";
inline constexpr const char* kSizeHalf = "size_half";
inline constexpr const char* kSizeDouble = "size_double";
inline constexpr const char* kTessHalf = "tess_half";
inline constexpr const char* kTessDouble = "tess_double";
inline constexpr const char* kNoRasterizer = "lp_no_rast";
} // namespace perturbation

/// Load of each pipeline stage in one frame (absolute counts, or ratios in RunEvidence).
struct StageLoads {
    double cpu = 0;    ///< GL API calls
    double vertex = 0; ///< primitives submitted (the geometry stage's work: shading, assembly, setup)
    double fill = 0;   ///< fragment shader invocations
};

/// One measured perturbation.
struct BottleneckRun {
    std::string perturbation; ///< "baseline", "submit_immediate", ... (namespace perturbation)
    double wallMs = 0;        ///< median frame time; not finite or <= 0 = failed run, left out of the fit
    StageLoads loads;         ///< census frame; any not finite or < 0 = unusable run, left out of the fit
};

/// What the table prints for one run: its ratios to the baseline and the model's prediction.
struct RunEvidence {
    std::string perturbation;
    double timeRatio = 0;       ///< T / T0 (NaN for a run without a finite frame time)
    StageLoads loadRatio;       ///< L / L0 per stage; NaN where L0 = 0
    double fittedTimeRatio = 0; ///< a + c*C/C0 + v*V/V0 + f*F/F0 (NaN for a run with unusable loads)
    bool usedInFit = false;     ///< false for a failed run (bad time or loads) and a held-out one
    bool heldOut = false;       ///< a scale run: predicted by the model, not fitted (see isHeldOut)
};

struct BottleneckResult {
    std::string label; ///< "cpu", "vertex", "fill" or "mixed:<largest>+<second>"
    /// Elasticities at the baseline; shareCpu + shareVertex + shareFill = 1. shareFixed is part of
    /// shareCpu (the a / t0 of it).
    double shareCpu = 0, shareVertex = 0, shareFill = 0, shareFixed = 0;
    /// Fitted coefficients in normalised units (fractions of the baseline frame time per baseline load).
    double coefFixed = 0, coefCpu = 0, coefVertex = 0, coefFill = 0;
    double r2 = 0; ///< 1 - SS_res / SS_tot on t (1 when SS_tot = 0)
    /// Residuals relative to max(t_i, 1), i.e. to the run's time or, for runs faster than the baseline,
    /// the baseline's: an LP_NO_RAST run at 1% of the frame must not turn a 0.01 miss into 100%.
    double maxRelResidual = 0; ///< max |t_i - t_hat_i| / max(t_i, 1) over the runs in the fit
    double rmsRelResidual = 0; ///< root mean square of the same
    /// rmsRelResidual > kPoorFitRmsRel: the linear model does not explain the times. Judged on the
    /// relative residual, not on R^2: a CPU-bound frame barely moves under any perturbation, so its
    /// SS_tot is timing noise and R^2 says nothing, while a model within a few percent of every run
    /// is a good fit whatever the spread.
    bool poorFit = false;
    size_t runsInFit = 0; ///< usable runs, baseline included
    /// The largest relative error of the model's prediction for a held-out run (NaN without one):
    /// how well the fit carries over to the thesis's own tests.
    double heldOutRelError = 0;
    std::vector<RunEvidence> evidence; ///< every input run, in input order
};

class BottleneckClassifier {
public:
    static constexpr double kDominantShare = 0.5;  ///< a share >= this names the bottleneck alone
    static constexpr double kPoorFitRmsRel = 0.15; ///< 15%: several times this machine's timing noise

    /// The scale runs (scale_x10_near, scale_x0.01) are not fitted, only predicted. Each of the other
    /// perturbations moves one stage's load by construction (resolution: fill; tessellation: vertex;
    /// submission: calls). Rescaling the geometry moves the fill AND changes what the clipper and the
    /// rasteriser's setup do with the triangles (most leave the frustum at x10 near; at x0.01 tiny
    /// triangles cover no pixel centre and are culled before setup), work no load counter sees. Fitting
    /// them lets that unmeasured work masquerade as fill or as fixed cost; predicting them instead
    /// turns the thesis's tests into a check of the model (heldOutRelError).
    static bool isHeldOut(const std::string& perturbation);
    static constexpr size_t kMinRuns = 4; ///< usable runs needed (4 unknowns at most)
    static constexpr size_t kMaxNnlsColumns = 6;
    static constexpr const char* kLabelCpu = "cpu";
    static constexpr const char* kLabelVertex = "vertex";
    static constexpr const char* kLabelFill = "fill";
    static constexpr const char* kLabelMixedPrefix = "mixed:";

    /// Fits the model above to `runs` and classifies. Throws sb::Error(BadInput) naming what is missing
    /// when there is no "baseline" run (or more than one), when the baseline's time or loads are
    /// unusable, or when fewer than kMinRuns runs are usable.
    static BottleneckResult classify(const std::vector<BottleneckRun>& runs);

    /// Non-negative least squares: argmin |A x - b|^2 subject to x >= 0, A row-major m x n, n <=
    /// kMaxNnlsColumns. Exact, by enumerating every passive set (subset of columns), solving its normal
    /// equations (columns scaled to unit norm; subsets with a relative pivot < 1e-12 are skipped as
    /// singular) and keeping the feasible solution with the smallest residual. Where several subsets reach
    /// the same residual (to 1e-10 relative: collinear columns), the one with fewest columns, then lowest
    /// column indices, wins, so a rank-deficient A gives a deterministic minimal-residual x. Columns outside
    /// the chosen set are exactly 0. Throws std::invalid_argument on inconsistent sizes, n > kMaxNnlsColumns
    /// or non-finite entries.
    static std::vector<double> solveNnls(const std::vector<double>& A, size_t m, size_t n,
                                         const std::vector<double>& b);
};

} // namespace sb
