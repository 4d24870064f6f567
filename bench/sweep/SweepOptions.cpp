#include "bench/sweep/SweepOptions.h"

#include <algorithm>

#include "gl/backends/BackendRegistry.h"

namespace sb {

void SweepOptions::add(CLI::App& app) {
    app.add_option("-t,--technique", techniques,
                   "technique[:prop=v1,v2...], repeatable; comma lists of property values are axes too");
    app.add_option("--scene", scenes, "scenes, comma-separated");
    app.add_option("-n,--instances", instances, "instance counts, comma-separated ('default' = the scene's)");
    app.add_option("--scale", scale, "instance scales, comma-separated");
    app.add_option("--tess", tess, "tessellations, comma-separated");
    app.add_option("--tess-factor", tessFactor, "tessellation factors, comma-separated");
    app.add_option("--submit", submit, "submission modes, comma-separated");
    app.add_option("--camera", camera, "camera presets, comma-separated");
    app.add_option("--size", size, "resolutions WxH, comma-separated");
    app.add_option("--light", light, "light types, comma-separated ('scene' = as the scene says)");
    app.add_option("--repeat", repeat, "rounds of interleaved measurement per combination");
    // Options of a single run that stay the same across the sweep; forwarded verbatim.
    auto forward = [&](const char* name, const std::string& help) {
        app.add_option_function<std::string>(
            name,
            [this, name](const std::string& v) {
                passThrough.insert(passThrough.end(), {name, v});
            },
            help);
    };
    auto flag = [&](const char* name, const char* help) {
        app.add_flag_function(
            name, [this, name](int64_t) { passThrough.push_back(name); }, help);
    };
    forward("--frames", "measured frames per configuration");
    forward("--seconds", "measure each configuration for this long instead");
    forward("--warmup", "discarded warm-up frames");
    forward("--seed", "layout seed");
    forward("--model", "model file replacing the layout mesh");
    forward("--backend", backendNames(true)); // headless: every combination runs in a worker process
    forward("--gpu", "EGL device index");
    forward("--ref-samples", "accuracy: reference samples per pixel");
    forward("--light-index", "accuracy: which light to judge");
    forward("--max-memory-gib", "refuse scenes estimated above this memory");
    flag("--no-timer-check", "skip the GPU-timer calibration (rows say unchecked)");
    flag("--no-stability", "accuracy: skip perturbation gain and flicker");
}

void SweepOptions::applyTo(SweepDefinition& d) const {
    auto axis = [](const std::string& text, const char* option, std::vector<std::string>& out) {
        if (!text.empty()) out = SweepDefinition::splitList(text, option);
    };
    if (!techniques.empty()) d.axes.techniques = techniques;
    axis(scenes, "--scene", d.axes.scenes);
    axis(instances, "--instances", d.axes.instances);
    axis(scale, "--scale", d.axes.scale);
    axis(tess, "--tess", d.axes.tess);
    axis(tessFactor, "--tess-factor", d.axes.tessFactor);
    axis(submit, "--submit", d.axes.submit);
    axis(camera, "--camera", d.axes.camera);
    axis(size, "--size", d.axes.size);
    axis(light, "--light", d.axes.light);
    if (repeat > 0) d.repeat = repeat;
    d.commonArgs.insert(d.commonArgs.end(), passThrough.begin(), passThrough.end());
}

bool SweepOptions::passes(const std::string& option) const {
    return std::find(passThrough.begin(), passThrough.end(), option) != passThrough.end();
}

} // namespace sb
