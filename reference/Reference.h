#pragma once
// `reference`: exact visibility ray-traced with Intel Embree, drawn as a technique; the ground truth.
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include <vector>

#include "reference/ReferenceTracer.h"
#include "techniques/Submission.h"
#include "techniques/Technique.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Reference {
    static constexpr const char* kHard = "hard";
    static constexpr const char* kSamples = "samples";
    static constexpr const char* kThreads = "threads";

    static TechniqueInfo declaration();
    /// The tracer's options from the technique's properties (fixed seed: a frame traces to the same
    /// image frame after frame).
    static ReferenceTracer::Options tracerOptions(const PropertySet& properties);
    /// Channel i = light i of `visibility` into `rgba` (width * height * 4 floats; channels without a
    /// light stay 1, as the cleared target would be), rows bottom-up as traced or, with `topDown`, in
    /// Vulkan's order.
    static void packVisibility(const std::vector<VisibilityImage>& visibility, int width, int height,
                               bool topDown, float* rgba);
    /// The counters of both forms: draw_calls and triangles of the G-buffer and shade passes, rays,
    /// rays_per_second_per_thread, noise_bound and samples_per_pixel (largest over lights).
    static Counters counters(const SubmitStats& draws, const std::vector<TraceStats>& traces);
};

} // namespace sb
