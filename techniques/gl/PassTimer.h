#pragma once
// What a technique calls at each of its passes: `ctx.passes.begin("depth")`. It names the pass for
// GL error reports (DebugOutput), places a GPU timestamp (TimerQueryRing) and checks for GL errors of
// the pass that just ended, so a failure says which pass caused it.
#include <string>

#include "gl/TimerQueryRing.h"
#include "techniques/PassClock.h"
#include "techniques/PassObserver.h"
#include "techniques/PassRouter.h"

namespace sb {

class PassTimer {
public:
    explicit PassTimer(TimerQueryRing* ring) : mRing(ring) {}
    /// nullptr: no GPU timestamps (the harness switches them off where the timer is untrusted).
    void setRing(TimerQueryRing* ring) { mRing = ring; }
    /// `technique` prefixes pass names in error messages ("shadowmap/depth").
    void setTechnique(const std::string& technique) { mTechnique = technique; }
    /// nullptr: none (the timed frames). The census frame sets one to count each pass's work.
    void setObserver(PassObserver* observer) { mObserver = observer; }
    /// nullptr: passes keep the names their technique gives them. A hybrid technique sets one while a
    /// part runs (techniques/PassRouter.h).
    void setRouter(PassRouter* router) { mRouter = router; }
    PassRouter* router() const { return mRouter; }
    /// nullptr: none. The harness sets one to take each pass's CPU begin (techniques/PassClock.h).
    void setClock(PassClock* clock) { mClock = clock; }
    /// Ends the previous pass (error check) and starts `pass`. `pass` must be a string literal or
    /// otherwise live for the process: the query ring keeps it by pointer and reads it back frames
    /// later, possibly after the technique that named it is gone.
    void begin(const char* pass);
    /// Ends the last pass of the frame (error check).
    void end();
    /// Records that the technique leaves out declared pass `pass` this frame because of `reason`
    /// ("no light casts shadows"): the census frame reports it (bench explain, CSV `passes_skipped`);
    /// a timed frame pays one null-pointer test. Both strings must be literals or outlive the frame.
    void skip(const char* pass, const char* reason) {
        if (mObserver) mObserver->passSkipped(mRouter ? mRouter->nameOf(pass) : pass, reason);
    }

private:
    TimerQueryRing* mRing;
    PassObserver* mObserver = nullptr;
    PassRouter* mRouter = nullptr;
    PassClock* mClock = nullptr;
    std::string mTechnique;
    bool mOpen = false;
};

} // namespace sb
