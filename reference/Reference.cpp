#include "reference/Reference.h"

#include <algorithm>
#include <cstring>

#include "shading/ShaderLimits.h"
#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Reference::kSamples, "64", 1, 4096, "area-light samples per pixel (stratified)"),
        integer(Reference::kThreads, "0", 0, 256, "tracing threads, 0 = the CPUs the process was given"),
        flag(Reference::kHard, "false", "treat area lights as points"),
    };
}

} // namespace

TechniqueInfo Reference::declaration() {
    return {.name = "reference",
            .description = "exact visibility by ray tracing (Intel Embree): the ground truth",
            .effects = Effect::HardShadows | Effect::SoftShadows | Effect::SelfShadowing |
                       Effect::NonPlanarReceivers | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"gbuffer", "trace", "shade"},
            .properties = declareProperties()};
}

ReferenceTracer::Options Reference::tracerOptions(const PropertySet& p) {
    ReferenceTracer::Options o;
    o.softSamples = int(p.getInt(kSamples));
    o.threads = int(p.getInt(kThreads));
    o.seed = 1;
    o.forceHard = p.getBool(kHard);
    return o;
}

void Reference::packVisibility(const std::vector<VisibilityImage>& visibility, int width, int height,
                               bool topDown, float* rgba) {
    const size_t pixels = size_t(width) * size_t(height);
    std::fill(rgba, rgba + pixels * 4, 1.0f);
    for (size_t light = 0; light < visibility.size() && light < size_t(kMaxLights); ++light) {
        const std::vector<float>& v = visibility[light].value;
        for (size_t p = 0; p < v.size() && p < pixels; ++p) {
            const size_t x = p % size_t(width), y = p / size_t(width);
            const size_t row = topDown ? size_t(height) - 1 - y : y;
            rgba[(row * size_t(width) + x) * 4 + light] = v[p];
        }
    }
}

Counters Reference::counters(const SubmitStats& s, const std::vector<TraceStats>& traces) {
    double rays = 0.0, threadSeconds = 0.0, noise = 0.0;
    int spp = 0;
    for (const TraceStats& t : traces) {
        rays += double(t.rays);
        threadSeconds += t.seconds * t.threads;
        noise = std::max(noise, t.noiseBound);
        spp = std::max(spp, t.samplesPerPixel);
    }
    return {{"draw_calls", double(s.drawCalls)},
            {"triangles", double(s.triangles)},
            {"rays", rays},
            {"rays_per_second_per_thread", threadSeconds > 0.0 ? rays / threadSeconds : 0.0},
            {"noise_bound", noise},
            {"samples_per_pixel", double(spp)}};
}

} // namespace sb
