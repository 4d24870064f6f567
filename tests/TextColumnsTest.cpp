// bench/lib/output/TextColumns: the console tables' layout. The answers are the cells put in: a column
// starts where the widest cell before it ends plus the gap, so splitting a line at the column starts
// gives the cells back, whatever their widths.
#include <gtest/gtest.h>

#include "bench/lib/output/TextColumns.h"

using namespace sb;

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
        out.push_back(text.substr(start, nl - start));
    EXPECT_EQ(start, text.size()) << "every line ends in a newline";
    return out;
}

// A value wider than its heading (the console's "1401.25 ms" under a 10-wide heading, a property name
// longer than the list's name column) widens the column: every cell starts at the same offset in every
// row, and the widest cell of each column is followed by exactly the gap.
TEST(TextColumns, ColumnWidthsComeFromTheWidestCell) {
    TextColumns t;
    t.addRow({"technique", "gpu", "n"});
    t.addRow({"shadowmap", "1401.25 ms", "10"});
    t.addRow({"fragment_iterations", "int", "7"});
    const std::vector<std::string> lines = splitLines(t.toString());
    ASSERT_EQ(lines.size(), 3u);
    // Widest cells by hand: "fragment_iterations" (19) and "1401.25 ms" (10), gap 2.
    const size_t second = 19 + 2, third = second + 10 + 2;
    const std::vector<std::vector<std::string>> cells{
        {"technique", "gpu", "n"}, {"shadowmap", "1401.25 ms", "10"}, {"fragment_iterations", "int", "7"}};
    for (size_t r = 0; r < lines.size(); ++r) {
        const std::string& l = lines[r];
        EXPECT_EQ(l.substr(0, second).find_last_not_of(' ') + 1, cells[r][0].size()) << l;
        EXPECT_EQ(l.substr(second, third - second).find_last_not_of(' ') + 1, cells[r][1].size()) << l;
        EXPECT_EQ(l.substr(0, cells[r][0].size()), cells[r][0]) << l;
        EXPECT_EQ(l.substr(second, cells[r][1].size()), cells[r][1]) << l;
        EXPECT_EQ(l.substr(third), cells[r][2]) << l;
    }
}

// The gap never drops below one space, and the last cell of a row is never padded.
TEST(TextColumns, AtLeastOneSpaceAndNoTrailingSpaces) {
    TextColumns t("", 0);
    t.addRow({"aaaa", "b", ""});
    t.addRow({"c", "dddd"});
    const std::vector<std::string> lines = splitLines(t.toString());
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "aaaa b");
    EXPECT_EQ(lines[1], "c    dddd");
}

// Widths count code points: a cell holding "µs" (3 bytes, 2 code points) keeps the next column where
// an ASCII cell of 2 characters puts it.
TEST(TextColumns, WidthsCountCodePointsAndIndentStartsEveryLine) {
    TextColumns t("  ");
    t.addRow({"µs", "x"});
    t.addRow({"ms", "y"});
    const std::vector<std::string> lines = splitLines(t.toString());
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "  µs  x");
    EXPECT_EQ(lines[1], "  ms  y");
    EXPECT_EQ(TextColumns::displayWidth("µs"), 2u);
}

} // namespace
