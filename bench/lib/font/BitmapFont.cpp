#include "bench/lib/font/BitmapFont.h"

namespace sb {

int BitmapFont::textWidth(std::string_view text, int scale) {
    if (text.empty()) return 0;
    return (int(text.size()) * kCellWidth - (kCellWidth - kGlyphWidth)) * scale;
}

std::string BitmapFont::fit(const std::string& text, int maxWidth, int scale) {
    size_t n = text.size();
    while (n > 0 && textWidth(std::string_view(text).substr(0, n), scale) > maxWidth) --n;
    return text.substr(0, n);
}

std::vector<std::string> BitmapFont::wrap(const std::string& text, int maxWidth, int scale, int maxLines) {
    std::vector<std::string> lines;
    size_t from = 0;
    while (from < text.size() && int(lines.size()) < maxLines) {
        const size_t n = std::max<size_t>(1, fit(text.substr(from), maxWidth, scale).size());
        lines.push_back(text.substr(from, n));
        from += n;
    }
    return lines;
}

std::vector<uint8_t> BitmapFont::atlas() {
    const int width = kGlyphCount * kGlyphWidth;
    std::vector<uint8_t> texels(size_t(width) * kGlyphHeight, 0);
    for (int g = 0; g < kGlyphCount; ++g)
        for (int y = 0; y < kGlyphHeight; ++y)
            for (int x = 0; x < kGlyphWidth; ++x)
                if (pixel(char(kFirst + g), x, y))
                    texels[size_t(y) * width + size_t(g * kGlyphWidth + x)] = 255;
    return texels;
}

} // namespace sb
