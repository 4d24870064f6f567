#pragma once
// The GL state every technique may assume at the start of execute() (the harness sets it before each
// frame) and restores when it is done with a pass that changed it: depth test LESS with writes, no
// blending (equation ADD, ONE/ZERO), no culling, no stencil test, no polygon offset, clip distances
// 0 and 1 off, every colour channel written.
namespace sb {

void resetFrameState();

} // namespace sb
