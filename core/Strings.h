#pragma once
// String helpers shared by error messages and reports ("known: a, b, c").
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

} // namespace sb
