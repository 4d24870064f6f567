#pragma once
// The signed difference technique − reference of a soft-shadow technique (continuous visibility: a
// penumbra that is too wide, too narrow, too light or too dark), on a diverging blue/white/red scale,
// with a colour bar and its scale printed under the map.
//
// A judged sample with difference d, t = clamp(d / scale, -1, 1):
//   t <= 0: (255 (1 + t), 255 (1 + t), 255)   -scale blue (0, 0, 255), 0 white: the technique too dark;
//   t >= 0: (255, 255 (1 - t), 255 (1 - t))   +scale red (255, 0, 0): the technique too bright;
// each channel rounded to the nearest integer. A non-finite technique value is kNonFinite; samples
// outside the evaluation mask kNotJudged, no geometry (reference < 0) kBackground.
// Under the map (kBarHeight rows, background kPanel): the bar from x = kPad to width - kPad, every
// column the colour of its t (-1 at the left, +1 at the right), kBarThickness rows from y = height +
// kPad; under it "-<scale>" at the left, "0" centred and "+<scale>" at the right, and the caption
// "technique - reference" on the line below, in kText.
#include <string>
#include <vector>

#include "bench/lib/images/RgbImage.h"

namespace sb {

class DifferenceMap {
public:
    static constexpr Rgb kNonFinite{255, 0, 255};
    static constexpr Rgb kNotJudged{60, 60, 60};
    static constexpr Rgb kBackground{0, 0, 0};
    static constexpr Rgb kPanel{24, 24, 24};
    static constexpr Rgb kText{255, 255, 255};
    static constexpr int kPad = 4, kBarThickness = 10;

    /// The colour of difference `d` at full scale `scale` (> 0).
    static Rgb colour(float d, float scale = 1.0f);
    /// Text scale of the labels for a map `width` pixels wide (1 below 512, else 2).
    static int textScale(int width);
    /// Rows under the map: pad, bar, pad, scale labels, pad, caption, pad.
    static int barHeight(int width);
    /// "1", "0.5": the scale as printed on the bar.
    static std::string scaleText(float scale);
    /// The smallest of 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1 that is at least `maxAbs` (1 above): a scale
    /// that shows a small change (a golden's few grey levels) and still reads as a round number.
    static float niceScale(float maxAbs);

    /// The map (width x (height + barHeight(width))) in the buffers' row order for the map part: pass
    /// top-row-first buffers (the bar is always drawn under the map). Throws std::invalid_argument when
    /// the sizes disagree or scale is not positive.
    static RgbImage build(const std::vector<float>& technique, const std::vector<float>& reference,
                          const std::vector<uint8_t>& mask, int width, int height, float scale = 1.0f);
};

} // namespace sb
