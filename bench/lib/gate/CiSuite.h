#pragma once
// The perf gate's suite (results/ci/suite.json; README "Gate a change"): named configurations, each one
// technique with its run options, and which of them each layer runs. A configuration's name is its
// identity in the baseline, so renaming one is a baseline change.
//
//   {"name": "shadowbench-ci",
//    "args": ["--size", "160x160", "--seed", "7"],          given to every run; a config's own option
//                                                           of the same name replaces the suite's
//    "work": {"frames": 1, "warmup": 0},                    layer A: the census frame after these
//    "instructions": {"frames": 3, "warmup": 1, "configs": ["none_aircraft"]},   layer B (valgrind)
//    "wall": {"frames": 10, "warmup": 3, "rounds": 9, "control": "none_aircraft",
//             "configs": ["none_aircraft"]},                                      layer C
//    "configs": [{"name": "none_aircraft", "bound": "balanced",
//                 "args": ["-t", "none", "--instances", "50"]},
//                {"name": "raytraced_vulkan", "args": ["--api", "vulkan", "-t", "raytraced"],
//                 "drivers": ["mesa-25.0.7"],
//                 "why": "VK_KHR_ray_query: the system's lavapipe (Mesa 22.3.6) lacks it"}]}
//
// "bound" says which stage the configuration is meant to load (cpu, vertex, fill, balanced); it is
// reported, not measured here (bench bottleneck measures it). "drivers" (names of core/DriverTable.h)
// binds a configuration to the drivers that can run it, for a technique whose form needs a capability
// only they offer, and "why" says what the others lack: on another driver every layer leaves it out and
// the report says so and why, and its baseline rows live in those drivers' baselines only
// (results/ci/baseline/<driver>/).
#include <string>
#include <vector>

namespace sb {

struct CiConfig {
    std::string name;  ///< [a-z0-9_]+, unique
    std::string bound; ///< cpu | vertex | fill | balanced
    std::vector<std::string> args;
    std::vector<std::string> drivers; ///< the drivers it runs on; empty: every driver
    std::string why;                  ///< with `drivers`: what the other drivers lack
    /// Whether the configuration runs on `driver` (a driver table name, as DriverTable::current()).
    bool runsOn(const std::string& driver) const;
    /// Why it does not run on `driver`: "runs on mesa-25.0.7 only: <why>".
    std::string notRunReason() const;
};

struct CiLayerRuns {
    int frames = 1;
    int warmup = 0;
    int rounds = 1;                   ///< layer C only
    std::vector<std::string> configs; ///< names; all configurations when the file gives none (layer A)
    std::string control;              ///< layer C: the configuration of the A/A control
};

struct CiSuite {
    std::string name;
    std::string path;              ///< where it was read from
    std::vector<std::string> args; ///< common to every run
    std::vector<CiConfig> configs;
    CiLayerRuns work, instructions, wall;

    /// Reads and checks a suite file; every error is sb::Error(BadInput) naming the file and the JSON
    /// path (unknown keys, a name given twice, a layer naming an unknown configuration, a
    /// configuration without exactly one -t/--technique).
    static CiSuite load(const std::string& path);
    const CiConfig& config(const std::string& wanted) const;
    /// The configurations a layer runs, in the suite's order, restricted to `only` when non-empty
    /// (an unknown name in `only` is bad input).
    std::vector<const CiConfig*> select(const CiLayerRuns& layer, const std::vector<std::string>& only) const;
    /// select() restricted to the configurations that run on every one of `drivers` (the head's, and the
    /// base's in an A/B); with `boundOnly`, to those whose `drivers` name them (what only they can run).
    std::vector<const CiConfig*> selectOn(const CiLayerRuns& layer, const std::vector<std::string>& only,
                                          const std::vector<std::string>& drivers, bool boundOnly) const;
};

} // namespace sb
