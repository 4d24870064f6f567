#pragma once
// One picture per scene and light with every technique's error map side by side (ErrorMap.h): a header
// (what was judged), a legend (each colour with its meaning), then a grid of tiles, each its label
// (the technique in kTitle, wrapped over up to kTitleLines lines of the tile's width, then its figures
// in kText) above its map. The grid has at most `columns`
// tiles per row; every cell of it is as wide as the widest map and its label block as tall as the tallest
// label, so the maps line up. Text is BitmapFont (bench/lib/font/BitmapFont.h) at textScale() (1 for maps
// narrower than 512 px, 2 below 1024, else 3), lines kLineGap pixels apart; every text is cut to the width it
// has.
//
// Geometry (m = kMargin, L = lineHeight(), in pixels): header lines from y = m, one per L; the legend
// below them, one entry per line (a swatch of the glyph height, then its text); the grid from gridTop()
// = m + (header lines + legend entries) * L + m. Tile k sits in row k / columns, column k % columns: its
// label block at x = m + column * (cellWidth + m), y = gridTop + row * (labelHeight + cellHeight + m),
// its map right under the label block. The sheet is wide enough for the grid and for the header and
// legend text, and m below the last row. A legend swatch is a square of the glyph height outlined in
// kSwatchOutline (one pixel), its colour inside, the text 4 * scale pixels after it.
#include <string>
#include <vector>

#include "bench/lib/images/RgbImage.h"

namespace sb {

/// One technique on the sheet.
struct ContactTile {
    std::string title;              ///< the technique with its properties
    std::vector<std::string> lines; ///< its figures, one per line
    RgbImage map;                   ///< its error map, top row first
};

/// One colour of the legend and what it means.
struct LegendEntry {
    Rgb swatch;
    std::string text;
};

class ContactSheet {
public:
    static constexpr int kMargin = 8, kLineGap = 3, kTitleLines = 3;
    static constexpr Rgb kBackground{16, 16, 16};
    static constexpr Rgb kText{235, 235, 235};
    static constexpr Rgb kTitle{255, 215, 90};
    static constexpr Rgb kSwatchOutline{110, 110, 110};

    /// Where one tile goes.
    struct Placement {
        int labelX = 0, labelY = 0, labelWidth = 0, labelHeight = 0;
        int mapX = 0, mapY = 0;
    };
    struct Layout {
        int width = 0, height = 0;
        int textScale = 1, lineHeight = 0;
        int columns = 1, cellWidth = 0, cellHeight = 0, labelHeight = 0;
        int gridTop = 0;
        std::vector<Placement> tiles;
    };

    static int textScale(int mapWidth);
    /// The title's lines on a tile `width` pixels wide at text scale `scale`.
    static std::vector<std::string> titleLines(const std::string& title, int width, int scale);
    /// The geometry above for these contents (maps' sizes and label line counts are read, not drawn).
    static Layout layout(const std::vector<std::string>& header, const std::vector<LegendEntry>& legend,
                         const std::vector<ContactTile>& tiles, int columns = 4);
    /// The sheet. Throws std::invalid_argument without tiles or with columns < 1.
    static RgbImage compose(const std::vector<std::string>& header, const std::vector<LegendEntry>& legend,
                            const std::vector<ContactTile>& tiles, int columns = 4);
};

} // namespace sb
