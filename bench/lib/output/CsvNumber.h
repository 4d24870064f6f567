#pragma once
// How numbers are written into result CSVs: fixed 4 decimals (0.1 us resolution for milliseconds;
// enough for every timing and counter, and stable to diff between runs).
#include <cstdio>
#include <string>

namespace sb {

inline std::string csvNumber(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

} // namespace sb
