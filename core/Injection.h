#pragma once
// Deliberate regressions for the perf gate's proof (README "Gate a change", results/ci/README.md): the
// environment variable SHADOWBENCH_INJECT names the ones to switch on, comma-separated. Each one is a
// mistake an engine change could make, so the proof can show which layer of the gate catches it:
//   extra_fullscreen_pass     the harness adds a full-screen pass after the technique's (fragments up)
//   no_caster_culling         shadow maps draw every object into the map, receivers included
//   double_shadow_resolution  shadow maps allocate and render twice the configured resolution per side
// A driver-side slowdown needs no switch: it is an environment of the driver (LP_NUM_THREADS=1).
// Nothing is injected when the variable is unset; an unknown name is bad input (exit 2) at start-up,
// so a typo in a proof cannot silently measure the unmodified code.
#include <string>

namespace sb {

enum class Injection { ExtraFullscreenPass, NoCasterCulling, DoubleShadowResolution };

/// True when SHADOWBENCH_INJECT names `which` (read once per process).
bool injected(Injection which);
/// Checks SHADOWBENCH_INJECT; throws sb::Error(BadInput) naming an unknown entry and the known ones.
void checkInjections();
/// The switched-on names, comma-separated ("" when none): recorded in every row.
std::string injectionsText();

} // namespace sb
