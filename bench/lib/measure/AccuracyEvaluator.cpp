#include "bench/lib/measure/AccuracyEvaluator.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/Error.h"
#include "core/Fnv1a.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"

namespace sb {

namespace {
// Unit vector towards light `l` from p.
glm::vec3 towardsLight(const Light& l, const glm::vec3& p) {
    return l.type == LightType::Directional ? -glm::normalize(l.direction) : glm::normalize(l.position - p);
}

// The light turned by `deg` about an axis perpendicular to its direction (directional, spot), or
// moved sideways by the same angle as seen from the scene's centre (point).
Light turnLight(const Light& l, float deg, const glm::vec3& sceneCentre) {
    Light out = l;
    glm::vec3 dir =
        l.type == LightType::Point ? glm::normalize(sceneCentre - l.position) : glm::normalize(l.direction);
    glm::vec3 axis = glm::normalize(glm::cross(dir, anyPerpendicularUp(dir)));
    glm::mat3 r = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(deg), axis));
    if (l.type == LightType::Point)
        out.position = sceneCentre - r * (sceneCentre - l.position);
    else
        out.direction = r * dir;
    return out;
}
} // namespace

AccuracyEvaluator::AccuracyEvaluator(MeasuredHarness& harness)
    : mHarness(harness), mEmbreeTime(harness.pathTime()) {
    mEmbree = std::make_unique<EmbreeScene>(harness.scene());
    mTracer = std::make_unique<ReferenceTracer>(harness.scene(), *mEmbree);
}

AccuracyEvaluator::~AccuracyEvaluator() = default;

void AccuracyEvaluator::followCasters() {
    const Scene& scene = mHarness.scene();
    if (!scene.motion || !scene.motion->casters || mHarness.pathTime() == mEmbreeTime) return;
    mTracer.reset(); // it holds the Embree scene it replaces
    mEmbree = std::make_unique<EmbreeScene>(scene);
    mTracer = std::make_unique<ReferenceTracer>(scene, *mEmbree);
    mEmbreeTime = mHarness.pathTime();
}

namespace {
/// Beyond a point or spot light's range, and outside a spot's outer cone, no light arrives, so whether
/// a sample "sees" the light does not change the image: techniques that use the range (shadow volumes'
/// range culling, scissor and finite volumes) or the cone (a spot's map covers the cone only and calls
/// what lies outside it lit, while the reference calls it 0) may leave anything there, and such samples
/// are not judged. Judging them made every technique, exact ones included, 85% "wrong" on sphere_plane
/// with --light spot.
bool lightArrives(const Light& light, const glm::vec3& p) {
    if (light.type == LightType::Directional) return true;
    const glm::vec3 d = p - light.position;
    const float dist = glm::length(d);
    if (light.range > 0.0f && !(dist < light.range)) return false;
    if (light.type != LightType::Spot || !(dist > 0.0f)) return true;
    return glm::dot(d / dist, glm::normalize(light.direction)) >= std::cos(glm::radians(light.spotOuterDeg));
}
} // namespace

AccuracyEvaluator::Sample AccuracyEvaluator::judgeFrame(Technique& technique, const AccuracyOptions& o,
                                                        TraceStats* stats, GBuffer* gbuffer) {
    mHarness.renderFrame(technique);
    return judgeVisibility(mHarness.readVisibility(), o, stats, gbuffer);
}

AccuracyEvaluator::Sample AccuracyEvaluator::judgeVisibility(std::vector<float> visibilityRgba,
                                                             const AccuracyOptions& o, TraceStats* stats,
                                                             GBuffer* gbuffer) {
    const Scene& scene = mHarness.scene();
    followCasters(); // the reference traces the scene as this frame drew it
    Sample s;
    s.techniqueRgba = std::move(visibilityRgba);
    s.technique = AccuracyMetrics::channel(s.techniqueRgba, o.light);
    const GBuffer g = mHarness.renderGBuffer(); // the judged API's own rasterisation of the samples
    ReferenceTracer::Options ro;
    ro.softSamples = o.referenceSamples;
    s.reference = reference(g, o.light, ro, stats);
    s.mask.assign(g.size(), 0);
    const Light& light = scene.lights[size_t(o.light)];
    for (size_t i = 0; i < g.size(); ++i) {
        if (!g.covered(i)) continue;
        glm::vec3 p(g.position[i]);
        s.mask[i] = glm::dot(mTracer->seenNormalAt(g, i), towardsLight(light, p)) > o.nDotLThreshold &&
                    lightArrives(light, p);
    }
    if (gbuffer) *gbuffer = g;
    return s;
}

