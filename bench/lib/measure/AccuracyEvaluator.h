#pragma once
// `bench accuracy`: judges a technique's visibility target against the exact reference at
// the same sample positions, and measures how stable it is. The same on every API: the evaluator
// renders every frame it judges (perturbed and moving ones included) and its G-buffer on the harness
// it was given (MeasuredHarness::renderGBuffer: GL's or Vulkan's own rasterisation), so a Vulkan run is
// judged by Vulkan frames at the samples Vulkan rasterised, with no GL context at all.
//
// For light `light` of the scene:
//  1. render one frame of the technique, read back its visibility target (numeric sanity over every
//     channel);
//  2. render the G-buffer with the same camera and submitter, trace the reference there (hard for
//     point-shaped lights, stratified soft for area lights);
//  3. evaluation mask: covered samples whose seen side faces the light, n.L > 0.05 (n: the geometric
//     normal turned towards the camera, ReferenceTracer::seenNormalAt);
//  4. metrics (reference/AccuracyMetrics.h): false-shadow/false-light rates, with and without the
//     1-px band around reference edges; RMSE, mean and max error;
//  5. texels per pixel (bench/lib/measure/TexelDensity.h), for a technique that reads shadow maps
//     (Technique::mapTexels): at the judged samples of receiving instances that its lighting pass looks up
//     in a map, the map's texels per screen pixel through the receiver's plane, from the G-buffer and
//     the technique's light-space mapping on the CPU (nothing rendered);
//  6. stability: perturbation gain for a 0.25 px camera shift and for a 0.01 degree light turn
//     (technique changes / max(1, reference changes)), and flicker over a short camera drift (the
//     same ratio summed over kDriftSteps steps of 0.5 px).
// A scene in motion (scenes/Motion.h) is judged along its path instead of perturbed: at kPathSamples
// points spread over the path, the frame there (the metrics above are the first point's, at t = 0)
// and the frame after it; the worst and mean error over the points, and the temporal flicker: the
// samples whose lit/shadowed state changes from a frame to the next in the technique but not in the
// reference (whose changes are the motion's own), over the reference's changes, summed over the
// point pairs. Every
// judged frame is traced against the scene as that frame drew it.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/measure/TexelDensity.h"
#include "bench/lib/output/CsvWriter.h"
#include "reference/AccuracyMetrics.h"
#include "reference/EmbreeScene.h"
#include "reference/ReferenceTracer.h"

namespace sb {

struct AccuracyOptions {
    int light = 0;
    int referenceSamples = 64; ///< per pixel for area lights
    bool stability = true;     ///< perturbation gain and flicker (costs kDriftSteps + 2 extra frames)
    float cameraShiftPx = 0.25f;
    float lightTurnDeg = 0.01f;
    float nDotLThreshold = 0.05f;
};

struct AccuracyResult {
    int light = 0;
    bool softReference = false;
    HardMetrics hard;
    SoftMetrics soft;
    NumericSanity sanity;
    uint64_t cameraChangesTechnique = 0, cameraChangesReference = 0;
    uint64_t lightChangesTechnique = 0, lightChangesReference = 0;
    double cameraGain = 0.0, lightGain = 0.0, flicker = 0.0;
    bool stabilityMeasured = false;
    /// A scene in motion: judged along the path (see above).
    struct Path {
        int points = 0;
        double wrongMeanPct = 0.0, wrongMaxPct = 0.0;
        uint64_t changesTechnique = 0, changesReference = 0;
        /// Samples that change in the technique where the reference does not: flicker the motion
        /// does not explain.
        uint64_t falseChanges = 0;
        double flicker = 0.0; ///< falseChanges / max(1, changesReference)
    };
    std::optional<Path> path;
    /// Shadow-map texels per pixel over the judged samples a map shades (samples 0: none, or a technique
    /// without a map, or a judgement of a read-back alone: the columns are empty).
    TexelDensity::Summary texels;
    TraceStats reference;
    /// The columns of this result (appended to the timing row of the same configuration).
    void appendColumns(CsvRow& row) const;
};

class AccuracyEvaluator {
public:
    static constexpr int kDriftSteps = 6;
    static constexpr int kPathSamples = 4;
    explicit AccuracyEvaluator(MeasuredHarness& harness);
    ~AccuracyEvaluator();
    /// The technique must be this harness's API's form, prepared on it (MeasuredHarness::measure does
    /// it). Restores the harness's camera shift and lights afterwards.
    AccuracyResult evaluate(Technique& technique, const AccuracyOptions& options);
    /// The same judgement of one visibility read-back of this harness's configuration (its size and
    /// camera): hard and soft metrics and the numeric sanity, no stability and no path (nothing is
    /// rendered but the G-buffer).
    AccuracyResult evaluateVisibility(std::vector<float> visibilityRgba, const AccuracyOptions& options);
    /// Whether `harness` is the one this evaluator renders with (evaluate() can re-render its frames).
    bool rendersWith(const MeasuredHarness& harness) const { return &harness == &mHarness; }

