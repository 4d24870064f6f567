#pragma once
// The console tables (ConsoleReport, BottleneckStudy): rows of cells laid out in left-aligned columns
// whose widths come from the widest cell of each column, so a value wider than its heading (a long
// property name, "1401.25 ms") widens its column instead of running into the next cell. Also the
// helper that turns a number into a cell through a printf format.
#include <iosfwd>
#include <string>
#include <vector>

namespace sb {

/// `v` formatted with the printf format `f` ("%.2f ms").
std::string formatNumber(const char* f, double v);

class TextColumns {
public:
    /// `indent` starts every line; `gap` spaces (at least one) separate two columns.
    explicit TextColumns(std::string indent = "", size_t gap = 2);

    /// Appends a row. Rows may have different lengths: a short row leaves its last columns empty, and
    /// the last cell of a row is never padded (no trailing spaces).
    void addRow(std::vector<std::string> cells);

    /// Every row, one line each, column c starting where the widest cell of column c - 1 ends plus the
    /// gap. Widths count UTF-8 code points, so a cell holding "µs" does not shift its row.
    void print(std::ostream& os) const;

    /// print() into a string.
    std::string toString() const;

    /// The display width of `s` (its UTF-8 code points).
    static size_t displayWidth(const std::string& s);

private:
    std::string mIndent;
    size_t mGap;
    std::vector<std::vector<std::string>> mRows;
};

} // namespace sb