TexelDensity::Summary AccuracyEvaluator::texelDensity(const MapTexels& maps, const AccuracyOptions& o,
                                                      const Sample& judged, const GBuffer& g) const {
    const Scene& scene = mHarness.scene();
    const glm::mat4 viewProj = mHarness.projection() * mHarness.view();
    const glm::ivec2 size(mHarness.config().width, mHarness.config().height);
    std::vector<double> values;
    for (size_t i = 0; i < g.size(); ++i) {
        if (!judged.mask[i]) continue;
        const uint32_t instance = g.instance(i);
        // A non-receiver's lighting looks no map up (shadowApplies, common/lighting.glsl).
        if (instance >= scene.instances.size() || !scene.instances[instance].receivesShadow) continue;
        const ShadedPoint at{glm::dvec3(glm::vec3(g.position[i])), instance};
        if (const std::optional<double> t = TexelDensity::texelsPerPixel(
                maps, size_t(o.light), at, glm::dvec3(mTracer->seenNormalAt(g, i)), viewProj, size))
            values.push_back(*t);
    }
    return TexelDensity::summarize(std::move(values));
}

namespace {
/// The most the kept references (AccuracyEvaluator::reference) may hold: two 1920x1080 images.
constexpr size_t kReferenceBytes = size_t(16) << 20;

/// Everything a reference image depends on besides the Embree scene: the samples (the G-buffer), the
/// light as it is now (the stability check turns it) and the tracer's options.
uint64_t referenceKey(const GBuffer& g, const Light& l, int light, const ReferenceTracer::Options& o,
                      float casterTime) {
    Fnv1a h;
    h.value(g.width);
    h.value(g.height);
    h.vector(g.position);
    h.vector(g.primitive);
    h.vector(g.backFacing);
    h.value(light);
    h.value(casterTime);
    h.value(o.softSamples);
    h.value(o.seed);
    h.value(o.forceHard);
    h.value(l.type);
    h.value(l.direction);
    h.value(l.position);
    h.value(l.range);
    h.value(l.spotOuterDeg);
    h.value(l.spotInnerDeg);
    h.value(l.shape);
    h.value(l.size);
    h.value(l.angularRadiusDeg);
    h.value(l.castsShadows);
    return h.result();
}
} // namespace

std::vector<float> AccuracyEvaluator::reference(const GBuffer& g, int light,
                                                const ReferenceTracer::Options& o, TraceStats* stats) {
    // The tracer throws for a light the scene does not have; it is asked before the key reads the light.
    if (light < 0 || size_t(light) >= mHarness.scene().lights.size())
        return mTracer->trace(g, light, o, stats).value;
    const uint64_t key = referenceKey(g, mHarness.scene().lights[size_t(light)], light, o, mEmbreeTime);
    if (!stats) // a caller that reports the trace's rays and time gets a trace
        for (const auto& [k, image] : mReferences)
            if (k == key) return image;
    std::vector<float> image = mTracer->trace(g, light, o, stats).value;
    // Kept within kReferencesKept images and kReferenceBytes: the matrix's 128x128 images are 64 KiB,
    // while `bench accuracy` at a large size gets no more than that budget on top of what it held before.
    if (image.size() * sizeof(float) > kReferenceBytes) return image;
    size_t bytes = image.size() * sizeof(float);
    for (const auto& kept : mReferences) bytes += kept.second.size() * sizeof(float);
    while (!mReferences.empty() && (mReferences.size() >= kReferencesKept || bytes > kReferenceBytes)) {
        bytes -= mReferences.front().second.size() * sizeof(float);
        mReferences.erase(mReferences.begin());
    }
    mReferences.emplace_back(key, image);
    return image;
}

uint64_t AccuracyEvaluator::techniqueChanges(const Sample& a, const Sample& b) const {
    // Judged where both images evaluate the sample (the mask moves with the camera too).
    std::vector<uint8_t> both(a.mask.size());
    for (size_t i = 0; i < both.size(); ++i) both[i] = a.mask[i] && b.mask[i];
    return AccuracyMetrics::changedSamples(a.technique, b.technique, both);
}

