#include "bench/lib/sweep/SweepDefinition.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/lib/options/QualitySweep.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/CsvNumber.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/Paths.h"
#include "core/Strings.h"
#include "registry/MemoryBudget.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

namespace sb {

namespace {

/// A JSON scalar as command-line text: strings as they are, integers without a decimal point.
std::string scalarText(const JsonReader& r) {
    const nlohmann::json& v = r.value();
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
    if (v.is_number_float()) {
        std::ostringstream os;
        os << v.get<double>(); // shortest round-trip text for the values people write ("0.5", "10")
        return os.str();
    }
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    r.fail("a string or a number");
}

/// An axis: one scalar or an array of them.
std::vector<std::string> axisValues(const JsonReader& r) {
    if (!r.value().is_array()) return {scalarText(r)};
    std::vector<std::string> out;
    for (const JsonReader& e : r.elements(true)) out.push_back(scalarText(e));
    return out;
}

/// {"name": "shadowmap", "properties": {"resolution": [512, 1024], "pcf": 3}} ->
/// "shadowmap:resolution=512,1024:pcf=3"
std::string techniqueFromJson(const JsonReader& r) {
    if (r.value().is_string()) return r.string();
    r.requireObject({"name", "properties"});
    std::string spec = r["name"].string();
    if (!r.has("properties")) return spec;
    const JsonReader props = r["properties"];
    if (!props.value().is_object()) props.fail("an object of property values");
    for (const auto& item : props.value().items()) {
        const JsonReader value(item.value(), r.source(), props.path() + "/" + item.key());
        spec += ":" + item.key() + "=" + join(axisValues(value), ",");
    }
    return spec;
}

void addOption(std::vector<std::string>& args, const JsonReader& root, const char* key, const char* option) {
    if (root.has(key)) {
        args.push_back(option);
        args.push_back(scalarText(root[key]));
    }
}

/// Runs bench's own option parser over one combination, so every value is checked exactly as a plain
/// `bench` run would check it.
RunConfig validateArgs(const std::vector<std::string>& args, SweepPlan::Mode mode, const std::string& where) {
    try {
        return RunOptions::parseArgs(args, mode == SweepPlan::Mode::Accuracy ? RunConfig::Mode::Accuracy
                                                                             : RunConfig::Mode::Measure);
    } catch (const Error& e) {
        throw Error("sweep: " + where + ": " + e.what());
    }
}

/// The scene of one combination loads with the combination's scene options (instances, scale,
/// tessellation, light, memory limit) and has its camera, exactly as the worker will load it: what a
/// worker would refuse is bad input before anything is measured, not a failed row after. Scenes are
/// loaded once per distinct set of scene options (the camera, size and submit axes share one).
class SceneCheck {
public:
    /// Also the whole configuration of each of `techniques` within the memory limit
    /// (registry/MemoryBudget.h).
    void check(const RunConfig& config, const std::vector<std::string>& techniques,
               const std::string& where) {
        const SceneOptions& o = config.sceneOptions;
        const std::string key = config.scene + "|" + o.modelPath + "|" +
                                std::to_string(o.instances.value_or(0)) + "|" + std::to_string(o.scale) +
                                "|" + std::to_string(o.tessellation.value_or(0)) + "|" +
                                std::to_string(o.tessellationFactor) + "|" +
                                std::to_string(o.lightType ? int(*o.lightType) : -1) + "|" +
                                std::to_string(o.seed.value_or(0)) + "|" + std::to_string(o.memoryLimitBytes);
        auto it = mScenes.find(key);
        if (it == mScenes.end()) {
            try {
                const Scene scene = SceneLoader::load(config.scene, o);
                Loaded loaded{{}, int(scene.lights.size()), SceneLoader::estimateBytes(scene)};
                for (const CameraPreset& c : scene.cameras) loaded.cameras.push_back(c.name);
                it = mScenes.emplace(key, loaded).first;
            } catch (const Error& e) {
                throw Error("sweep: " + where + ": " + e.what(), e.code());
            }
        }
        std::vector<TechniqueSpec> specs;
        for (const std::string& t : techniques) specs.push_back(TechniqueSpec::parse(t));
        MemoryBudget::check(specs, {config.width, config.height, it->second.lights}, it->second.bytes,
                            o.memoryLimitBytes, "sweep: " + where + ": ");
        const std::vector<std::string>& cameras = it->second.cameras;
        if (std::find(cameras.begin(), cameras.end(), config.camera) == cameras.end())
            throw Error("sweep: scene '" + config.scene + "' has no camera '" + config.camera +
                        "' (known: " + join(cameras, ", ") + ")");
    }

private:
    /// What a combination needs of its scene: its cameras' names, its lights and its memory estimate.
    struct Loaded {
        std::vector<std::string> cameras;
        int lights = 0;
        uint64_t bytes = 0;
    };
    std::map<std::string, Loaded> mScenes; ///< scene-options key -> what was loaded
};

/// a * b, saturating at the largest value (the estimate of a sweep's size must not wrap).
uint64_t saturatingProduct(uint64_t a, uint64_t b) {
    return a != 0 && b > UINT64_MAX / a ? UINT64_MAX : a * b;
}

/// How many specs "name:k=a,b:j=c,d,e" expands to (2 x 3 here), without expanding it.
uint64_t techniqueCount(const std::string& text) {
    uint64_t n = 1;
    for (const auto& [key, values] : TechniqueSpec::parse(text).properties)
        n = saturatingProduct(n, uint64_t(std::count(values.begin(), values.end(), ',')) + 1);
    return n;
}

/// One axis of the product: the CSV column it describes, bench's option, its values, and the value
/// that means "leave the option out".
struct Axis {
    const char* column;
    const char* option;
    std::vector<std::string> values;
    std::string omit;
};

/// Calls `f` with every combination of the axes' values, the last axis varying fastest.
template <typename F>
void forEachCombination(const std::vector<Axis>& axes, F&& f) {
    std::vector<size_t> at(axes.size(), 0);
    std::vector<std::string> values(axes.size());
    for (;;) {
        for (size_t i = 0; i < axes.size(); ++i) values[i] = axes[i].values[at[i]];
        f(values);
        size_t i = axes.size();
        while (i > 0 && ++at[i - 1] == axes[i - 1].values.size()) at[--i] = 0;
        if (i == 0) return;
    }
}

/// The columns a failed row gets for a combination (values in the form the measured rows write them:
/// numbers as csvNumber, the size split into width and height, omitted options as bench records them).
KeyValues identityColumns(const std::vector<std::string>& v) {
    const auto [w, h] = RunOptions::parseSize(v[3]);
    return {{"scene", v[0]},
            {"lights", v[1] == "scene" ? "" : v[1]},
            {"camera", v[2]},
            {"width", std::to_string(w)},
            {"height", std::to_string(h)},
            {"submit", v[4]},
            {"scale", csvNumber(std::stod(v[5]))},
            {"tessellation", v[6]},
            {"tess_factor", csvNumber(std::stod(v[7]))},
            {"instances", v[8] == "default" ? "" : v[8]},
            {"api", v[9]}};
}

template <typename T>
std::vector<T> orDefault(std::vector<T> v, T fallback) {
    if (v.empty()) v.push_back(std::move(fallback));
    return v;
}

} // namespace

std::vector<std::string> SweepDefinition::splitList(const std::string& text, const std::string& option) {
    std::vector<std::string> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = text.find(',', start);
        std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) throw Error(option + " " + text + ": empty item in the list (expected a,b,c)");
        out.push_back(item);
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

std::vector<std::string> SweepDefinition::expandTechnique(const std::string& text) {
    const TechniqueSpec spec = TechniqueSpec::parse(text);
    std::vector<TechniqueSpec> out{{spec.name, {}}};
    for (const auto& [key, values] : spec.properties) {
        std::vector<TechniqueSpec> next;
        for (const TechniqueSpec& partial : out)
            for (const std::string& v : splitList(values, "-t " + text + ": property '" + key + "'")) {
                TechniqueSpec s = partial;
                s.properties.emplace_back(key, v);
                next.push_back(std::move(s));
            }
        out = std::move(next);
    }
    std::vector<std::string> texts;
    for (const TechniqueSpec& s : out) texts.push_back(s.toString());
    return texts;
}

SweepDefinition SweepDefinition::fromJsonFile(const std::string& path) {
    // The scene files' reader: nesting bounded, numbers checked, errors at a line and column.
    const nlohmann::json doc = JsonReader::parse(Paths::readTextFile(path), path);
    return fromJson(doc, path, "", std::filesystem::path(path).stem().string());
}

SweepDefinition SweepDefinition::fromJson(const nlohmann::json& doc, const std::string& source,
                                          const std::string& path, const std::string& defaultName) {
    const JsonReader root(doc, source, path);
    root.requireObject({"name",    "mode",        "quality_sweep", "techniques", "scenes",  "instances",
                        "scale",   "tess",        "tess_factor",   "submit",     "camera",  "size",
                        "light",   "repeat",      "frames",        "warmup",     "seconds", "seed",
                        "backend", "ref_samples", "stability",     "args",       "api"});
    SweepDefinition d;
    d.name = root.has("name") ? root["name"].string() : defaultName;
    if (root.has("mode")) {
        const std::string mode = root["mode"].string();
        if (mode != "measure" && mode != "accuracy") root["mode"].fail("\"measure\" or \"accuracy\"");
        d.mode = mode == "accuracy" ? SweepPlan::Mode::Accuracy : SweepPlan::Mode::Measure;
    }
    if (root.has("quality_sweep")) d.qualitySweep = root["quality_sweep"].boolean();
    if (root.has("techniques"))
        for (const JsonReader& t : root["techniques"].elements(true))
            d.axes.techniques.push_back(techniqueFromJson(t));
    const std::pair<const char*, std::vector<std::string>*> axes[] = {{"scenes", &d.axes.scenes},
                                                                      {"instances", &d.axes.instances},
                                                                      {"scale", &d.axes.scale},
                                                                      {"tess", &d.axes.tess},
                                                                      {"tess_factor", &d.axes.tessFactor},
                                                                      {"submit", &d.axes.submit},
                                                                      {"camera", &d.axes.camera},
                                                                      {"size", &d.axes.size},
                                                                      {"light", &d.axes.light},
                                                                      {"api", &d.axes.api}};
    for (const auto& [key, axis] : axes)
        if (root.has(key)) *axis = axisValues(root[key]);
    if (root.has("repeat")) d.repeat = int(root["repeat"].integer(1, 1000, "an integer in [1, 1000]"));
    addOption(d.commonArgs, root, "frames", "--frames");
    addOption(d.commonArgs, root, "warmup", "--warmup");
    addOption(d.commonArgs, root, "seconds", "--seconds");
    addOption(d.commonArgs, root, "seed", "--seed");
    addOption(d.commonArgs, root, "backend", "--backend");
    addOption(d.commonArgs, root, "ref_samples", "--ref-samples");
    if (root.has("stability") && !root["stability"].boolean()) d.commonArgs.push_back("--no-stability");
    if (root.has("args"))
        for (const JsonReader& a : root["args"].elements()) d.commonArgs.push_back(a.string());
    return d;
}

void SweepDefinition::checkSize(uint64_t configurations, const std::string& how) const {
    if (configurations <= maxConfigs) return;
    throw Error(
        "sweep '" + name + "': " +
        (configurations == UINT64_MAX ? std::string("more than 2^64") : std::to_string(configurations)) +
        " configurations (" + how + ") exceed the limit of " + std::to_string(maxConfigs) +
        "; narrow an axis or raise it with --max-configs N");
}

SweepPlan SweepDefinition::expand() const {
    SweepPlan plan;
    plan.name = name;
    plan.mode = mode;
    plan.commonArgs = commonArgs;
    if (mode != SweepPlan::Mode::Accuracy && qualitySweep)
        throw Error("sweep '" + name + "': quality_sweep needs \"mode\": \"accuracy\"");
    // The size is known from the list lengths alone: a sweep of 10^6 configurations is refused in
    // microseconds rather than after expanding (and validating) every one of them.
    uint64_t specCount = 0;
    for (const std::string& t : orDefault(axes.techniques, std::string("shadowmap")))
        specCount = std::min<uint64_t>(UINT64_MAX - 1, specCount) + techniqueCount(t);
    uint64_t combinations = 1;
    for (const auto* axis : {&axes.scenes, &axes.instances, &axes.scale, &axes.tess, &axes.tessFactor,
                             &axes.submit, &axes.camera, &axes.size, &axes.light, &axes.api})
        combinations = saturatingProduct(combinations, std::max<uint64_t>(1, axis->size()));
    checkSize(saturatingProduct(saturatingProduct(specCount, combinations), uint64_t(repeat)),
              std::to_string(specCount) + " technique specs x " + std::to_string(combinations) +
                  " axis combinations x " + std::to_string(repeat) + " rounds");

    std::vector<std::string> techniques;
    for (const std::string& t : orDefault(axes.techniques, std::string("shadowmap")))
        for (const std::string& spec : expandTechnique(t)) {
            TechniqueRegistry::describe(TechniqueSpec::parse(spec)); // names, knobs and ranges checked
            if (!qualitySweep) {
                techniques.push_back(spec);
                continue;
            }
            for (const TechniqueSpec& q : QualitySweep::expand(TechniqueSpec::parse(spec)))
                techniques.push_back(q.toString());
        }
    std::set<std::string> seen;
    for (const std::string& t : techniques)
        if (!seen.insert(t).second)
            throw Error("sweep '" + name + "': technique '" + t + "' is listed twice");
    if (qualitySweep)
        checkSize(saturatingProduct(saturatingProduct(techniques.size(), combinations), uint64_t(repeat)),
                  std::to_string(techniques.size()) + " quality-sweep specs x " +
                      std::to_string(combinations) + " axis combinations x " + std::to_string(repeat) +
                      " rounds");

    const SweepAxes a{{},
                      orDefault(axes.scenes, std::string("aircraft")),
                      orDefault(axes.instances, std::string("default")),
                      orDefault(axes.scale, std::string("1")),
                      orDefault(axes.tess, std::string("default")),
                      orDefault(axes.tessFactor, std::string("1")),
                      orDefault(axes.submit, std::string("retained")),
                      orDefault(axes.camera, std::string("far")),
                      orDefault(axes.size, std::string("1024x1024")),
                      orDefault(axes.light, std::string("scene")),
                      orDefault(axes.api, std::string("gl"))};
    SceneCheck scenes;
    // Outer to inner (see the header); an axis value equal to `omit` adds no option (bench's default).
    const std::vector<Axis> product{{"scene", "--scene", a.scenes, ""},
                                    {"light", "--light", a.light, "scene"},
                                    {"camera", "--camera", a.camera, ""},
                                    {"size", "--size", a.size, ""},
                                    {"submit", "--submit", a.submit, ""},
                                    {"scale", "--scale", a.scale, ""},
                                    {"tess", "--tess", a.tess, "default"},
                                    {"tess_factor", "--tess-factor", a.tessFactor, ""},
                                    {"instances", "--instances", a.instances, "default"},
                                    {"api", "--api", a.api, "gl"}};
    forEachCombination(product, [&](const std::vector<std::string>& values) {
        std::vector<std::string> args;
        for (size_t i = 0; i < product.size(); ++i)
            if (values[i] != product[i].omit) args.insert(args.end(), {product[i].option, values[i]});
        std::vector<std::string> all = commonArgs;
        all.insert(all.end(), args.begin(), args.end());
        std::string where = "combination";
        for (size_t i = 0; i < product.size(); ++i)
            where += std::string(" ") + product[i].column + "=" + values[i];
        const RunConfig config = validateArgs(all, mode, where); // before identityColumns reads the numbers
        scenes.check(config, techniques, where);
        plan.addGroup(std::move(args), identityColumns(values), techniques, repeat);
    });
    return plan;
}

} // namespace sb
