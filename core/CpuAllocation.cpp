#include "core/CpuAllocation.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <string>
#include <thread>

namespace sb {

namespace {

constexpr const char* kStatusFile = "/proc/self/status";
constexpr std::string_view kAllowedKey = "Cpus_allowed_list:";

/// A CPU number of a list: digits only (from_chars alone would accept a sign).
std::optional<long> cpuNumber(std::string_view text) {
    long value = 0;
    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::string_view trimmed(std::string_view s) {
    const size_t first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

} // namespace

std::optional<int> countCpuList(std::string_view list) {
    list = trimmed(list);
    if (list.empty()) return std::nullopt;
    long count = 0;
    while (!list.empty()) {
        const size_t comma = list.find(',');
        const std::string_view item = list.substr(0, comma);
        list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 1);
        const size_t dash = item.find('-');
        const std::optional<long> first = cpuNumber(item.substr(0, dash));
        const std::optional<long> last =
            dash == std::string_view::npos ? first : cpuNumber(item.substr(dash + 1));
        if (!first || !last || *last < *first) return std::nullopt;
        count += *last - *first + 1;
        if (count > 1 << 20) return std::nullopt; // more CPUs than any kernel supports: not a CPU list
    }
    return int(count);
}

// The kernel writes the same mask sched_getaffinity() returns (the thread group leader's) as a list;
// tests/CpuAllocationTest.cpp holds the two equal under a narrowed mask.
int allocatedCpuCount() {
    std::ifstream in(kStatusFile);
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, kAllowedKey.size(), kAllowedKey) == 0) {
            if (const std::optional<int> n = countCpuList(std::string_view(line).substr(kAllowedKey.size())))
                return std::max(1, *n);
            break;
        }
    return std::max(1, int(std::thread::hardware_concurrency()));
}

} // namespace sb
