#pragma once
// String helpers shared by error messages and reports ("known: a, b, c").
#include <cstdint>
#include <cstdio>
#include <string>

namespace sb {

/// Joins the strings of any range with `separator`: join(names, ", ") -> "a, b, c".
template <typename Range, typename Project>
std::string join(const Range& items, const std::string& separator, Project project) {
    std::string out;
    for (const auto& item : items) {
        if (!out.empty()) out += separator;
        out += project(item);
    }
    return out;
}

template <typename Range>
std::string join(const Range& items, const std::string& separator) {
    return join(
        items, separator, [](const auto& s) -> const auto& { return s; });
}

/// A memory size for messages, in the largest unit that keeps it readable: "8.0 GiB", "128.0 MiB",
/// "4096 bytes". Every estimate and limit of --max-memory-gib is written with it, so the numbers of one
/// refusal compare at a glance.
inline std::string byteSize(uint64_t bytes) {
    char text[40];
    if (bytes >= (1ull << 30))
        std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    else if (bytes >= (1ull << 20))
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1ull << 20));
    else
        std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
}

} // namespace sb
