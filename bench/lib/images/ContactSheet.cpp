#include "bench/lib/images/ContactSheet.h"

#include <algorithm>
#include <stdexcept>

#include "bench/lib/font/BitmapFont.h"

namespace sb {

int ContactSheet::textScale(int mapWidth) {
    return mapWidth < 512 ? 1 : mapWidth < 1024 ? 2 : 3;
}

std::vector<std::string> ContactSheet::titleLines(const std::string& title, int width, int scale) {
    return BitmapFont::wrap(title, width, scale, kTitleLines);
}

ContactSheet::Layout ContactSheet::layout(const std::vector<std::string>& header,
                                          const std::vector<LegendEntry>& legend,
                                          const std::vector<ContactTile>& tiles, int columns) {
    if (tiles.empty()) throw std::invalid_argument("ContactSheet: no tiles");
    if (columns < 1) throw std::invalid_argument("ContactSheet: columns must be at least 1");
    Layout l;
    for (const ContactTile& t : tiles) {
        l.cellWidth = std::max(l.cellWidth, t.map.width());
        l.cellHeight = std::max(l.cellHeight, t.map.height());
    }
    l.textScale = textScale(l.cellWidth);
    size_t labelLines = 0;
    for (const ContactTile& t : tiles)
        labelLines =
            std::max(labelLines, std::max<size_t>(1, titleLines(t.title, l.cellWidth, l.textScale).size()) +
                                     t.lines.size());
    l.lineHeight = BitmapFont::kCellHeight * l.textScale + kLineGap;
    l.labelHeight = int(labelLines) * l.lineHeight;
    l.columns = std::min(columns, int(tiles.size()));
    const int rows = (int(tiles.size()) + l.columns - 1) / l.columns;
    l.gridTop = kMargin + int(header.size() + legend.size()) * l.lineHeight + kMargin;
    const int gridWidth = kMargin + l.columns * (l.cellWidth + kMargin);
    // The header and legend are not cut when a sheet has few narrow tiles: the sheet widens for them.
    int textWidth = 0;
    for (const std::string& h : header)
        textWidth = std::max(textWidth, BitmapFont::textWidth(h, l.textScale));
    const int swatch = BitmapFont::textHeight(l.textScale), swatchGap = 4 * l.textScale;
    for (const LegendEntry& e : legend)
        textWidth = std::max(textWidth, swatch + swatchGap + BitmapFont::textWidth(e.text, l.textScale));
    l.width = std::max(gridWidth, kMargin + textWidth + kMargin);
    l.height = l.gridTop + rows * (l.labelHeight + l.cellHeight + kMargin);
    for (size_t k = 0; k < tiles.size(); ++k) {
        const int row = int(k) / l.columns, column = int(k) % l.columns;
        Placement p;
        p.labelX = kMargin + column * (l.cellWidth + kMargin);
        p.labelY = l.gridTop + row * (l.labelHeight + l.cellHeight + kMargin);
        p.labelWidth = l.cellWidth;
        p.labelHeight = l.labelHeight;
        p.mapX = p.labelX;
        p.mapY = p.labelY + l.labelHeight;
        l.tiles.push_back(p);
    }
    return l;
}

RgbImage ContactSheet::compose(const std::vector<std::string>& header, const std::vector<LegendEntry>& legend,
                               const std::vector<ContactTile>& tiles, int columns) {
    const Layout l = layout(header, legend, tiles, columns);
    RgbImage sheet(l.width, l.height, kBackground);
    const int s = l.textScale, textRoom = l.width - 2 * kMargin;
    int y = kMargin;
    for (const std::string& h : header) {
        BitmapFont::draw(sheet, kMargin, y, BitmapFont::fit(h, textRoom, s), kText, s);
        y += l.lineHeight;
    }
    const int swatch = BitmapFont::textHeight(s), swatchGap = 4 * s;
    for (const LegendEntry& e : legend) {
        // Outlined, so a swatch as dark as the background (not judged) is still seen as a swatch.
        sheet.fillRect(kMargin, y, swatch, swatch, kSwatchOutline);
        sheet.fillRect(kMargin + 1, y + 1, swatch - 2, swatch - 2, e.swatch);
        BitmapFont::draw(sheet, kMargin + swatch + swatchGap, y,
                         BitmapFont::fit(e.text, textRoom - swatch - swatchGap, s), kText, s);
        y += l.lineHeight;
    }
    for (size_t k = 0; k < tiles.size(); ++k) {
        const Placement& p = l.tiles[k];
        int ly = p.labelY;
        const std::vector<std::string> title = titleLines(tiles[k].title, p.labelWidth, s);
        for (const std::string& line : title) {
            BitmapFont::draw(sheet, p.labelX, ly, line, kTitle, s);
            ly += l.lineHeight;
        }
        if (title.empty()) ly += l.lineHeight; // an untitled tile keeps its figures where the others are
        for (const std::string& line : tiles[k].lines) {
            BitmapFont::draw(sheet, p.labelX, ly, BitmapFont::fit(line, p.labelWidth, s), kText, s);
            ly += l.lineHeight;
        }
        sheet.blit(tiles[k].map, p.mapX, p.mapY);
    }
    return sheet;
}

} // namespace sb
