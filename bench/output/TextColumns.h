#pragma once
// The two helpers of the console tables (ConsoleReport, BottleneckStudy): a number through a printf
// format, and a cell padded to a column width.
#include <cstdio>
#include <string>

namespace sb {

/// `v` formatted with the printf format `f` ("%.2f ms").
inline std::string formatNumber(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

/// `s` padded with spaces to at least `width` characters (left-aligned cell).
inline std::string padRight(std::string s, size_t width) {
    if (s.size() < width) s.append(width - s.size(), ' ');
    return s;
}

} // namespace sb