    /// One judged image: the technique's and the reference's visibility of the light, and the mask.
    struct Sample {
        std::vector<float> technique, reference;
        std::vector<uint8_t> mask;
        std::vector<float> techniqueRgba; ///< the whole read-back, for the numeric sanity check
    };
    /// With `gbuffer`, the G-buffer the samples were judged at is left there.
    Sample judgeFrame(Technique& technique, const AccuracyOptions& options, TraceStats* stats,
                      GBuffer* gbuffer = nullptr);
    /// The same judgement of a visibility read-back (RGBA per pixel, rows bottom-up, the harness's size
    /// and current camera) against this harness's G-buffer and reference.
    Sample judgeVisibility(std::vector<float> visibilityRgba, const AccuracyOptions& options,
                           TraceStats* stats, GBuffer* gbuffer = nullptr);
    /// Texels per pixel (step 5 above) of `maps` for the options' light at the samples `judged` marks on
    /// `g` (this harness's size and current camera).
    TexelDensity::Summary texelDensity(const MapTexels& maps, const AccuracyOptions& options,
                                       const Sample& judged, const GBuffer& g) const;
    /// The frame the last evaluate() or evaluateVisibility() scored (its hard, soft and sanity metrics
    /// are this frame's: a moving scene's first path point), without the RGBA read-back; null before
    /// the first. `bench accuracy --images` draws it (bench/lib/images/AccuracyImages.h).
    const Sample* lastJudged() const { return mLastJudged ? &*mLastJudged : nullptr; }

private:
    /// The result's light fields; throws for a light the scene does not have.
    AccuracyResult start(const AccuracyOptions& options) const;
    /// Hard, soft and sanity metrics of `base` into `result`; throws when no pixel can be judged.
    void score(const Sample& base, const AccuracyOptions& options, AccuracyResult& result) const;
    uint64_t techniqueChanges(const Sample& a, const Sample& b) const;
    void measureStability(Technique& technique, const AccuracyOptions& options, const Sample& base,
                          AccuracyResult& result);
    /// A scene in motion: the metrics along the path (AccuracyResult::Path); the harness is left at
    /// the path's start.
    void measurePath(Technique& technique, const AccuracyOptions& options, AccuracyResult& result);
    /// The Embree scene rebuilt where the harness's casters stand now (a scene in motion).
    void followCasters();
    /// The reference's visibility of `light` at the samples of `g`: traced, or the image traced for the
    /// same samples, light and options before. The golden matrix judges every technique, and -t auto's
    /// calibration every candidate, on the same frame of one harness: each trace (64 rays a sample for
    /// an area light) was once repeated for every one of them. With `stats` it is always traced.
    std::vector<float> reference(const GBuffer& g, int light, const ReferenceTracer::Options& o,
                                 TraceStats* stats);
    /// Keeps `sample` (without its RGBA read-back) as lastJudged().
    void keepJudged(const Sample& sample);
    MeasuredHarness& mHarness;
    std::optional<Sample> mLastJudged;
    float mEmbreeTime = 0.0f; ///< the path time whose casters the Embree scene holds
    std::unique_ptr<EmbreeScene> mEmbree;
    std::unique_ptr<ReferenceTracer> mTracer;
    /// The last references traced (reference()), keyed by a hash of what they depend on; a few cover
    /// every light of a scene and the stability check's turned light (a frame of 1920x1080 is 8 MiB).
    static constexpr size_t kReferencesKept = 8;
    std::vector<std::pair<uint64_t, std::vector<float>>> mReferences;
};

} // namespace sb
