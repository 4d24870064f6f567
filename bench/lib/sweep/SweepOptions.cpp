#include "bench/lib/sweep/SweepOptions.h"

#include <algorithm>

#include "core/Error.h"
#include "gl/backends/BackendRegistry.h"

namespace sb {

namespace {

/// An option of a single run that a sweep passes to every run. `help` null: the backend list.
struct PassThroughOption {
    const char* name;
    bool takesValue;
    const char* help;
    const char* alternative; ///< the option that sets the same thing another way, or null
};

// The one table of pass-through options: registration, replacement and the scan below read it.
const PassThroughOption kPassThrough[] = {
    {"--frames", true, "measured frames per configuration (replaces the file's frames or seconds)",
     "--seconds"},
    {"--seconds", true, "measure each configuration for this long instead", "--frames"},
    {"--warmup", true, "discarded warm-up frames", nullptr},
    {"--seed", true, "layout seed", nullptr},
    {"--model", true, "model file replacing the layout mesh", nullptr},
    {"--backend", true, nullptr, nullptr},
    {"--gpu", true, "EGL device index", nullptr},
    {"--ref-samples", true, "accuracy: reference samples per pixel", nullptr},
    {"--light-index", true, "accuracy: which light to judge", nullptr},
    {"--max-memory-gib", true,
     "refuse a run whose estimated memory (scene, model file, frame targets, technique) exceeds this",
     nullptr},
    {"--no-timer-check", false, "skip the GPU-timer calibration (rows say unchecked)", nullptr},
    {"--no-stability", false, "accuracy: skip perturbation gain and flicker", nullptr},
    {"--strict-effects", false, "refuse techniques that cannot produce an effect the scene asks for",
     nullptr},
};

const PassThroughOption* findPassThrough(const std::string& name) {
    for (const PassThroughOption& o : kPassThrough)
        if (name == o.name) return &o;
    return nullptr;
}

/// Removes every occurrence of `option` from `args`: "option value" (or "option" for a flag) and
/// "option=value". The scan steps over the value of every other pass-through option, so a value
/// that happens to read like an option name (a model file called "--seed") is never taken for one.
void removeOption(std::vector<std::string>& args, const std::string& option) {
    const PassThroughOption* removed = findPassThrough(option);
    const size_t arity = removed && removed->takesValue ? 2 : 1;
    for (size_t i = 0; i < args.size();) {
        if (args[i] == option) {
            args.erase(args.begin() + ptrdiff_t(i),
                       args.begin() + ptrdiff_t(std::min(args.size(), i + arity)));
        } else if (args[i].rfind(option + "=", 0) == 0) {
            args.erase(args.begin() + ptrdiff_t(i));
        } else {
            const PassThroughOption* other = findPassThrough(args[i]);
            i += other && other->takesValue ? 2 : 1;
        }
    }
}

} // namespace

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
    app.add_option_function<int>(
        "--repeat", [this](int rounds) { repeat = rounds; },
        "rounds of interleaved measurement per combination");
    // Options of a single run that stay the same across the sweep; forwarded verbatim.
    for (const PassThroughOption& o : kPassThrough) {
        const std::string help = o.help ? o.help : backendNames(true); // headless: runs are worker processes
        if (o.takesValue)
            app.add_option_function<std::string>(
                o.name,
                [this, &o](const std::string& v) {
                    passThrough.insert(passThrough.end(), {o.name, v});
                },
                help);
        else
            app.add_flag_function(
                o.name, [this, &o](int64_t) { passThrough.push_back(o.name); }, help);
    }
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
    if (repeat) {
        // The bounds of a run's --repeat and of the definition file's "repeat".
        if (*repeat < 1 || *repeat > 1000)
            throw Error("--repeat " + std::to_string(*repeat) + ": expected 1..1000");
        d.repeat = *repeat;
    }
    // The command line replaces what the definition says, as it does for the axes: the file's value of
    // an option given here goes (bench's parser takes an option once, so keeping both was an error),
    // and so does the other half of a frame budget (--frames after a file's "seconds" must not be
    // ignored because --seconds wins).
    for (const PassThroughOption& o : kPassThrough)
        if (passes(o.name)) {
            removeOption(d.commonArgs, o.name);
            if (o.alternative) removeOption(d.commonArgs, o.alternative);
        }
    d.commonArgs.insert(d.commonArgs.end(), passThrough.begin(), passThrough.end());
}

bool SweepOptions::passes(const std::string& option) const {
    return std::find(passThrough.begin(), passThrough.end(), option) != passThrough.end();
}

} // namespace sb
