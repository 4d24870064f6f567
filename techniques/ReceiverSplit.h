#pragma once
// The lit pass of a technique that looks a shadow up per fragment, drawn as two programs where the scene
// allows it: the receivers with the lookup, then the instances that receive no shadow with a program
// compiled without it (SB_NON_RECEIVER_DRAWS, shaders/common/lighting.glsl). llvmpipe (Mesa 22.3.6)
// runs a lookup under the mask of the branch on the receiver flag, so a non-receiver's fragments would
// otherwise pay for the lookup whose result they drop (results/perf/README.md, "The lit shader").
// The API-neutral half; techniques/gl/LitPrograms.h and techniques/vulkan/LitPipelines.h draw with it.
#include "scenes/Scene.h"
#include "shading/Defines.h"
#include "techniques/Submission.h"

namespace sb::ReceiverSplit {

/// Whether the lit pass draws the scene's receivers and its non-receivers with two programs: when the
/// scene has both, and drawing every receiver before every non-receiver keeps the order of
/// DrawSet::All's draws in submission mode `mode` (scene order; for instanced draws mesh by mesh, scene
/// order within a mesh), so that a depth tie between the two resolves as with one program and the image
/// is the same.
bool drawsApart(const Scene& scene, SubmitMode mode);

/// The defines of one of those two programs: `lit` (a lit pass's defines for a scene with
/// non-receivers) for the receivers alone (no per-fragment receiver test) or for the non-receivers
/// alone (no lookup).
Defines defines(Defines lit, bool receivers);

} // namespace sb::ReceiverSplit
