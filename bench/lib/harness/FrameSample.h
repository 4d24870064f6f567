#pragma once
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/harness/CpuPassSpan.h"

namespace sb {

/// One measured frame (docs/ARCHITECTURE.md, "The timing contract"). CPU submit: first to last GL call of the
/// frame (on llvmpipe this includes vertex shading and binning, which run inside the draw calls). Wall:
/// submit plus the glFinish wait (rasterisation and fragment shading on llvmpipe's threads).
struct FrameSample {
    double cpuSubmitMs = 0.0;
    double wallMs = 0.0;
    /// A scene in motion: the part of the CPU submit time spent moving the scene and updating the
    /// technique for it (Technique::sceneChanged); 0 for a static scene.
    double motionMs = 0.0;
    std::vector<std::pair<std::string, double>> gpuPassMs; ///< raw timer-query values, pass order
    double gpuTotalMs = -1.0;                              ///< -1: not (yet) available
    /// When the frame started: the steady clock in ms since its epoch (places frames on a timeline:
    /// bench/lib/rows/TraceWriter.h).
    double startMs = 0.0;
    /// CPU submit per pass, in pass order (a pass entered twice, twice).
    std::vector<CpuPassSpan> cpuPasses;
};

} // namespace sb
