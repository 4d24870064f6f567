#pragma once
// Everything that defines one measured configuration, as parsed from the command line. Recorded in
// full in every CSV row so any row can be re-run exactly.
#include <cstdint>
#include <string>
#include <vector>

#include "bench/lib/output/RowExport.h"
#include "gl/Context.h"
#include "scenes/SceneOptions.h"
#include "techniques/PropertySet.h"
#include "techniques/gl/Submitter.h"
#include "vk/VulkanContext.h"

namespace sb {

struct RunConfig {
    enum class Mode { Measure, Accuracy };
    Mode mode = Mode::Measure; ///< `bench` or `bench accuracy`
    std::vector<TechniqueSpec> techniques{{"shadowmap", {}}};
    std::string scene = "aircraft";
    SceneOptions sceneOptions;
    std::string camera = "far";
    int width = 1024, height = 1024;
    SubmitMode submit = SubmitMode::Retained;
    /// --back-faces: cull the back faces of closed meshes where the image cannot change
    /// (scenes/BackFaceCulling.h), or draw them all (the before/after comparison).
    BackFaces backFaces = BackFaces::Cull;
    int frames = 50;      ///< measured frames (ignored when seconds > 0)
    double seconds = 0.0; ///< measure for this long instead (at least kMinFrames frames)
    int warmup = 5;       ///< discarded frames (shader JIT on llvmpipe costs up to ~100 ms early on)
    ContextOptions context;
    /// The API the frames are rendered with (--api): GL (the context above) or Vulkan (the device of
    /// `vulkan`; bench/lib/harness/VulkanHarness.h).
    enum class Api { GL, Vulkan };
    Api api = Api::GL;
    VulkanOptions vulkan;
    std::string csvPath;         ///< --csv: append one row per technique
    std::string samplesPath;     ///< --samples: per-frame samples
    std::string tracePath;       ///< --trace: timelines (bench/lib/rows/TraceWriter.h)
    std::string screenshotPath;  ///< --screenshot: colour PNG (one per configuration: RunImageNames.h)
    std::string visibilityPath;  ///< --visibility: visibility PNG (named as --screenshot)
    std::string dumpShadersPath; ///< --dump-shaders: every assembled stage (gl/ProgramCache.h)
    bool checkTimer = true;      ///< run the GPU-timer trust calibration
    bool sweep = false;          ///< accuracy: walk each technique's quality knobs
    int accuracyLight = 0;       ///< accuracy: which light is judged
    int referenceSamples = 64;   ///< accuracy: reference samples per pixel for area lights
    bool stability = true;       ///< accuracy: perturbation gain and flicker
    int windowFrames = 0;        ///< --window: close after this many frames (0 = when the window closes)
    bool quiet = false;
    /// A technique that cannot produce an effect the scene asks for is refused (exit 3) instead of
    /// measured with a one-line warning (techniques/EffectCoverage.h).
    bool strictEffects = false;
    /// `-t auto` (bench/lib/select/AutoResolver.h): the accuracy bound, the calibration cache ("" = the
    /// default under ~/.cache) and whether to measure every candidate again.
    double autoMaxWrongPct = 10.0;
    std::string calibrationPath;
    std::string calibrationSeedPath; ///< --calibration-seed: rows read first, never written ("" = none)
    bool recalibrate = false;
    /// A scene in motion (scenes/Motion.h) frozen at this path time in [0, 1] (--time); < 0: the frames
    /// move along the path.
    double pathTime = -1.0;
    int pathFrames = 0; ///< --path-frames: frames per pass along the path (0 = the scene's)
    int repeat = 1;     ///< rounds of interleaved measurement (--repeat)
    RowFormat format = RowFormat::Console; ///< what goes to stdout (--format); progress then goes to stderr
    static constexpr int kMinFrames = 5;

    /// One untimed-style frame of `scene` from `camera` at size x size: no warm-up, no timer
    /// calibration, quiet. What the matrix renders per cell and the tests' quick configuration.
    static RunConfig oneFrame(const std::string& scene, const std::string& camera, int size,
                              SubmitMode submit = SubmitMode::Retained) {
        RunConfig c;
        c.scene = scene;
        c.camera = camera;
        c.width = c.height = size;
        c.submit = submit;
        c.frames = 1;
        c.warmup = 0;
        c.checkTimer = false;
        c.quiet = true;
        return c;
    }
};

} // namespace sb
