#pragma once
// Accuracy of a technique's visibility against the reference's, over the samples that show
// geometry whose seen side faces the light (n.L > 0.05, n turned towards the camera): the evaluation
// mask.
//   hard: false-shadow rate (reference lit, technique shadowed), false-light rate (the reverse), their
//         sum, each in percent of evaluated samples; the same with samples within 1 px of a reference
//         shadow edge left out (separates edge aliasing from gross errors). A technique sample counts as
//         shadowed when its visibility < 0.5.
//   soft: RMSE, mean and max absolute visibility error over the evaluated samples.
//   numeric sanity: NaN, Inf and values outside [0, 1] over a whole read-back (all channels): the
//         count must be zero.
//   stability: changed samples between two images (for perturbation gain and flicker).
#include <cstdint>
#include <vector>

namespace sb {

struct HardMetrics {
    uint64_t evaluated = 0, falseShadow = 0, falseLight = 0;
    double falseShadowPct = 0, falseLightPct = 0, wrongPct = 0;
    uint64_t evaluatedNoEdge = 0, falseShadowNoEdge = 0, falseLightNoEdge = 0;
    double falseShadowNoEdgePct = 0, falseLightNoEdgePct = 0, wrongNoEdgePct = 0;
};

struct SoftMetrics {
    uint64_t evaluated = 0;
    double rmse = 0, meanAbs = 0, maxAbs = 0;
};

struct NumericSanity {
    uint64_t nan = 0, inf = 0, outOfRange = 0;
    uint64_t total() const { return nan + inf + outOfRange; }
};

class AccuracyMetrics {
public:
    /// `technique` and `reference`: one value per sample (width*height), `mask`: 1 = evaluated.
    static HardMetrics hard(const std::vector<float>& technique, const std::vector<float>& reference,
                            const std::vector<uint8_t>& mask, int width, int height);
    static SoftMetrics soft(const std::vector<float>& technique, const std::vector<float>& reference,
                            const std::vector<uint8_t>& mask);
    static NumericSanity sanity(const std::vector<float>& values);
    /// 1 where any of the 8 neighbours (within 1 px) has a different reference classification
    /// (lit = reference >= 0.5) among covered samples (reference >= 0); 0 elsewhere.
    static std::vector<uint8_t> edgeMask(const std::vector<float>& reference, int width, int height);
    /// Samples whose classification (value < 0.5) differs between `a` and `b`, counted where `mask`.
    static uint64_t changedSamples(const std::vector<float>& a, const std::vector<float>& b,
                                   const std::vector<uint8_t>& mask);
    /// Perturbation gain: technique changes / max(1, reference changes).
    static double perturbationGain(uint64_t techniqueChanges, uint64_t referenceChanges);
    /// Extracts channel `channel` of an RGBA float read-back (4 floats per pixel).
    static std::vector<float> channel(const std::vector<float>& rgba, int channel);
};

} // namespace sb
