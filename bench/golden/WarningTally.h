#pragma once
// The warnings of the matrix's cells, one line per cause: a technique that cannot shadow a scene says so
// in every submission mode, on both APIs, and `bench golden` used to repeat the line for every cell.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sb {

class WarningTally {
public:
    /// The lines `cell` wrote (StderrCapture::take); a line written twice by one cell counts once.
    void add(const std::string& cell, const std::vector<std::string>& lines);
    /// One line per distinct warning, in the order first seen:
    /// "warning: 4 cells: <the line> (first: technique/scene/mode)"; "1 cell" for one.
    std::vector<std::string> summary() const;
    bool empty() const { return mOrder.empty(); }

private:
    struct Cause {
        std::string firstCell;
        std::set<std::string> cells;
    };
    std::vector<std::string> mOrder; ///< the causes, first seen first
    std::map<std::string, Cause> mCauses;
};

} // namespace sb
