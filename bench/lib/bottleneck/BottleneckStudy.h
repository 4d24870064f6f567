#pragma once
// `bench bottleneck`: the CPU / vertex / fill study of Coleman's thesis, section 6.2, run
// automatically on any GL implementation. For every base combination of the axes (usually one scene at
// one setting) and every technique, the perturbation set (BottleneckClassifier.h lists what each one
// moves):
//   baseline          as given
//   submit_immediate  submission immediate: CPU load up (submit_retained when the base is immediate);
//                     on Vulkan (--api vulkan among the common arguments), which has no immediate mode,
//                     submit_instanced instead: CPU load down (submit_retained from an instanced base)
//   scale_x10_near    instances x10 seen from the 'near' camera: fill up at equal vertex count (the
//                     thesis's fill test; left out for scenes without a 'near' camera)
//   scale_x0.01       instances x0.01: fill down at equal vertex count (the thesis's vertex test)
//   size_half, size_double   resolution /2 and x2 per axis: fill only
//   tess_half, tess_double   tessellation factor /2 and x2: vertex load only (retained submission)
//   lp_no_rast        Mesa llvmpipe and lavapipe only: LP_NO_RAST=1 in the worker's environment, the
//   rasteriser off
// Each perturbation is a group of the sweep machinery (its own worker process, so LP_NO_RAST reaches only
// its own context), the techniques interleaved inside it. The analysis reads the rows back (from this
// run or any earlier CSV: --from), fits BottleneckClassifier per base and technique, prints the table
// with the evidence and writes it as CSV.
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/lib/bottleneck/BottleneckClassifier.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/sweep/SweepDefinition.h"

namespace sb {

/// One classified (base combination, technique).
struct BottleneckEntry {
    std::string sweepId;
    std::string studyBase;     ///< the base combination ("scene=aircraft ... instances=100")
    std::string techniqueSpec; ///< as given to -t
    KeyValues identity;        ///< scene, instances, scale ... of the baseline row
    double baselineWallMs = 0;
    BottleneckResult result;
};

class BottleneckStudy {
public:
    /// The perturbation plan for every base combination of `base` (whose axes must not already vary
    /// what the study varies in a way it cannot, e.g. two tess factors are fine, each gets its own
    /// study). `llvmpipe` adds the LP_NO_RAST run; `scenesWithNear` lists the scenes that have a 'near'
    /// camera (the others get no scale_x10_near run).
    static SweepPlan plan(const SweepDefinition& base, bool llvmpipe,
                          const std::vector<std::string>& scenesWithNear);
    /// The same for this machine: probes the GL renderer the workers will get (a context of the
    /// definition's backend), or the Vulkan device with --api vulkan, and loads the scenes to see which
    /// have a 'near' camera.
    static SweepPlan plan(const SweepDefinition& base);
    /// Classifies every (sweep, base, technique) found in `rows` (rows of other kinds are ignored).
    /// Throws sb::Error when the table holds no bottleneck rows at all.
    static std::vector<BottleneckEntry> analyse(const CsvTable& rows);
    static void printTable(std::ostream& os, const std::vector<BottleneckEntry>& entries);
    /// One row per entry: identity, class, shares, fit quality and, per perturbation, the time and
    /// load ratios and the fitted time ratio.
    static CsvTable table(const std::vector<BottleneckEntry>& entries);
    /// The columns of `classes` (a table() or a classes CSV read back) that printTable shows, in its
    /// order: technique_spec, the base setting, wall_ms_baseline, class, share_cpu, share_vertex,
    /// share_fill, rms_rel_residual, poor_fit, held_out_rel_error, time_ratio_<P> per perturbation run,
    /// renderer. The Markdown report (`--format md`) prints this, not the curated columns of result
    /// rows, which know nothing of a classification.
    static CsvTable summary(const CsvTable& classes);
    /// The perturbation names in the order the study runs and prints them.
    static const std::vector<std::string>& perturbations();
};

} // namespace sb
