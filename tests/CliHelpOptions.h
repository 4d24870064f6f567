#pragma once
// The option names a `bench ... --help` text lists: CLI11 prints each option on a line of its own,
// indented by two spaces, its names first ("  -t,--technique TEXT ..."). Read from the help text as a
// user sees it, so a test can hold the man page and the completion against it.
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace sb::test {

inline std::set<std::string> helpOptionNames(const std::string& help) {
    static const std::regex line(R"(^  (--?[A-Za-z][\w-]*(?:,--?[A-Za-z][\w-]*)*)(?: |$))");
    std::set<std::string> names;
    std::istringstream lines(help);
    for (std::string l; std::getline(lines, l);) {
        std::smatch m;
        if (!std::regex_search(l, m, line)) continue;
        std::istringstream flags(m[1].str());
        for (std::string f; std::getline(flags, f, ',');) names.insert(f);
    }
    return names;
}

} // namespace sb::test
