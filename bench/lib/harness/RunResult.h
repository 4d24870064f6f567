#pragma once
// What one measured run of one technique gave, on either API: the statistics of its frames, its exact
// work in the census frame, its counters and what it is (the row's identity columns).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/harness/FrameSample.h"
#include "bench/lib/statistics/Statistics.h"
#include "scenes/Scene.h"
#include "techniques/FrameWork.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct RunResult {
    std::string technique;
    std::string properties;         ///< canonical PropertySet::toString()
    std::string permutation;        ///< program keys
    EffectMask effectsProduced = 0; ///< TechniqueInfo::effects (the row's effects_* columns)
    Counters counters;              ///< of the last measured frame
    std::vector<FrameSample> samples;
    Statistics cpuSubmit, wall;
    Statistics motion; ///< a scene in motion: FrameSample::motionMs (inside cpuSubmit)
    std::vector<std::pair<std::string, Statistics>> gpuPass; ///< per declared pass (raw timer values)
    Statistics gpuTotal;
    /// CPU submit per declared pass (FrameSample::cpuPasses, a pass entered several times summed per frame).
    std::vector<std::pair<std::string, Statistics>> cpuPass;
    uint64_t gpuFramesMissing = 0; ///< measured frames whose queries never came back
    double setupMs = 0.0;          ///< setScene + compile (untimed for the frames)
    FrameLoads loads;              ///< census frame after the measured ones
};

} // namespace sb
