#include "bench/golden/MatrixProgress.h"

#include <iostream>

namespace sb {

MatrixProgress::MatrixProgress(size_t total, Judge judge)
    : mBar(stderr, total, 0), mJudge(std::move(judge)) {}

MatrixObserver MatrixProgress::observer() {
    return {[this](const std::string& cell) { mBar.setCurrent(cell); },
            [this](const std::vector<MatrixCell>& cells) {
                mBar.finished(cells.back().name(), mJudge(cells));
                mWarnings.add(cells.back().name(), cells.back().warnings);
            }};
}

void MatrixProgress::pause() {
    mBar.close();
}

void MatrixProgress::finish() {
    mBar.close();
    for (const std::string& line : mWarnings.summary()) std::cerr << line << "\n";
}

} // namespace sb
