// Every shader permutation the registry can produce, compiled offline by glslang (glslangValidator,
// Debian glslang-tools), a compiler other than the driver's: a source that only Mesa's compiler
// accepts fails here.
//
// The permutations are derived, never listed by hand. The axes of a technique are the scene-side
// inputs its compile() reads (the built-in scene: lights, instances, meshes; the submission mode:
// SB_INSTANCED; --light: every light's type; the scene's effects, each toggled; the scene's shadow
// exceptions, a non-receiver or a light that casts none) and every property it
// declares, sampled by type: an enum or bool takes all its values, an int of at most 17 values all of
// them, a wider int {min, min+1, default, default+1, max}, a float {min, default, max}. A new property,
// scene, submission mode, light type or effect is covered without touching this file.
//
// The cross product of all of them is far too large (volume alone: 10 scenes x 4 x 4 x 7 x 2^11 x ...),
// and most axes never reach a shader (a resolution, a bias). So each compile() is identified by the set
// of stage sources it selected (the program cache's dump paths: files + defines + stage name the source
// exactly) and the axes are pruned to those that change it:
//   - two values of an axis are equivalent when they select the same sources in every context tried;
//     one representative per class is kept, and an axis with one class is dropped;
//   - contexts: the defaults, and each representative of each kept axis alone (pairs: an axis that
//     matters only once another is off its default, such as blur only with projectors, is found);
//   - repeated until nothing changes; then the cross product of the kept axes' representatives, the
//     exceptions, contact and fit axes excepted: each is crossed with each other kept axis in pairs
//     (see crossedInPairs and finalConfigs).
// Every program those configurations select is dumped (ProgramCache::setDumpDirectory, what
// bench --dump-shaders does), deduplicated by content, and each distinct stage goes through
// glslangValidator in its default mode: OpenGL GLSL validation with the profile of the #version line.
// (-G, OpenGL SPIR-V, refuses "#version 450 compatibility": SPIR-V for OpenGL has no compatibility
// profile; -V is Vulkan.) A failure prints glslang's log with the dumped file's path. Each technique is
// its own test (EveryTechnique/ShaderPermutationsTest.EveryPermutationCompilesWithGlslang/<name>).
//
// Sampled, not exhaustive, where a value goes into a define verbatim (synthetic's iteration counts,
// occluder's INSTANCE_COUNT, which follows the scene's instance count, here 2 where a scene has a
// random layout): those are
// covered at their sample values, which exercise the same source text with another number.
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <malloc.h>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"
#include "scenes/ShadowPlaneChooser.h"
#include "techniques/occluder/OccluderGL.h"
#include "techniques/occluder/OccluderMeshCache.h"

using namespace sb;

