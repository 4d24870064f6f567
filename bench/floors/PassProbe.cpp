#include "bench/floors/PassProbe.h"

// Callgrind client requests (bench/lib/callgrind/): compiled in where valgrind's header exists
// (SB_HAVE_VALGRIND, set for this file in CMakeLists.txt); natively a request is a few no-op instructions.
#ifdef SB_HAVE_VALGRIND
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define RUNNING_ON_VALGRIND 0
#endif

namespace sb {

bool callgrindRunning() {
    return RUNNING_ON_VALGRIND != 0;
}

void callgrindInstrumentation(bool on) {
    if (on) {
        CALLGRIND_START_INSTRUMENTATION;
    } else {
        CALLGRIND_STOP_INSTRUMENTATION;
    }
}

void finishAndDump(const std::string& name) {
    glFinish();
    if (!name.empty()) CALLGRIND_DUMP_STATS_AT(name.c_str());
}

PassProbe::PassProbe(bool inspect) : mInspect(inspect) {}

void PassProbe::frameBegins() {
    mPasses.clear();
    mOpen = false;
    finishAndDump(mDumpPrefix.empty() ? "" : mDumpPrefix + "skip");
    open("frame");
}

void PassProbe::passBegins(const char* pass) {
    close();
    open(pass);
}

void PassProbe::framePassesEnd() {
    close();
}

void PassProbe::open(const char* pass) {
    ProbedPass p;
    p.name = pass;
    mPasses.push_back(std::move(p));
    mStart = std::chrono::steady_clock::now();
    mOpen = true;
}

void PassProbe::close() {
    if (!mOpen) return;
    mOpen = false;
    ProbedPass& p = mPasses.back();
    finishAndDump(mDumpPrefix.empty() ? "" : mDumpPrefix + p.name);
    p.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart).count();
    if (mInspect) p.target = PassTarget::current();
}

} // namespace sb