void AccuracyEvaluator::measureStability(Technique& technique, const AccuracyOptions& o, const Sample& base,
                                         AccuracyResult& r) {
    auto referenceChanges = [](const Sample& a, const Sample& b) {
        std::vector<uint8_t> both(a.mask.size());
        for (size_t i = 0; i < both.size(); ++i) both[i] = a.mask[i] && b.mask[i];
        return AccuracyMetrics::changedSamples(a.reference, b.reference, both);
    };
    // Camera: a quarter-pixel shift.
    mHarness.setPixelShift({o.cameraShiftPx, 0.0f});
    Sample cam = judgeFrame(technique, o, nullptr);
    r.cameraChangesTechnique = techniqueChanges(base, cam);
    r.cameraChangesReference = referenceChanges(base, cam);
    r.cameraGain = AccuracyMetrics::perturbationGain(r.cameraChangesTechnique, r.cameraChangesReference);
    mHarness.setPixelShift({0.0f, 0.0f});

    // Light: a 0.01 degree turn (the technique re-runs its light-dependent precompute).
    const Light original = mHarness.scene().lights[size_t(o.light)];
    mHarness.setLight(size_t(o.light),
                      turnLight(original, o.lightTurnDeg, mHarness.scene().computeBounds().center()));
    mHarness.prepare(technique);
    Sample turned = judgeFrame(technique, o, nullptr);
    r.lightChangesTechnique = techniqueChanges(base, turned);
    r.lightChangesReference = referenceChanges(base, turned);
    r.lightGain = AccuracyMetrics::perturbationGain(r.lightChangesTechnique, r.lightChangesReference);
    mHarness.setLight(size_t(o.light), original);
    mHarness.prepare(technique);

    // Flicker: a drift of kDriftSteps half-pixel steps, changes summed over consecutive frames.
    uint64_t tech = 0, ref = 0;
    Sample prev = base;
    for (int k = 1; k <= kDriftSteps; ++k) {
        mHarness.setPixelShift({0.5f * float(k), 0.25f * float(k)});
        Sample next = judgeFrame(technique, o, nullptr);
        tech += techniqueChanges(prev, next);
        ref += referenceChanges(prev, next);
        prev = std::move(next);
    }
    mHarness.setPixelShift({0.0f, 0.0f});
    r.flicker = AccuracyMetrics::perturbationGain(tech, ref);
    r.stabilityMeasured = true;
}

AccuracyResult AccuracyEvaluator::evaluate(Technique& technique, const AccuracyOptions& o) {
    AccuracyResult r = start(o);
    mHarness.seekPath(0); // a scene in motion: the first frame of the path (nothing for a static one)
    GBuffer g;
    const Sample base = judgeFrame(technique, o, &r.reference, &g);
    score(base, o, r);
    keepJudged(base);
    // Before the perturbations below re-fit the technique's maps: the judged frame's.
    if (const MapTexels* maps = technique.mapTexels()) r.texels = texelDensity(*maps, o, base, g);
    if (mHarness.moving())
        measurePath(technique, o, r); // perturbing one frame of a moving scene would measure its motion
    else if (o.stability)
        measureStability(technique, o, base, r);
    return r;
}

AccuracyResult AccuracyEvaluator::evaluateVisibility(std::vector<float> visibilityRgba,
                                                     const AccuracyOptions& o) {
    AccuracyResult r = start(o);
    const Sample judged = judgeVisibility(std::move(visibilityRgba), o, &r.reference);
    score(judged, o, r);
    keepJudged(judged);
    return r;
}

void AccuracyEvaluator::keepJudged(const Sample& sample) {
    // A copy, not the read-back: three values per pixel instead of seven.
    Sample kept;
    kept.technique = sample.technique;
    kept.reference = sample.reference;
    kept.mask = sample.mask;
    mLastJudged = std::move(kept);
}

AccuracyResult AccuracyEvaluator::start(const AccuracyOptions& o) const {
    const Scene& scene = mHarness.scene();
    if (o.light < 0 || size_t(o.light) >= scene.lights.size())
        throw Error("accuracy: light " + std::to_string(o.light) + " does not exist (scene '" + scene.name +
                    "' has " + std::to_string(scene.lights.size()) + ")");
    AccuracyResult r;
    r.light = o.light;
    r.softReference = scene.lights[size_t(o.light)].isArea();
    return r;
}

void AccuracyEvaluator::score(const Sample& base, const AccuracyOptions& o, AccuracyResult& r) const {
    const Scene& scene = mHarness.scene();
    uint64_t evaluated = std::count(base.mask.begin(), base.mask.end(), uint8_t(1));
    if (evaluated == 0)
        throw Error("accuracy: no pixel of scene '" + scene.name + "' shows geometry facing light " +
                        std::to_string(o.light) + " (n.L > " + csvNumber(o.nDotLThreshold) +
                        ") from camera '" + mHarness.config().camera + "': nothing to judge",
                    ExitCode::BadInput);
    r.sanity = AccuracyMetrics::sanity(base.techniqueRgba);
    r.hard = AccuracyMetrics::hard(base.technique, base.reference, base.mask, mHarness.config().width,
                                   mHarness.config().height);
    r.soft = AccuracyMetrics::soft(base.technique, base.reference, base.mask);
}

