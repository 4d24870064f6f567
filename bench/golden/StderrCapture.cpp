#include "bench/golden/StderrCapture.h"

#include <iostream>
#include <unistd.h>

namespace sb {

StderrCapture::StderrCapture() {
    // Both C and C++ streams write to descriptor 2 unbuffered, but a caller may have buffered text:
    // it belongs before the capture, on the real stderr.
    std::cerr.flush();
    std::fflush(stderr);
    mFile = std::tmpfile();
    if (!mFile) return;
    mSaved = ::dup(2);
    if (mSaved < 0 || ::dup2(::fileno(mFile), 2) < 0) {
        if (mSaved >= 0) ::close(mSaved);
        mSaved = -1;
        std::fclose(mFile);
        mFile = nullptr;
    }
}

StderrCapture::~StderrCapture() {
    restore();
    if (mFile) std::fclose(mFile);
}

void StderrCapture::restore() {
    if (mSaved < 0) return;
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(mSaved, 2);
    ::close(mSaved);
    mSaved = -1;
}

std::vector<std::string> StderrCapture::take() {
    restore();
    std::vector<std::string> lines;
    if (!mFile) return lines;
    std::rewind(mFile);
    std::string line;
    for (int c = std::fgetc(mFile);; c = std::fgetc(mFile)) {
        if (c == EOF || c == '\n') {
            if (!line.empty()) lines.push_back(line);
            line.clear();
            if (c == EOF) break;
        } else {
            line += char(c);
        }
    }
    std::fclose(mFile);
    mFile = nullptr;
    return lines;
}

} // namespace sb
