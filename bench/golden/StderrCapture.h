#pragma once
// What the process writes to stderr (file descriptor 2) while one object lives: the techniques say what
// they cannot do on stderr as they prepare (a scene without a receiver plane, a mesh without a useful
// shadow plane), once per cell of the matrix. `bench golden` takes those lines per cell and prints each
// cause once with its count (bench/golden/WarningTally.h) instead of hundreds of repeated lines.
#include <cstdio>
#include <string>
#include <vector>

namespace sb {

class StderrCapture {
public:
    /// Redirects file descriptor 2 into a temporary file. A capture that cannot start (no temporary
    /// file) leaves stderr as it is and takes nothing.
    StderrCapture();
    /// Puts stderr back if take() was not called.
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// Puts stderr back and returns the non-empty lines written since the constructor, in order.
    std::vector<std::string> take();

private:
    void restore();
    std::FILE* mFile = nullptr;
    int mSaved = -1;
};

} // namespace sb
