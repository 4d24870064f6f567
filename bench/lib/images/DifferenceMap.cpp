#include "bench/lib/images/DifferenceMap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "bench/lib/font/BitmapFont.h"

namespace sb {

Rgb DifferenceMap::colour(float d, float scale) {
    const float t = std::clamp(d / scale, -1.0f, 1.0f);
    if (t <= 0.0f) {
        const auto v = uint8_t(std::lround(255.0f * (1.0f + t)));
        return {v, v, 255};
    }
    const auto v = uint8_t(std::lround(255.0f * (1.0f - t)));
    return {255, v, v};
}

int DifferenceMap::textScale(int width) {
    return width < 512 ? 1 : 2;
}

int DifferenceMap::barHeight(int width) {
    const int s = textScale(width);
    return kPad + kBarThickness + kPad + BitmapFont::textHeight(s) + kPad + BitmapFont::textHeight(s) + kPad;
}

std::string DifferenceMap::scaleText(float scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(scale));
    return text;
}

float DifferenceMap::niceScale(float maxAbs) {
    for (float s : {0.01f, 0.02f, 0.05f, 0.1f, 0.2f, 0.5f})
        if (maxAbs <= s) return s;
    return 1.0f;
}

RgbImage DifferenceMap::build(const std::vector<float>& technique, const std::vector<float>& reference,
                              const std::vector<uint8_t>& mask, int width, int height, float scale) {
    const size_t n = size_t(std::max(0, width)) * size_t(std::max(0, height));
    if (technique.size() != n || reference.size() != n || mask.size() != n)
        throw std::invalid_argument("DifferenceMap: buffer sizes do not match " + std::to_string(width) +
                                    "x" + std::to_string(height));
    if (!(scale > 0.0f)) throw std::invalid_argument("DifferenceMap: the scale must be positive");
    RgbImage out(width, height + barHeight(width), kPanel);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            Rgb c;
            if (!mask[i])
                c = reference[i] >= 0.0f ? kNotJudged : kBackground;
            else if (!std::isfinite(technique[i]))
                c = kNonFinite;
            else
                c = colour(technique[i] - reference[i], scale);
            out.set(x, y, c);
        }
    // The colour bar: column x of [kPad, width - kPad) at t running from -1 to +1.
    const int x0 = kPad, x1 = width - kPad, barY = height + kPad;
    for (int x = x0; x < x1; ++x) {
        const float t = x1 - x0 > 1 ? -1.0f + 2.0f * float(x - x0) / float(x1 - x0 - 1) : 0.0f;
        out.fillRect(x, barY, 1, kBarThickness, colour(t * scale, scale));
    }
    const int s = textScale(width);
    const int labelY = barY + kBarThickness + kPad;
    const std::string lo = "-" + scaleText(scale), hi = "+" + scaleText(scale);
    BitmapFont::draw(out, x0, labelY, lo, kText, s);
    BitmapFont::draw(out, (x0 + x1) / 2 - BitmapFont::textWidth("0", s) / 2, labelY, "0", kText, s);
    BitmapFont::draw(out, x1 - BitmapFont::textWidth(hi, s), labelY, hi, kText, s);
    const int captionY = labelY + BitmapFont::textHeight(s) + kPad;
    BitmapFont::draw(out, x0, captionY, BitmapFont::fit("technique - reference", x1 - x0, s), kText, s);
    return out;
}

} // namespace sb
