#pragma once
// `bench --window`: an on-screen viewer on the GLFW backend. Renders the chosen techniques with the
// same Harness frame path as a measurement and blits the colour target to the window, or draws one
// light's visibility through a false-colour ramp (bench/lib/viewer/VisibilityView.h). An overlay in the
// top-left corner (bench/lib/viewer/Overlay.h) shows the technique, its properties, the median wall and
// CPU-submit times of the last kMedianFrames frames, the GPU-timer trust verdict (calibrated at the
// start as a measurement does, unless --no-timer-check) and the scene's light count; the title repeats
// the technique and times.
//
// Keys arrive as events (bench/lib/viewer/InputQueue.h), so a tap between two slow frames is never lost:
// Tab next technique (Shift+Tab previous), 1-9 technique by number, V colour / visibility view, L next
// light in the visibility view, R reset the camera, + / - (or keypad, or wheel) zoom, Esc quit; mouse
// drag orbits.
//
// The viewer's own drawing (visibility view, overlay) goes only into the window's default framebuffer
// after the frame was timed, and restores the GL state it changes: the frames it times are the frames
// a measurement times.
//
// Unless -q, one line goes to the log stream (stdout, or stderr with --format other than console, as
// a run's progress) each time the window shows another entry of the technique list (a second
// configuration of the same technique gets its own line) or another view:
//   viewer: technique <name>
//   viewer: view colour | viewer: view visibility of light <n>   (n from 1)
// Each is printed after the frame that shows it has been presented (scripts and tests wait for it).
#include <memory>
#include <vector>

#include "bench/lib/harness/Harness.h"

namespace sb {

class Viewer {
public:
    static constexpr size_t kMedianFrames = 30; ///< frames the overlay's median times are taken over

    /// Runs until the window closes or Esc, or after `maxFrames` frames when it is positive.
    static int run(Harness& harness, std::vector<std::unique_ptr<GlTechnique>>& techniques,
                   int maxFrames = 0);
};

} // namespace sb
