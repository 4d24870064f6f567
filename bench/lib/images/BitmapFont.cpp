#include "bench/lib/images/BitmapFont.h"

#include <algorithm>

namespace sb {

int BitmapFont::textWidth(const std::string& text, int scale) {
    if (text.empty()) return 0;
    return (int(text.size()) * kCellWidth - (kCellWidth - kGlyphWidth)) * scale;
}

int BitmapFont::draw(RgbImage& image, int x, int y, const std::string& text, Rgb colour, int scale) {
    scale = std::max(1, scale);
    for (char c : text) {
        for (int gy = 0; gy < kGlyphHeight; ++gy)
            for (int gx = 0; gx < kGlyphWidth; ++gx)
                if (pixel(c, gx, gy)) image.fillRect(x + gx * scale, y + gy * scale, scale, scale, colour);
        x += kCellWidth * scale;
    }
    return x;
}

std::string BitmapFont::fit(const std::string& text, int maxWidth, int scale) {
    size_t n = text.size();
    while (n > 0 && textWidth(text.substr(0, n), scale) > maxWidth) --n;
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

} // namespace sb