namespace {

constexpr int kWideInt = 16; ///< an int range with more steps than this is sampled
constexpr uint32_t kInstances = 2;
constexpr const char* kUnsupported = "<unsupported>";

struct Axis {
    std::string name;                ///< "scene", "submit", "light", "effects", "exceptions" or a property
    std::vector<std::string> values; ///< values[0] is the default ("" = the scene's own)
};

/// Axis name -> value; an axis that is absent has its default.
using Config = std::map<std::string, std::string>;

std::string formatNumber(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

void addUnique(std::vector<std::string>& values, const std::string& v) {
    if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
}

/// The sample of one property (its default first).
Axis propertyAxis(const PropertyDesc& p) {
    Axis a{p.name, {p.defaultValue}};
    switch (p.type) {
    case PropertyType::Bool:
        addUnique(a.values, "true");
        addUnique(a.values, "false");
        break;
    case PropertyType::Enum:
        for (const std::string& c : p.choices) addUnique(a.values, c);
        break;
    case PropertyType::Int: {
        const int64_t lo = int64_t(p.min), hi = int64_t(p.max), def = std::stoll(p.defaultValue);
        if (hi - lo <= kWideInt) {
            for (int64_t v = lo; v <= hi; ++v) addUnique(a.values, std::to_string(v));
        } else {
            for (int64_t v : {lo, lo + 1, def + 1, hi})
                if (v >= lo && v <= hi) addUnique(a.values, std::to_string(v));
        }
        break;
    }
    case PropertyType::Float:
        addUnique(a.values, formatNumber(p.min));
        addUnique(a.values, formatNumber(p.max));
        break;
    }
    return a;
}

/// The shadow exceptions a scene file can declare (CompileContext::defines), applied to the scene's
/// first instance or light: the built-in scenes declare none. A non-receiver listed last is drawn apart
/// by techniques that can keep the draw order that way (ReceiverSplit::drawsApart,
/// techniques/ReceiverSplit.h), with programs of their own.
constexpr const char* kNonReceiver = "first_instance_receives_none";
constexpr const char* kLastNonReceiver = "last_instance_receives_none";
constexpr const char* kUnshadowedLight = "first_light_casts_none";
constexpr size_t kSceneAxes = 5;

/// The scene-side axes: built-in scenes, submission modes, light types, effect toggles, exceptions.
std::vector<Axis> sceneAxes() {
    Axis scene{"scene", {}}, submit{"submit", {submitModeName(SubmitMode::Retained)}}, light{"light", {""}},
        effects{"effects", {""}},
        exceptions{"exceptions", {"", kNonReceiver, kLastNonReceiver, kUnshadowedLight}};
    for (const std::string& s : SceneLoader::listBuiltinScenes()) addUnique(scene.values, s);
    for (const auto& m : submitModes().entries()) addUnique(submit.values, m.name);
    for (const auto& l : lightTypeNames().entries()) addUnique(light.values, l.name);
    for (Effect e : kAllEffects) addUnique(effects.values, effectName(e));
    return {scene, submit, light, effects, exceptions};
}

std::string valueOf(const Config& c, const Axis& a) {
    auto it = c.find(a.name);
    return it == c.end() ? a.values[0] : it->second;
}

/// One Harness (context, scene, submitter) at a time, rebuilt when the scene-side inputs change;
/// evaluations are sorted by those inputs so that rebuilds are few.
class Workbench {
public:
    explicit Workbench(std::string dumpDir) : mDumpDir(std::move(dumpDir)) {}

    /// The sorted dump paths the technique's compile() selected for `c`, joined; kUnsupported when
    /// the technique refuses the configuration (ExitCode BadInput/Unsupported: a light type it cannot
    /// shadow, a capability). A compile or link error fails the test.
    std::string evaluate(const std::string& technique, const Config& c, const std::vector<Axis>& axes) {
        Harness& h = harness(valueOf(c, axes[0]), valueOf(c, axes[1]), valueOf(c, axes[2]));
        Scene scene = h.scene();
        if (std::string toggle = valueOf(c, axes[3]); !toggle.empty())
            scene.effects ^= EffectMask(*parseEffect(toggle));
        const std::string exception = valueOf(c, axes[4]);
        if (exception == kNonReceiver && !scene.instances.empty()) scene.instances[0].receivesShadow = false;
        if (exception == kLastNonReceiver && !scene.instances.empty())
            scene.instances.back().receivesShadow = false;
        if (exception == kUnshadowedLight && !scene.lights.empty()) scene.lights[0].castsShadows = false;
        std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(technique);
        for (size_t i = kSceneAxes; i < axes.size(); ++i)
            t->properties().set(axes[i].name, valueOf(c, axes[i]));
        if (!t->checkCapabilities(h.context()).empty()) return kUnsupported;
        ProgramCache& programs = h.programs();
        programs.takeDumpLog();
        programs.setDumpLabel(technique);
        try {
            t->setScene(scene);
            t->compile({programs, scene, h.submitter(), h.context()});
        } catch (const Error& e) {
            if (e.code() != ExitCode::Failure) {
                programs.takeDumpLog();
                return kUnsupported;
            }
            // The driver refused a source: a failure, and the dumped stages still go to glslang below
            // (its log is the second opinion).
            ADD_FAILURE() << technique << " " << describe(c) << ": " << e.what();
        }
        std::vector<std::string> log = programs.takeDumpLog();
        std::set<std::string> paths(log.begin(), log.end());
        std::string key;
        for (const std::string& p : paths) key += p + "\n";
        ++mEvaluations;
        // Hand the freed heap back: glibc keeps what llvmpipe's threads freed (8192^2 shadow maps
        // among small allocations), and without this the process grew past this machine's 24 GiB.
        // Every 16th compile: trimming costs system time, and 16 maps are a few GiB at most.
        if (mEvaluations % 16 == 0) malloc_trim(0);
        return key;
    }

    static std::string describe(const Config& c) {
        std::string text;
        for (const auto& [k, v] : c) text += (text.empty() ? "" : ":") + k + "=" + v;
        return text.empty() ? "defaults" : text;
    }
    size_t evaluations() const { return mEvaluations; }
    size_t harnesses() const { return mHarnesses; }

private:
    Harness& harness(const std::string& scene, const std::string& submit, const std::string& light) {
        std::string key = scene + "|" + submit + "|" + light;
        if (mHarness && key == mKey) return *mHarness;
        mHarness.reset();
        RunConfig config = test::quickConfig(scene, "", 16, *parseSubmitMode(submit));
        if (!light.empty()) config.sceneOptions.lightType = parseLightType(light);
        config.sceneOptions.instances = kInstances;
        Scene loaded;
        try {
            loaded = SceneLoader::load(scene, config.sceneOptions);
        } catch (const Error&) { // a scene without a random layout has a fixed instance list
            config.sceneOptions.instances.reset();
            loaded = SceneLoader::load(scene, config.sceneOptions);
        }
        config.camera = loaded.cameras.at(0).name;
        config.dumpShadersPath = mDumpDir;
        mHarness = std::make_unique<Harness>(config);
        mKey = key;
        ++mHarnesses;
        return *mHarness;
    }

    std::string mDumpDir;
    std::unique_ptr<Harness> mHarness;
    std::string mKey;
    size_t mEvaluations = 0, mHarnesses = 0;
};

/// The pruning of one technique's axes, round by round (each round's configurations are evaluated
/// together, sorted by scene-side inputs, so that each Harness is built once per round).
class Explorer {
public:
    Explorer(std::string technique, std::vector<Axis> axes)
        : mTechnique(std::move(technique)), mAxes(std::move(axes)) {
        for (const Axis& a : mAxes) mReps.push_back({a.name, {a.values[0]}});
    }

    const std::string& technique() const { return mTechnique; }
    const std::vector<Axis>& axes() const { return mAxes; }
    bool done() const { return mDone; }

    /// Contexts: the defaults and each representative of each kept axis alone; needed: every axis's
    /// every value in every context.
    std::vector<Config> roundConfigs() {
        mContexts = {{}};
        for (const Axis& r : mReps)
            for (size_t i = 1; i < r.values.size(); ++i) mContexts.push_back({{r.name, r.values[i]}});
        std::vector<Config> needed = mContexts;
        for (const Axis& a : mAxes)
            for (const Config& ctx : mContexts) {
                if (ctx.count(a.name)) continue;
                for (const std::string& v : a.values) {
                    Config c = ctx;
                    c[a.name] = v;
                    needed.push_back(c);
                }
            }
        return needed;
    }
    /// After the round's configurations are evaluated: new representatives; done when unchanged.
    void finishRound() {
        std::vector<Axis> next;
        for (const Axis& a : mAxes) next.push_back({a.name, classRepresentatives(a)});
        bool same = true;
        for (size_t i = 0; i < next.size(); ++i) same = same && next[i].values == mReps[i].values;
        mReps = next;
        mDone = same || ++mRounds >= 4;
    }
    /// The axes with more than one representative.
    std::vector<Axis> kept() const {
        std::vector<Axis> out;
        for (const Axis& r : mReps)
            if (r.values.size() > 1) out.push_back(r);
        return out;
    }

    bool known(const Config& c) const { return mMemo.count(c) != 0; }
    void record(const Config& c, std::string result) { mMemo[c] = std::move(result); }
    const std::string& result(const Config& c) const { return mMemo.at(c); }

private:
    /// First value of each class of values that select the same sources in every context where both
    /// are accepted: a configuration its technique refuses (kUnsupported) says nothing about sources,
    /// so it neither separates nor joins values. Greedy: a value joins the first class it agrees with.
    std::vector<std::string> classRepresentatives(const Axis& a) const {
        struct Class {
            std::string rep;
            std::vector<const std::string*> signature;
            long repSupported;
        };
        std::vector<Class> classes;
        for (const std::string& v : a.values) {
            std::vector<const std::string*> signature;
            for (const Config& ctx : mContexts) {
                if (ctx.count(a.name)) continue;
                Config c = ctx;
                c[a.name] = v;
                signature.push_back(&result(c));
            }
            auto agrees = [&](const std::vector<const std::string*>& other) { // where both are accepted
                for (size_t i = 0; i < signature.size(); ++i)
                    if (*signature[i] != kUnsupported && *other[i] != kUnsupported &&
                        *signature[i] != *other[i])
                        return false;
                return true;
            };
            auto supported = [](const std::vector<const std::string*>& sig) {
                return std::count_if(sig.begin(), sig.end(),
                                     [](const std::string* r) { return *r != kUnsupported; });
            };
            auto cls = std::find_if(classes.begin(), classes.end(),
                                    [&](const auto& c) { return agrees(c.signature); });
            if (cls == classes.end()) {
                classes.push_back({v, std::move(signature), supported(signature)});
                continue;
            }
            // The member its technique accepts most often represents the class (the cross product then
            // meets fewer refusals), and the class learns what this member showed.
            if (supported(signature) > cls->repSupported) {
                cls->rep = v;
                cls->repSupported = supported(signature);
            }
            for (size_t i = 0; i < signature.size(); ++i)
                if (*cls->signature[i] == kUnsupported) cls->signature[i] = signature[i];
        }
        std::vector<std::string> reps;
        for (const auto& c : classes) reps.push_back(c.rep);
        return reps;
    }

    std::string mTechnique;
    std::vector<Axis> mAxes, mReps;
    std::vector<Config> mContexts;
    std::map<Config, std::string> mMemo;
    int mRounds = 0;
    bool mDone = false;
};

/// Evaluates the (explorer, configuration) pairs not yet known, sorted by scene-side inputs (so that each
/// Harness is built once per round).
void evaluate(Workbench& bench, std::vector<std::pair<Explorer*, Config>> work) {
    auto sceneKey = [](const std::pair<Explorer*, Config>& w) {
        const std::vector<Axis>& a = w.first->axes();
        return valueOf(w.second, a[0]) + "|" + valueOf(w.second, a[1]) + "|" + valueOf(w.second, a[2]);
    };
    std::stable_sort(work.begin(), work.end(),
                     [&](const auto& a, const auto& b) { return sceneKey(a) < sceneKey(b); });
    for (auto& [explorer, config] : work)
        if (!explorer->known(config))
            explorer->record(config, bench.evaluate(explorer->technique(), config, explorer->axes()));
}

/// Every combination of the kept axes' values.
std::vector<Config> crossProduct(const std::vector<Axis>& kept) {
    std::vector<Config> out = {{}};
    for (const Axis& a : kept) {
        std::vector<Config> grown;
        for (const Config& c : out)
            for (const std::string& v : a.values) {
                Config g = c;
                g[a.name] = v;
                grown.push_back(g);
            }
        out = std::move(grown);
    }
    return out;
}

/// The axes crossed with each other kept axis in pairs only (the rest at defaults), not with the whole
/// product. The exceptions axis: its defines only remove terms from a lighting loop, so they meet each
/// other axis's source text in a pair; crossing them with the whole product tripled the compiles (9566
/// configurations, 7 minutes on 2 cores) for nothing new. `contact` (techniques/ContactShadows.h): its
/// define adds one function (shaders/common/contact_shadow.glsl, reading the frame block and the light's
/// kind) and one call around the visibility, text another axis meets in a pair; crossed whole it doubled
/// shadowmap's compiles (4991 programs, 530 s on 2 loaded cores). `fit` (cascaded's fit=sdsm): it adds
/// two programs of their own (the view depth pre-pass, with the submitter's defines only, and the
/// depth-range reduction, with none) and leaves the lighting program as it is.
bool crossedInPairs(const std::string& axis) {
    return axis == "exceptions" || axis == "contact" || axis == "fit";
}

/// The final configurations: every combination of the kept axes' values, except the crossedInPairs
/// axes, each of whose values is crossed with each value of every other kept axis in pairs.
std::vector<Config> finalConfigs(const std::vector<Axis>& kept) {
    std::vector<Axis> crossed, paired;
    for (const Axis& a : kept) (crossedInPairs(a.name) ? paired : crossed).push_back(a);
    std::vector<Config> out = crossProduct(crossed);
    for (size_t p = 0; p < paired.size(); ++p) {
        const Axis& pa = paired[p];
        for (size_t e = 1; e < pa.values.size(); ++e) {
            out.push_back({{pa.name, pa.values[e]}});
            for (const Axis& a : crossed)
                for (size_t i = 1; i < a.values.size(); ++i)
                    out.push_back({{pa.name, pa.values[e]}, {a.name, a.values[i]}});
            // The paired axes with each other, each pair once.
            for (size_t q = p + 1; q < paired.size(); ++q)
                for (size_t i = 1; i < paired[q].values.size(); ++i)
                    out.push_back({{pa.name, pa.values[e]}, {paired[q].name, paired[q].values[i]}});
        }
    }
    return out;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Runs glslangValidator on every file (paths relative to `dir`), many per process (each file is
/// validated on its own; one process per file would cost ~0.2 s each). A batch that fails is rerun
/// file by file so that each failure names its file with glslang's log. Returns the failures.
size_t validate(const std::string& dir, const std::vector<std::string>& files) {
    constexpr size_t kBatch = 64;
    size_t failures = 0;
    for (size_t start = 0; start < files.size(); start += kBatch) {
        std::string command = "cd '" + dir + "' && glslangValidator";
        const size_t end = std::min(files.size(), start + kBatch);
        for (size_t i = start; i < end; ++i) command += " '" + files[i] + "'";
        if (test::runCommand(command).exitCode == 0) continue;
        for (size_t i = start; i < end; ++i) {
            auto r = test::runCommand("glslangValidator '" + dir + "/" + files[i] + "'");
            if (r.exitCode == 0) continue;
            ++failures;
            ADD_FAILURE() << "glslangValidator refuses " << dir << "/" << files[i] << ":\n" << r.output;
        }
    }
    return failures;
}

bool glslangAvailable() {
    return test::runCommand("command -v glslangValidator").exitCode == 0;
}

// glslang must accept a shader the driver accepts and refuse a broken one: a negative control, so a
// validator that says yes to everything (a wrong mode, a stub) cannot pass the test below.
TEST(ShaderPermutations, GlslangRefusesABrokenShader) {
    ASSERT_TRUE(glslangAvailable()) << "glslangValidator not found: install the Debian package "
                                       "`glslang-tools` (scripts/install-deps.sh installs it)";
    const std::string dir = test::freshTestDir("glslang");
    test::writeFile(dir + "/good.frag",
                    "#version 450 compatibility\nvoid main() { gl_FragColor = vec4(1.0); }\n");
    test::writeFile(
        dir + "/bad.frag",
        "#version 450 compatibility\nvoid main() { vec3 c = vec2(1.0); gl_FragColor = vec4(c, 1.0); }\n");
    EXPECT_EQ(test::runCommand("glslangValidator " + dir + "/good.frag").exitCode, 0);
    EXPECT_NE(test::runCommand("glslangValidator " + dir + "/bad.frag").exitCode, 0);
}

// The permutations below set the occluder up 2751 times on a few meshes; its plane choice and bakes
// (techniques/occluder/OccluderMeshCache.h) are computed once per mesh and input, which took its test
// from 214 s to 18 s of CPU. A set-up served from memory must draw what a fresh one draws, bit for bit:
// the teapot (built-in planes, five baked layers) rendered with a cold cache and again with a warm one,
// the primitives (three generated meshes, planes chosen automatically) set up twice, and the chooser's
// answer through the cache equal to the chooser's own on a plate over a floor (a mesh that gets a plane).
TEST(ShaderPermutations, OccluderSetUpAgainChoosesAndBakesOnceAndDrawsTheSamePixels) {
    OccluderMeshCache::clear();
    // The visibility of one frame, and the texture layers the technique made (its counter: a layer
    // is resolution^2 texels, 512 by default).
    auto render = [](const std::string& scene, size_t* layers = nullptr, const char* planes = "16") {
        RunConfig config = test::quickConfig(scene, "", 64);
        config.camera = SceneLoader::load(scene, config.sceneOptions).cameras.at(0).name;
        Harness h(config);
        OccluderGL t;
        t.properties().set(Occluder::kPlanes, planes);
        h.prepare(t);
        h.renderFrame(t);
        for (const auto& [name, value] : t.counters())
            if (name == "occluder_texels" && layers) *layers = size_t(value / (512.0 * 512.0));
        return h.targets().readVisibilityRGBA32F();
    };
    size_t layers = 0;
    const std::vector<float> cold = render("teapot", &layers);
    EXPECT_EQ(layers, 5u) << "the teapot's planes own five occluder textures";
    const OccluderMeshCache::Stats baked = OccluderMeshCache::stats();
    EXPECT_EQ(baked.texelMisses, layers);
    EXPECT_EQ(baked.texelHits, 0u);
    const std::vector<float> warm = render("teapot");
    EXPECT_EQ(OccluderMeshCache::stats().texelMisses, layers) << "baked again";
    EXPECT_EQ(OccluderMeshCache::stats().texelHits, layers);
    // The textures shape the frame: without planes (planes=0) its visibility differs.
    const std::vector<float> unshadowed = render("teapot", nullptr, "0");
    size_t shaped = 0;
    for (size_t i = 0; i < cold.size(); ++i) shaped += cold[i] != unshadowed[i];
    EXPECT_GT(shaped, 0u) << "the teapot's frame shows no occluder shadow to compare";
    EXPECT_TRUE(cold == warm) << "a set-up from the cache draws other visibility than a fresh bake";

    render("primitives");
    render("primitives");
    const OccluderMeshCache::Stats chosen = OccluderMeshCache::stats();
    EXPECT_EQ(chosen.choiceMisses, 3u) << "primitives: three meshes without given planes, chosen once each";
    EXPECT_EQ(chosen.choiceHits, 3u);

    // A plate (an 8 x 8 grid at y = 1) over a floor (8 x 8 at y = 0), lit from above: the chooser
    // finds a plane. The cache's answer equals the chooser's, and any changed input is chosen anew.
    Mesh m;
    m.name = "plate_over_floor";
    for (float y : {0.0f, 1.0f}) {
        const uint32_t base = uint32_t(m.positions.size());
        const float h = y > 0.0f ? 0.5f : 2.0f;
        for (int j = 0; j <= 8; ++j)
            for (int i = 0; i <= 8; ++i)
                m.positions.emplace_back(-h + h * float(i) / 4.0f, y, -h + h * float(j) / 4.0f);
        for (uint32_t j = 0; j < 8; ++j)
            for (uint32_t i = 0; i < 8; ++i) {
                const uint32_t a = base + j * 9 + i, b = a + 1, c = a + 9, d = c + 1;
                for (uint32_t v : {a, c, d, a, d, b}) m.indices.push_back(v);
            }
    }
    m.normals.assign(m.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    const std::vector<glm::vec3> up = {glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f))};
    const ShadowPlaneChoice direct = ShadowPlaneChooser::choose(m, up, 4);
    ASSERT_FALSE(direct.planes.empty()) << direct.reason;
    for (int round = 0; round < 2; ++round) {
        const ShadowPlaneChoice cached = OccluderMeshCache::choose(m, up, 4);
        ASSERT_EQ(cached.planes.size(), direct.planes.size());
        for (size_t i = 0; i < direct.planes.size(); ++i) {
            const ShadowPlane &a = cached.planes[i], &b = direct.planes[i];
            EXPECT_EQ(a.name, b.name);
            EXPECT_TRUE(a.origin == b.origin && a.normal == b.normal && a.right == b.right && a.up == b.up &&
                        a.width == b.width && a.height == b.height && a.sectionOnly == b.sectionOnly)
                << a.name;
        }
        EXPECT_EQ(cached.reason, direct.reason);
        EXPECT_EQ(cached.capturedPct, direct.capturedPct);
        EXPECT_EQ(cached.falsePct, direct.falsePct);
    }
    const size_t before = OccluderMeshCache::stats().choiceMisses;
    EXPECT_EQ(before, chosen.choiceMisses + 1) << "the plate was chosen for once";
    Mesh moved = m;
    moved.positions[0].x = std::nextafter(moved.positions[0].x, 1.0f); // one vertex, one ulp
    OccluderMeshCache::choose(moved, up, 4);
    OccluderMeshCache::choose(m, up, 3);
    OccluderMeshCache::choose(m, {glm::vec3(0.0f, 1.0f, 0.0f)}, 4);
    EXPECT_EQ(OccluderMeshCache::stats().choiceMisses, before + 3) << "a changed vertex, limit or light";

    // A full cache drops its least recently used entries: with room for none, everything is made again.
    const size_t budget = OccluderMeshCache::maxBytes();
    OccluderMeshCache::setMaxBytes(0);
    EXPECT_EQ(OccluderMeshCache::stats().entries, 0u);
    OccluderMeshCache::choose(m, up, 4);
    EXPECT_EQ(OccluderMeshCache::stats().choiceMisses, before + 4);
    OccluderMeshCache::setMaxBytes(budget);
    OccluderMeshCache::clear();
}

/// One test per registered technique, so that ctest runs them side by side and each has its own time
/// limit (tests/CMakeLists.txt): the whole set took 111 s on one core of a 2-core AMD EPYC virtual machine
/// with transparent huge pages and 658 s without (every evaluation builds the technique's shadow maps,
/// which llvmpipe zeroes on creation: 50 million page faults, not the compiles, were the time).
class ShaderPermutationsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ShaderPermutationsTest, EveryPermutationCompilesWithGlslang) {
    ASSERT_TRUE(glslangAvailable()) << "glslangValidator not found: install the Debian package "
                                       "`glslang-tools` (scripts/install-deps.sh installs it)";
    const std::string name = GetParam();
    const std::string dumpDir = test::freshTestDir("permutations-" + name);
    const auto started = std::chrono::steady_clock::now();
    Workbench bench(dumpDir);
    size_t configurations = 0, unsupported = 0;
    std::set<std::string> programs; ///< distinct stage paths
    std::vector<Axis> axes = sceneAxes();
    {
        const std::unique_ptr<GlTechnique> technique = TechniqueRegistry::create(name);
        // The hybrid's properties name its parts, whose programs are explored as techniques of their
        // own; its scene axes at the default parts show that the parts compile side by side.
        if (name != "hybrid")
            for (const PropertyDesc& p : technique->info().properties) axes.push_back(propertyAxis(p));
    }
    Explorer explorer(name, axes);
    while (!explorer.done()) {
        std::vector<std::pair<Explorer*, Config>> work;
        for (Config& c : explorer.roundConfigs()) work.emplace_back(&explorer, std::move(c));
        evaluate(bench, work);
        explorer.finishRound();
    }
    const std::vector<Axis> kept = explorer.kept();
    const std::vector<Config> all = finalConfigs(kept);
    std::vector<std::pair<Explorer*, Config>> finalWork;
    for (const Config& c : all) finalWork.emplace_back(&explorer, c);
    evaluate(bench, finalWork);
    std::string keptText;
    for (const Axis& a : kept) keptText += " " + a.name + "(" + std::to_string(a.values.size()) + ")";
    for (const Config& c : all) {
        const std::string& r = explorer.result(c);
        ++configurations;
        if (r == kUnsupported) {
            ++unsupported;
            continue;
        }
        for (size_t s = 0, end; (end = r.find('\n', s)) != std::string::npos; s = end + 1)
            programs.insert(r.substr(s, end - s));
    }
    std::printf("[ shaders  ] %-10s %zu configurations over the axes that change a source:%s -> %zu stages\n",
                name.c_str(), all.size(), keptText.empty() ? " none" : keptText.c_str(), programs.size());
    EXPECT_FALSE(programs.empty()) << name << " selected no program at all";

    // Distinct by content: the same program dumped under two configurations is validated once.
    std::map<std::string, std::string> byContent; ///< source -> first dump path
    for (const std::string& p : programs) byContent.emplace(test::readFile(dumpDir + "/" + p), p);
    std::set<std::string> permutations; ///< distinct (program, defines) after content dedupe
    std::vector<std::string> files;
    for (const auto& [source, path] : byContent) {
        permutations.insert(path.substr(path.find('/') + 1, path.rfind('/') - path.find('/') - 1));
        files.push_back(path);
    }
    // Digests of what was selected and compiled: a change that means to alter only the cost (a cache,
    // fewer rebuilds) must leave both as they were.
    std::string selections, sources;
    for (const Config& c : all) selections += Workbench::describe(c) + "=" + explorer.result(c) + "\n";
    for (const auto& entry : byContent) sources += entry.first + "\n";
    std::printf("[ shaders  ] digests: selections %016zx, sources %016zx\n",
                std::hash<std::string>{}(selections), std::hash<std::string>{}(sources));
    const auto validated = std::chrono::steady_clock::now();
    const size_t failures = validate(dumpDir, files);
    const double glslangSeconds = secondsSince(validated);
    std::printf(
        "[ shaders  ] %zu configurations (%zu refused by the technique), %zu harnesses, %zu compiles\n",
        configurations, unsupported, bench.harnesses(), bench.evaluations());
    std::printf("[ shaders  ] %zu stages; %zu distinct sources (%zu program permutations) compiled by "
                "glslangValidator, %zu failed\n",
                programs.size(), byContent.size(), permutations.size(), failures);
    std::printf("[ shaders  ] %.1f s exploring and compiling on the driver, %.1f s in glslangValidator\n",
                secondsSince(started) - glslangSeconds, glslangSeconds);
    EXPECT_EQ(failures, 0u);
    if (!HasFailure()) std::filesystem::remove_all(dumpDir); // kept for inspection when something failed
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, ShaderPermutationsTest,
                         ::testing::ValuesIn(TechniqueRegistry::namesOn(Api::GL)),
                         [](const ::testing::TestParamInfo<std::string>& param) { return param.param; });

} // namespace