void AccuracyEvaluator::measurePath(Technique& technique, const AccuracyOptions& o, AccuracyResult& r) {
    const Motion& motion = *mHarness.scene().motion;
    const int w = mHarness.config().width, h = mHarness.config().height;
    AccuracyResult::Path path;
    path.points = kPathSamples;
    for (int k = 0; k < kPathSamples; ++k) {
        mHarness.seekPath(uint64_t(k) * motion.frames / kPathSamples);
        const Sample at = judgeFrame(technique, o, nullptr);
        const Sample next = judgeFrame(technique, o, nullptr); // the frame after it on the path
        const double wrong = AccuracyMetrics::hard(at.technique, at.reference, at.mask, w, h).wrongPct;
        path.wrongMeanPct += wrong / kPathSamples;
        path.wrongMaxPct = std::max(path.wrongMaxPct, wrong);
        std::vector<uint8_t> both(at.mask.size());
        for (size_t i = 0; i < both.size(); ++i) both[i] = at.mask[i] && next.mask[i];
        for (size_t i = 0; i < both.size(); ++i) {
            if (!both[i]) continue;
            const bool techniqueFlips = (at.technique[i] < 0.5f) != (next.technique[i] < 0.5f);
            const bool referenceFlips = (at.reference[i] < 0.5f) != (next.reference[i] < 0.5f);
            path.changesTechnique += techniqueFlips;
            path.changesReference += referenceFlips;
            path.falseChanges += techniqueFlips && !referenceFlips;
        }
    }
    path.flicker = AccuracyMetrics::perturbationGain(path.falseChanges, path.changesReference);
    r.path = path;
    mHarness.seekPath(0);
}

void AccuracyResult::appendColumns(CsvRow& row) const {
    auto add = [&](const char* name, double v) { row.emplace_back(name, csvNumber(v)); };
    row.emplace_back(col::kAccLight, std::to_string(light));
    row.emplace_back(col::kAccReference, softReference ? "soft" : "hard");
    add(col::kAccEvaluated, double(hard.evaluated));
    add(col::kAccFalseShadowPct, hard.falseShadowPct);
    add(col::kAccFalseLightPct, hard.falseLightPct);
    add(col::kAccWrongPct, hard.wrongPct);
    add(col::kAccFalseShadowNoEdgePct, hard.falseShadowNoEdgePct);
    add(col::kAccFalseLightNoEdgePct, hard.falseLightNoEdgePct);
    add(col::kAccWrongNoEdgePct, hard.wrongNoEdgePct);
    add(col::kAccRmse, soft.rmse);
    add(col::kAccMeanAbs, soft.meanAbs);
    add(col::kAccMaxAbs, soft.maxAbs);
    add(col::kAccNan, double(sanity.nan));
    add(col::kAccInf, double(sanity.inf));
    add(col::kAccOutOfRange, double(sanity.outOfRange));
    row.emplace_back(col::kAccGainCamera, stabilityMeasured ? csvNumber(cameraGain) : "");
    row.emplace_back(col::kAccGainLight, stabilityMeasured ? csvNumber(lightGain) : "");
    row.emplace_back(col::kAccFlicker, stabilityMeasured ? csvNumber(flicker) : "");
    row.emplace_back(col::kAccPathPoints, path ? std::to_string(path->points) : "");
    row.emplace_back(col::kAccPathWrongMeanPct, path ? csvNumber(path->wrongMeanPct) : "");
    row.emplace_back(col::kAccPathWrongMaxPct, path ? csvNumber(path->wrongMaxPct) : "");
    row.emplace_back(col::kAccPathChangesTechnique, path ? std::to_string(path->changesTechnique) : "");
    row.emplace_back(col::kAccPathChangesReference, path ? std::to_string(path->changesReference) : "");
    row.emplace_back(col::kAccPathFalseChanges, path ? std::to_string(path->falseChanges) : "");
    row.emplace_back(col::kAccPathFlicker, path ? csvNumber(path->flicker) : "");
    const bool mapped = texels.samples != 0;
    row.emplace_back(col::kAccTexelsPerPixelP50, mapped ? csvNumber(texels.p50) : "");
    row.emplace_back(col::kAccTexelsPerPixelP5, mapped ? csvNumber(texels.p5) : "");
    row.emplace_back(col::kAccTexelsPerPixelMin, mapped ? csvNumber(texels.min) : "");
    add(col::kRefSamples, reference.samplesPerPixel);
    add(col::kRefNoiseBound, reference.noiseBound);
    add(col::kRefRays, double(reference.rays));
    add(col::kRefRaysPerSPerThread, reference.raysPerSecondPerThread);
    add(col::kRefThreads, reference.threads);
}

} // namespace sb
