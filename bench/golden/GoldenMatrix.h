#pragma once
// The technique x submission x scene matrix (docs/ARCHITECTURE.md, "Results"): every technique of the
// registry, and every variant a technique declares (a form at other properties with cells of its own:
// bench/golden/MatrixVariants.h), in every submission mode, on every built-in scene, rendered small. A scene
// in motion (aircraft_day) is rendered at frame 5 of an 8-frame path, reached frame by frame. Each cell
// yields the images that are compared with the retained mode and with the committed golden, and its accuracy
// against the Embree reference per light. A cell a technique cannot handle is kept with the reason the
// technique gave (sb::Error with ExitCode::Unsupported from prepare), never dropped silently, and with
// the kind of refusal (MatrixCell::Refusal): the technique refuses the scene, has no form on the cell's
// API, or the driver lacks a capability the form needs (judged on a driver that has it, listed here).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/golden/ImageDiff.h"
#include "reference/AccuracyMetrics.h"
#include "scenes/Scene.h"
#include "techniques/gl/Submitter.h"

namespace sb {

/// Accuracy of one light of one cell against the reference at the same pixels.
struct CellAccuracy {
    HardMetrics hard;
    SoftMetrics soft;
    double noShadowPct = 0.0;   ///< judged samples the reference shadows: what drawing no shadow gets wrong
    double noShadowRmse = 0.0;  ///< the RMSE of drawing no shadow (visibility 1 everywhere)
    double allShadowRmse = 0.0; ///< the RMSE of shadowing everything (visibility 0 everywhere): a black-out
    bool softReference = false;
};

/// What `-t auto` chose for a scene (the matrix's `auto` cells): the cell is that technique's, held to
/// its golden and bound, and to auto's own rule (the choice delivers the request within the bound).
struct AutoPick {
    std::string spec, reason;
    EffectMask request = 0, effects = 0; ///< the scene's request; the rendered technique's effects
    double wrongPct = 0.0, bound = 0.0;  ///< the calibration's error of the choice; --auto-max-wrong
};

struct MatrixCell {
    /// Why a cell did not run, when it did not (`unsupported` says it in words). The kinds are judged
    /// differently (bench/golden/MatrixCheck.h).
    enum class Refusal {
        None,   ///< it ran, or threw (`failure`)
        Scene,  ///< the technique cannot handle this scene (a light type): its golden cell has no golden
        NoForm, ///< the technique has no form on this cell's API: its golden is its other API's cell
        Driver, ///< the driver lacks a capability the form needs: checked on a driver that has it
    };
    /// The technique's name, a variant's spec ("raytraced:mode=soft"), or `auto`.
    std::string technique, scene;
    std::optional<AutoPick> autoPick; ///< the `auto` cell: its choice
    /// The form whose golden and bound hold the cell (its technique field; the chosen technique for
    /// `auto`): MatrixVariants::key of it names the files.
    std::string judgedAs() const;
    SubmitMode mode = SubmitMode::Retained;
    /// "gl", or "vulkan": the API axis. A Vulkan cell is held to the same golden and bound as the GL
    /// cell of its technique and scene, and its image to the GL retained cell's.
    std::string api = "gl";
    bool vulkan() const { return api == "vulkan"; }
    std::string unsupported; ///< non-empty: the technique refused this scene, and why
    Refusal refusal = Refusal::None;
    std::string failure; ///< non-empty: the cell threw while rendering (a defect, not a refusal)
    Image8 visibility;   ///< light i in channel i (one channel for one light, else RGB)
    Image8 colour;       ///< RGB
    std::vector<float> visibilityFloat; ///< the raw read-back of the lights' channels, for the mode check
    std::vector<CellAccuracy> lights;
    NumericSanity sanity; ///< over the whole visibility read-back
    /// What the cell wrote on stderr while it rendered (a technique saying what it cannot shadow), one
    /// entry per line: `bench golden` prints each distinct line once, with how many cells wrote it.
    std::vector<std::string> warnings;
    /// "technique/scene/mode", with "/vulkan" appended for a Vulkan cell
    std::string name() const;
    bool ran() const { return unsupported.empty() && failure.empty(); }
};

/// Told of each cell as a scene of the matrix renders (the progress of `bench golden`): `starting` with
/// the cell's name before it renders, `finished` after, with the scene's cells so far (the new one last;
/// a cell's check needs only the cells before it). Either may be empty.
struct MatrixObserver {
    std::function<void(const std::string& cell)> starting;
    std::function<void(const std::vector<MatrixCell>& cells)> finished;
};

struct MatrixOptions {
    int size = 128;                  ///< square frame size (the committed goldens are 128^2)
    std::vector<std::string> scenes; ///< empty: every built-in scene
    /// Technique names and variants' specs, each a form of its own (MatrixVariants::select expands a
    /// name given on the command line); empty: every registered technique, each followed by its
    /// variants (MatrixVariants::all), then `auto`.
    std::vector<std::string> techniques;
    int referenceSamples = 64; ///< per pixel for area lights
    /// A scene with more triangles than this draws fewer of its layout's instances, in proportion
    /// (aircraft's 200 aircraft: 99; teapot's 200 teapots: 63; synthetic_triangles' 256 spheres: 66).
    /// Those scenes are sized for the performance studies; the matrix's checks (modes agree, goldens,
    /// bounds) touch the same code paths at a quarter of the triangles and take a third of the time.
    size_t maxTriangles = size_t(1) << 18;
    /// -t auto's calibration in the `auto` cells: interleaved timed rounds per candidate, no warm-up
    /// frame. What the cells check does not depend on the timings (any choice is held to its own
    /// golden and bound, and to auto's rule, which reads the effects and the judged error), so two
    /// rounds, the fewest the every-round comparison takes, do; `bench -t auto` times five.
    int autoRounds = 2;
    /// A cell whose form needs a capability this driver lacks fails (instead of being listed as not run
    /// here): for the check on the driver that is to run it, so that losing the capability is seen.
    bool strictDriver = false;
};

class GoldenMatrix {
public:
    /// The built-in scenes: scenes/data/*.json, sorted by name.
    static std::vector<std::string> builtinScenes();
    /// The camera a scene's cells use: "mid" where the scene has one (every shadow visible at a small
    /// size), else its first camera.
    static std::string cameraFor(const std::string& scene);
    static std::string cameraFor(const Scene& scene);
    /// The cell that holds `cell`'s technique to its golden and bound on `cell`'s scene, among `cells`:
    /// the GL retained cell, or the Vulkan retained cell for a technique with no GL form (it exists on
    /// Vulkan only). Every other cell of the technique is compared with it. Null when it is not among
    /// `cells` (yet: a scene's cells render GL first, each API retained first).
    static const MatrixCell* goldenCellOf(const std::vector<MatrixCell>& cells, const MatrixCell& cell);
    /// Every cell of one scene, retained mode first (the others are compared with it), then the other
    /// modes in their table order; techniques in registry order, then `auto`: -t auto resolved on the
    /// retained harness (a fresh calibration at the matrix's size, 10% bound) and its choice rendered in
    /// every mode. No candidate within the bound makes the auto cell unsupported with the reason.
    /// Then the Vulkan axis: every technique in Vulkan's two submission modes (retained, instanced),
    /// rendered with the validation layer on (a validation error fails the cell) and judged against the
    /// GL retained harness's reference; a technique without a Vulkan form, `auto` and a scene in motion
    /// are unsupported cells with their reason. A technique without a GL form has unsupported GL cells
    /// (Refusal::NoForm, the registry's reason) and no GL harness is made for a scene none of whose
    /// techniques has one. A Vulkan form whose capabilities this driver lacks is a Refusal::Driver cell
    /// naming what is missing and the driver, or a failed cell with MatrixOptions::strictDriver.
    /// Each cell's stderr is captured into MatrixCell::warnings.
    static std::vector<MatrixCell> renderScene(const std::string& scene, const MatrixOptions& options,
                                               const MatrixObserver& observer = {});
    /// The layout instances a scene's cells draw (RunConfig::sceneOptions.instances): nullopt, the scene's
    /// own, where it holds at most MatrixOptions::maxTriangles triangles, else its layout's count cut in
    /// proportion until it does (at least one). The instances the scene places by hand are all kept.
    static std::optional<uint32_t> layoutInstances(const Scene& scene, const MatrixOptions& options);
    /// How many cells renderScene returns for one scene: every technique (options.techniques, or the
    /// registry's and `auto`) in every GL submission mode and Vulkan's two.
    static size_t cellsPerScene(const MatrixOptions& options);
};

} // namespace sb
