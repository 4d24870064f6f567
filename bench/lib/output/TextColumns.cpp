#include "bench/lib/output/TextColumns.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace sb {

std::string formatNumber(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// A gap of zero would let two cells touch again, which is the one thing this class exists to prevent.
TextColumns::TextColumns(std::string indent, size_t gap)
    : mIndent(std::move(indent)), mGap(std::max<size_t>(1, gap)) {}

void TextColumns::addRow(std::vector<std::string> cells) {
    mRows.push_back(std::move(cells));
}

size_t TextColumns::displayWidth(const std::string& s) {
    return size_t(std::count_if(s.begin(), s.end(), [](char c) { return (uint8_t(c) & 0xC0) != 0x80; }));
}

void TextColumns::print(std::ostream& os) const {
    // Widths are taken over the whole table before anything is printed: a wide cell in the last row
    // moves the columns of the first.
    std::vector<size_t> widths;
    for (const auto& row : mRows) {
        if (widths.size() < row.size()) widths.resize(row.size(), 0);
        for (size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], displayWidth(row[c]));
    }
    for (const auto& row : mRows) {
        std::string line = mIndent;
        for (size_t c = 0; c < row.size(); ++c) {
            line += row[c];
            if (c + 1 < row.size()) line.append(widths[c] - displayWidth(row[c]) + mGap, ' ');
        }
        line.erase(line.find_last_not_of(' ') + 1); // empty trailing cells leave no trailing spaces
        os << line << "\n";
    }
}

std::string TextColumns::toString() const {
    std::ostringstream os;
    print(os);
    return os.str();
}

} // namespace sb
