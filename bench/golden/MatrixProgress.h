#pragma once
// The progress of `bench golden` on stderr: a line per finished cell off a terminal (done/total,
// failed, elapsed, time left; bench/lib/output/ProgressBar.h), one line redrawn in place with the cell
// that renders now on a terminal. The cells' warnings (MatrixCell::warnings) are gathered and printed
// at the end, one line per cause with its count of cells (WarningTally), instead of once per cell.
#include <cstddef>
#include <functional>
#include <vector>

#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/WarningTally.h"
#include "bench/lib/output/ProgressBar.h"

namespace sb {

class MatrixProgress {
public:
    /// Whether the newest cell passed, given the scene's cells so far (the new one last).
    using Judge = std::function<bool(const std::vector<MatrixCell>&)>;
    /// `total` cells over every scene (GoldenMatrix::cellsPerScene times the scenes).
    MatrixProgress(size_t total, Judge judge);
    /// What to hand GoldenMatrix::renderScene; valid while this object lives.
    MatrixObserver observer();
    /// Ends the in-place line before other output (on a terminal).
    void pause();
    /// Ends the progress and prints the warnings, each cause once with its count of cells.
    void finish();

private:
    ProgressBar mBar;
    Judge mJudge;
    WarningTally mWarnings;
};

} // namespace sb
