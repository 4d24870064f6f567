#pragma once
// The axes of `bench sweep`, from a JSON file, the command line, or both (the command line
// replaces what the file says: an axis it names, "repeat", and every run option it gives, such as
// --frames for "frames"; SweepOptions::applyTo). Every axis is a list; the sweep is their cartesian
// product, with the techniques (and their property lists) measured inside each combination:
//
//   {
//     "name": "instances",                              (optional; default: the file's stem)
//     "mode": "measure",                                ("accuracy": judge against the reference too)
//     "quality_sweep": false,                           (accuracy: walk each technique's quality knobs)
//     "techniques": ["none", "shadowmap:pcf=1,3",       (a comma list of values is an axis of its own)
//                    {"name": "shadowmap", "properties": {"resolution": [512, 1024, 2048]}}],
//     "scenes": ["aircraft", "teapot"],    "instances": [1, 50, 100, 200],   "scale": [1, 10],
//     "tess": [8, 16],   "tess_factor": [0.5, 1, 2],   "submit": ["retained", "immediate"],
//     "camera": ["far", "near"],   "size": ["512x512", "1024x1024"],   "light": ["directional", "spot"],
//     "api": ["gl", "vulkan"],                          (bench's --api: the rows' `api` column says which)
//     "repeat": 3,                                      (rounds of A/B interleaving per combination)
//     "frames": 30, "warmup": 5, "seconds": 0, "seed": 1, "backend": "egl-surfaceless",
//     "ref_samples": 64, "stability": true, "args": ["--max-memory-gib", "4"]   (passed to every run)
//   }
// Axes left out take bench's defaults (a single value). "instances": "default" keeps the scene's count.
// Order of the product, outer to inner: scene, light, camera, size, submit, scale, tess, tess_factor,
// instances, api (so the points of an instance curve run next to each other, and each point's APIs).
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/sweep/SweepPlan.h"

namespace sb {

struct SweepAxes {
    std::vector<std::string> techniques, scenes, instances, scale, tess, tessFactor, submit, camera, size,
        light, api;
};

class SweepDefinition {
public:
    std::string name = "sweep";
    SweepPlan::Mode mode = SweepPlan::Mode::Measure;
    bool qualitySweep = false;
    SweepAxes axes;
    int repeat = 1;
    std::vector<std::string> commonArgs; ///< fixed options for every run (--frames 30 ...)
    /// The most configurations (rows) expand() accepts: 10000 rows take hours even at a second each,
    /// so more is almost always a typo in an axis (--max-configs raises it).
    uint64_t maxConfigs = 10000;

    /// Reads a definition file; errors name the file and the JSON path.
    static SweepDefinition fromJsonFile(const std::string& path);
    /// The same from a parsed value (a figure declaration's "sweep"); `source` and `path` name it in
    /// errors, `defaultName` is used when it has no "name".
    static SweepDefinition fromJson(const nlohmann::json& value, const std::string& source,
                                    const std::string& path, const std::string& defaultName);
    /// Splits "a,b,c" into an axis (empty items are an error naming `option`).
    static std::vector<std::string> splitList(const std::string& text, const std::string& option);
    /// Expands property value lists of one spec: "shadowmap:resolution=512,1024:pcf=1,3" -> 4 specs.
    static std::vector<std::string> expandTechnique(const std::string& spec);

    /// The plan: refuses more than maxConfigs rows before expanding anything, then validates every
    /// technique spec, every combination's options and its scene as the worker will load it (no GL
    /// needed), so a typo fails before the first measurement. Throws sb::Error naming the axis value.
    SweepPlan expand() const;

private:
    /// Throws when `configurations` exceeds maxConfigs; `how` is the product that gave it.
    void checkSize(uint64_t configurations, const std::string& how) const;
};

} // namespace sb
