#include "techniques/gl/PassTimer.h"

#include "gl/DebugOutput.h"

namespace sb {

void PassTimer::begin(const char* pass) {
    if (mRouter) pass = mRouter->enter(pass);
    if (mClock) mClock->passBegins(pass); // first: the pass's CPU span includes the bookkeeping below
    if (mOpen) DebugOutput::check();      // errors of the pass that just ended are reported with its name
    DebugOutput::setCurrentPass(mTechnique.empty() ? std::string(pass) : mTechnique + "/" + pass);
    if (mRing) mRing->beginPass(pass);
    if (mObserver) mObserver->passBegins(pass);
    mOpen = true;
}

void PassTimer::end() {
    if (mOpen) DebugOutput::check();
    if (mObserver && mOpen) mObserver->framePassesEnd();
    DebugOutput::setCurrentPass("");
    mOpen = false;
}

} // namespace sb
