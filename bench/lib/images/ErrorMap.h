#pragma once
// Where a technique's hard classification is wrong, as a picture: the judgement of `bench accuracy`
// (reference/AccuracyMetrics.h: a sample is shadowed below visibility 0.5, a NaN sample is the opposite
// of the reference's answer, only samples of the evaluation mask are judged, and the 1-px band around a
// reference shadow edge — AccuracyMetrics::edgeMask — is what the *_no_edge_* figures leave out) drawn
// pixel for pixel, so that the picture's counts are the row's counts.
//
// Every pixel is exactly one of these colours:
//   false shadow (technique shadowed, reference lit)   kFalseShadow      off the edge band,
//                                                      kFalseShadowEdge  in it (paler);
//   false light  (technique lit, reference shadowed)   kFalseLight / kFalseLightEdge;
//   correct, in the edge band                          kEdgeBand;
//   correct, judged elsewhere                          grey 40 + round(100 * reference), reference
//                                                      clamped to [0, 1]: a dimmed copy of the reference
//                                                      (40 shadowed .. 140 lit);
//   not judged (outside the mask), geometry            kNotJudged;
//   no geometry (reference < 0 or NaN)                 kBackground.
// The greys have equal channels and the marks do not, so no mark can be mistaken for a grey. Blue is the
// side of "too dark" and red of "too bright", as in the signed difference map (DifferenceMap.h).
#include <cstdint>
#include <vector>

#include "bench/lib/images/RgbImage.h"

namespace sb {

/// What one pixel of the error map is.
enum class ErrorClass : uint8_t {
    Background,      ///< no geometry
    NotJudged,       ///< geometry outside the evaluation mask
    Correct,         ///< judged, right, off the edge band
    EdgeCorrect,     ///< judged, right, in the edge band
    FalseShadow,     ///< off the edge band
    FalseLight,      ///< off the edge band
    FalseShadowEdge, ///< in the edge band
    FalseLightEdge,  ///< in the edge band
};

class ErrorMap {
public:
    static constexpr Rgb kFalseShadow{30, 90, 255};
    static constexpr Rgb kFalseLight{255, 40, 30};
    static constexpr Rgb kFalseShadowEdge{150, 185, 255};
    static constexpr Rgb kFalseLightEdge{255, 170, 150};
    static constexpr Rgb kEdgeBand{100, 88, 0};
    static constexpr Rgb kNotJudged{20, 20, 20};
    static constexpr Rgb kBackground{0, 0, 0};
    /// The dimmed reference of a correct pixel off the edge band (`reference` clamped to [0, 1]).
    static Rgb dimmed(float reference);
    /// The colour of a class; `reference` is used by Correct only.
    static Rgb colour(ErrorClass c, float reference);

    /// The counts of the picture, in the terms of HardMetrics (reference/AccuracyMetrics.h).
    struct Counts {
        uint64_t evaluated = 0, falseShadow = 0, falseLight = 0;
        uint64_t evaluatedNoEdge = 0, falseShadowNoEdge = 0, falseLightNoEdge = 0;
        uint64_t edgeBand = 0; ///< judged samples in the edge band
    };

    /// Classifies every sample. `technique`, `reference`: one visibility per sample (width * height, any
    /// row order: the map keeps it); `mask`: 1 = judged. Throws std::invalid_argument when the sizes
    /// disagree.
    static std::vector<ErrorClass> classify(const std::vector<float>& technique,
                                            const std::vector<float>& reference,
                                            const std::vector<uint8_t>& mask, int width, int height);
    static Counts count(const std::vector<ErrorClass>& classes);

    /// The map in the buffers' row order (flip a GL read-back with RgbImage::flippedVertically).
    static ErrorMap build(const std::vector<float>& technique, const std::vector<float>& reference,
                          const std::vector<uint8_t>& mask, int width, int height);

    const RgbImage& image() const { return mImage; }
    const Counts& counts() const { return mCounts; }

private:
    RgbImage mImage;
    Counts mCounts;
};

} // namespace sb
