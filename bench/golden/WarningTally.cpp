#include "bench/golden/WarningTally.h"

namespace sb {

void WarningTally::add(const std::string& cell, const std::vector<std::string>& lines) {
    for (const std::string& line : lines) {
        auto [it, fresh] = mCauses.try_emplace(line);
        if (fresh) {
            mOrder.push_back(line);
            it->second.firstCell = cell;
        }
        it->second.cells.insert(cell);
    }
}

std::vector<std::string> WarningTally::summary() const {
    std::vector<std::string> out;
    for (const std::string& line : mOrder) {
        const Cause& c = mCauses.at(line);
        const size_t n = c.cells.size();
        out.push_back("warning: " + std::to_string(n) + (n == 1 ? " cell: " : " cells: ") + line +
                      " (first: " + c.firstCell + ")");
    }
    return out;
}

} // namespace sb
