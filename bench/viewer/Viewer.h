#pragma once
// `bench --window`: an on-screen viewer on the GLFW backend. Renders the chosen techniques with the
// same Harness frame path as a measurement and blits the colour (or visibility) target to the window.
// Mouse drag orbits, wheel or +/- zooms, Tab / 1-9 switch technique, V toggles the visibility view,
// R resets the camera, Esc quits. The title shows the technique and smoothed wall / CPU-submit times.
#include <memory>
#include <vector>

#include "bench/run/Harness.h"

namespace sb {

class Viewer {
public:
    /// Runs until the window closes or Esc, or after `maxFrames` frames when it is positive.
    static int run(Harness& harness, std::vector<std::unique_ptr<Technique>>& techniques, int maxFrames = 0);
};

} // namespace sb
