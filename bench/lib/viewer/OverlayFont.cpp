#include "bench/lib/viewer/OverlayFont.h"

namespace sb {

std::vector<uint8_t> OverlayFont::atlas() {
    const int width = kGlyphCount * kGlyphWidth;
    std::vector<uint8_t> texels(size_t(width) * kGlyphHeight, 0);
    for (int g = 0; g < kGlyphCount; ++g)
        for (int y = 0; y < kGlyphHeight; ++y)
            for (int x = 0; x < kGlyphWidth; ++x)
                if (ink(char(kFirst + g), x, y))
                    texels[size_t(y) * width + size_t(g * kGlyphWidth + x)] = 255;
    return texels;
}

int OverlayFont::textWidth(std::string_view text, int scale) {
    if (text.empty()) return 0;
    return (int(text.size()) * kAdvance - (kAdvance - kGlyphWidth)) * scale;
}

} // namespace sb
