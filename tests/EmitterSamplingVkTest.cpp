// shaders/raytraced/emitter.glsl on lavapipe against the Embree reference's reference/LightSampler on the
// CPU, with no ray query involved (the system driver's lavapipe runs it): a compute fixture
// (tests/shaders/vk/emitter_sampling.comp) evaluates the shader's emitter samples for origins x u values x
// light shapes and draws its stratified sequence; the test reads them back and checks
//   - each sample against LightSampler::sample: direction, distance, validity;
//   - the delta rule against LightSampler::isDelta;
//   - the sequence against its documentation (emitter.glsl's header), one point per stratum;
//   - that the strata are equal-measure pieces of each emitter: the mean of a smooth function over 64
//     stratified samples, over many pixels, against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "VkComputeKernel.h"
#include "VkTestSupport.h"
#include "reference/LightSampler.h"
#include "techniques/raytraced/LightEmitter.h"
#include "vk/VulkanBuffer.h"

namespace sb {
namespace {

using test::VulkanTest;

/// emitter_sampling.comp's buffers (std430).
struct GpuCase {
    glm::vec4 originLight; ///< xyz origin, w light index
    glm::vec2 u{0.0f};
    glm::uvec2 pixel{0u};
};
struct GpuResult {
    glm::vec4 directionDistance;
    glm::vec4 uValid;
};
struct Push {
    uint32_t mode = 0, count = 0;
    int32_t side = 1;
    uint32_t frame = 0;
};
static_assert(sizeof(GpuCase) == 32 && sizeof(GpuResult) == 32 && sizeof(Push) == 16);

constexpr uint32_t kLocalSize = 64; ///< emitter_sampling.comp's local_size_x

/// The fixture compiled for one scene's lights (at most 4: the shader's SB_EMITTERS array), with the
/// lights' positions and directions in a buffer as the frame block holds them (direction normalised).
class EmitterKernel {
public:
    EmitterKernel(VulkanContext& context, const Scene& scene)
        : mContext(context), mKernel(context, "tests/shaders/vk/emitter_sampling.comp", defines(scene), 3,
                                     sizeof(Push), "emitter test"),
          mLights(context, 8 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
        auto* lights = static_cast<glm::vec4*>(mLights.map());
        for (size_t i = 0; i < 4; ++i) {
            const Light l = i < scene.lights.size() ? scene.lights[i] : Light{};
            lights[i] = glm::vec4(l.position, 0.0f);
            lights[4 + i] = glm::vec4(glm::normalize(l.direction), 0.0f);
        }
    }

    /// Mode 0: one sample per case at the case's u.
    std::vector<GpuResult> sample(const std::vector<GpuCase>& cases) { return run(cases, 0, 1, 0); }
    /// Mode 1: the side^2 stratified samples of each case's pixel in frame `frame`, case-major.
    std::vector<GpuResult> stratified(const std::vector<GpuCase>& cases, int side, uint32_t frame) {
        return run(cases, 1, side, frame);
    }

private:
    static Defines defines(const Scene& scene) {
        Defines d;
        addEmitterDefines(scene, d);
        return d;
    }
    std::vector<GpuResult> run(const std::vector<GpuCase>& cases, uint32_t mode, int side, uint32_t frame) {
        const size_t results = cases.size() * (mode == 0 ? 1 : size_t(side * side));
        VulkanBuffer in(mContext, cases.size() * sizeof(GpuCase), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        VulkanBuffer out(mContext, results * sizeof(GpuResult), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::copy(cases.begin(), cases.end(), static_cast<GpuCase*>(in.map()));
        const Push push{mode, uint32_t(cases.size()), side, frame};
        mKernel.dispatch({&in, &mLights, &out}, &push,
                         (uint32_t(cases.size()) + kLocalSize - 1) / kLocalSize);
        const auto* data = static_cast<const GpuResult*>(out.map());
        return std::vector<GpuResult>(data, data + results);
    }

    VulkanContext& mContext;
    test::ComputeKernel mKernel; ///< emitter_sampling.comp, from the source tree's root
    VulkanBuffer mLights;
};

Light areaLight(LightType type, LightShape shape, glm::vec3 position, glm::vec3 direction, glm::vec2 size,
                float angularRadiusDeg = 0.0f) {
    Light l;
    l.type = type;
    l.shape = shape;
    l.position = position;
    l.direction = glm::normalize(direction);
    l.size = size;
    l.angularRadiusDeg = angularRadiusDeg;
    return l;
}

Scene sceneOf(std::vector<Light> lights) {
    Scene s;
    s.lights = std::move(lights);
    return s;
}

/// Every shape LightSampler maps, both branches of the frame's up vector (|w.y| < 0.99 and not), a sphere
/// seen from outside and from inside, and the two kinds of delta light; four lights a compile.
std::vector<Scene> samplingScenes() {
    const auto spot = LightType::Spot, point = LightType::Point, sun = LightType::Directional;
    return {
        sceneOf(
            {areaLight(spot, LightShape::Rect, {0.3f, 4.0f, -0.2f}, {0.2f, -1.0f, 0.1f}, {1.5f, 0.75f}),
             areaLight(point, LightShape::Disk, {1.0f, 3.0f, 2.0f}, {-0.3f, -1.0f, 0.2f}, {0.6f, 0.0f}),
             areaLight(point, LightShape::Sphere, {1.0f, 3.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, {0.5f, 0.0f}),
             areaLight(point, LightShape::Sphere, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {2.0f, 0.0f})}),
        sceneOf({areaLight(sun, LightShape::Disk, {}, {0.3f, -1.0f, 0.2f}, {}, 2.0f),
                 areaLight(sun, LightShape::Disk, {}, {0.05f, -1.0f, 0.02f}, {}, 10.0f),
                 areaLight(spot, LightShape::Rect, {0.0f, 4.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {2.0f, 1.0f}),
                 areaLight(point, LightShape::Point, {2.0f, 5.0f, 1.0f}, {0.0f, -1.0f, 0.0f}, {})}),
        sceneOf({areaLight(sun, LightShape::Point, {}, {0.1f, -1.0f, 0.3f}, {})}),
    };
}

/// Ray origins none of which lies within 0.25 of an emitter's plane (validity is a sign test there, and a
/// point on the plane would be decided by rounding): below the lights, above them (behind the one-sided
/// emitters) and inside the large sphere.
const std::vector<glm::vec3> kOrigins = {
    {0.0f, 0.0f, 0.0f}, {1.5f, 0.2f, -2.0f},  {-3.0f, 0.0f, 1.0f},  {0.5f, -1.0f, 0.7f},
    {4.0f, 2.0f, 3.0f}, {-2.0f, 2.5f, -1.0f}, {0.2f, 6.5f, 0.1f},   {3.0f, 8.0f, -2.0f},
    {0.0f, 1.2f, 0.3f}, {0.5f, 0.5f, -0.5f},  {10.0f, 1.0f, 10.0f}, {-6.0f, 0.5f, 4.0f},
};

/// u on a 5x5 grid inside [0.05, 0.95]^2, the centre (the concentric map's origin) included. Kept off the
/// square's edge: at u.x -> 1 a sphere sample grazes the sphere, where its distance d cos(theta) -
/// sqrt(r^2 - d^2 sin^2(theta)) is ill-conditioned (the root of a difference of nearly equal terms) and
/// one float rounding more or less (a fused multiply-add) moves it by far more than 1e-5.
const float kU[] = {0.05f, 0.27f, 0.5f, 0.73f, 0.95f};

/// Direction: 1e-5 in length of the difference, about 100 float ulps of a unit vector: the maps are the
/// same operations, but lavapipe's sin, cos, sqrt and division are its own (and it may fuse a multiply
/// and an add), each within a few ulps. Distance: 1e-5 relative, for the same reason.
constexpr float kDirectionTolerance = 1e-5f;
constexpr float kDistanceTolerance = 1e-5f;

class EmitterSamplingVkTest : public VulkanTest {};

TEST_F(EmitterSamplingVkTest, SamplesMatchLightSampler) {
    size_t compared = 0, valid = 0, invalid = 0;
    for (const Scene& scene : samplingScenes()) {
        EmitterKernel kernel(context(), scene);
        std::vector<GpuCase> cases;
        for (size_t light = 0; light < scene.lights.size(); ++light)
            for (const glm::vec3& o : kOrigins)
                for (float ux : kU)
                    for (float uy : kU) cases.push_back({glm::vec4(o, float(light)), {ux, uy}, {}});
        const std::vector<GpuResult> gpu = kernel.sample(cases);
        ASSERT_EQ(gpu.size(), cases.size());
        for (size_t i = 0; i < cases.size(); ++i) {
            const Light& light = scene.lights[size_t(cases[i].originLight.w)];
            const glm::vec3 origin(cases[i].originLight);
            const LightSampler::Sample cpu = LightSampler(light).sample(origin, cases[i].u);
            const glm::vec3 direction(gpu[i].directionDistance);
            const float distance = gpu[i].directionDistance.w;
            const std::string where = std::string(lightShapeName(light.shape)) + " " +
                                      lightTypeName(light.type) + " light, origin (" +
                                      std::to_string(origin.x) + "," + std::to_string(origin.y) + "," +
                                      std::to_string(origin.z) + "), u (" + std::to_string(cases[i].u.x) +
                                      "," + std::to_string(cases[i].u.y) + ")";
            ASSERT_EQ(gpu[i].uValid.z == 1.0f, cpu.valid) << where;
            ASSERT_LE(glm::length(direction - cpu.direction), kDirectionTolerance) << where;
            if (std::isinf(cpu.distance))
                ASSERT_TRUE(std::isinf(distance) && distance > 0.0f) << where << ": " << distance;
            else
                ASSERT_LE(std::abs(distance - cpu.distance), kDistanceTolerance * cpu.distance)
                    << where << ": " << distance << " vs " << cpu.distance;
            ++compared;
            cpu.valid ? ++valid : ++invalid;
        }
    }
    // The table reaches both validity outcomes (one-sided emitters seen from behind), so the check of
    // validity can fail both ways.
    EXPECT_EQ(compared, size_t(9 * kOrigins.size() * 25));
    EXPECT_GT(valid, compared / 2);
    EXPECT_GT(invalid, size_t(0));
}

TEST(EmitterSamplingTest, DeltaExactlyWhereLightSamplerIsDelta) {
    const auto spot = LightType::Spot, point = LightType::Point, sun = LightType::Directional;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<Light> lights = {
        areaLight(point, LightShape::Point, {}, {0, -1, 0}, {1.0f, 1.0f}),
        areaLight(spot, LightShape::Rect, {}, {0, -1, 0}, {1.0f, 0.0f}),
        areaLight(spot, LightShape::Rect, {}, {0, -1, 0}, {0.0f, 1.0f}),
        areaLight(spot, LightShape::Rect, {}, {0, -1, 0}, {1.0f, 0.5f}),
        areaLight(point, LightShape::Disk, {}, {0, -1, 0}, {0.0f, 0.0f}),
        areaLight(point, LightShape::Disk, {}, {0, -1, 0}, {nan, 0.0f}),
        areaLight(point, LightShape::Disk, {}, {0, -1, 0}, {0.5f, 0.0f}),
        areaLight(point, LightShape::Sphere, {}, {0, -1, 0}, {0.0f, 0.0f}),
        areaLight(point, LightShape::Sphere, {}, {0, -1, 0}, {0.5f, 0.0f}),
        areaLight(sun, LightShape::Disk, {}, {0, -1, 0}, {}, 0.0f),
        areaLight(sun, LightShape::Disk, {}, {0, -1, 0}, {}, 0.5f),
        areaLight(sun, LightShape::Point, {}, {0, -1, 0}, {}, 3.0f),
    };
    const EmitterKind expected[] = {EmitterKind::Point,     EmitterKind::Point, EmitterKind::Point,
                                    EmitterKind::Rect,      EmitterKind::Point, EmitterKind::Point,
                                    EmitterKind::Disk,      EmitterKind::Point, EmitterKind::Sphere,
                                    EmitterKind::Direction, EmitterKind::Cone,  EmitterKind::Direction};
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightEmitter e = LightEmitter::of(lights[i]);
        EXPECT_EQ(e.delta(), LightSampler(lights[i]).isDelta()) << "light " << i;
        EXPECT_EQ(e.kind, expected[i]) << "light " << i;
        EXPECT_EQ(e.constant.x, float(int(expected[i]))) << "light " << i;
    }
}

/// The PCG hash as Jarzynski and Olano's "Hash Functions for GPU Rendering" (JCGT 2020) defines it, and
/// the stream emitter.glsl's header documents, written here from that documentation.
uint32_t pcgHash(uint32_t v) {
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

glm::vec2 documentedStratum(int k, int side, uint32_t& state) {
    auto uniform = [&] {
        state = pcgHash(state);
        return float(state >> 8u) * 0x1.0p-24f;
    };
    const float inv = 1.0f / float(side);
    const float jx = uniform(), jy = uniform();
    return glm::vec2(std::min((float(k % side) + jx) * inv, 0x1.fffffep-1f),
                     std::min((float(k / side) + jy) * inv, 0x1.fffffep-1f));
}

/// Cases of `light` from `origin`, one per pixel of a width x width block.
std::vector<GpuCase> pixelCases(int light, const glm::vec3& origin, uint32_t width) {
    std::vector<GpuCase> cases;
    for (uint32_t y = 0; y < width; ++y)
        for (uint32_t x = 0; x < width; ++x) cases.push_back({glm::vec4(origin, float(light)), {}, {x, y}});
    return cases;
}

TEST_F(EmitterSamplingVkTest, SequenceIsTheDocumentedOneOnePointPerStratum) {
    const Scene scene = samplingScenes()[0];
    EmitterKernel kernel(context(), scene);
    // side 7 (not a power of two: 1/side rounds) and 8; frames 0 and a later one.
    for (const int side : {7, 8}) {
        for (const uint32_t frame : {0u, 41u}) {
            const std::vector<GpuCase> cases = pixelCases(0, glm::vec3(0.0f), 6);
            const std::vector<GpuResult> gpu = kernel.stratified(cases, side, frame);
            const int n = side * side;
            for (size_t c = 0; c < cases.size(); ++c) {
                uint32_t state = pcgHash(cases[c].pixel.x ^ pcgHash(cases[c].pixel.y ^ pcgHash(frame)));
                for (int k = 0; k < n; ++k) {
                    const glm::vec2 u(gpu[c * size_t(n) + size_t(k)].uValid);
                    const glm::vec2 documented = documentedStratum(k, side, state);
                    // The same integer stream and float operations (a correctly rounded division on both
                    // sides): equal.
                    ASSERT_EQ(u.x, documented.x) << "pixel " << c << " stratum " << k << " side " << side;
                    ASSERT_EQ(u.y, documented.y) << "pixel " << c << " stratum " << k << " side " << side;
                    // In [0,1) and in its own stratum (k % side, k / side): one point per stratum.
                    ASSERT_TRUE(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f);
                    ASSERT_EQ(int(u.x * float(side)), k % side) << "stratum " << k;
                    ASSERT_EQ(int(u.y * float(side)), k / side) << "stratum " << k;
                }
            }
        }
    }
}

/// One equal-measure check: the mean over `pixels`^2 pixels of the per-pixel mean of f over 64 stratified
/// samples of `light`, against f's closed-form mean over the emitter. `lipschitz` bounds |grad f| over the
/// unit square (u space). Why the tolerance holds: within a stratum of side h = 1/8 f varies by at most
/// L h sqrt(2), so its variance is at most (L h sqrt(2))^2 / 4; the per-pixel mean of N = 64 independent
/// strata then has variance <= L^2 / (2 N^2), and the mean of P pixels (independent streams) <= L^2 / (2
/// N^2 P). With P = 1024: a standard deviation <= L / 2896; five of them, 1.73e-3 L, is the tolerance. A
/// map that is not equal-measure is off by far more: a polar instead of the concentric disk gives R^2/3
/// instead of R^2/2, 33%; a rect stratum counted twice moves the mean by up to 1/64 of f's range.
struct MeasureCase {
    const char* name;
    int light;
    glm::vec3 origin;
    double expected;
    double lipschitz;
    double (*f)(const Light& light, const glm::vec3& origin, const glm::vec3& direction, float distance);
};

TEST_F(EmitterSamplingVkTest, StrataAreEqualMeasure) {
    constexpr int kSide = 8;
    constexpr uint32_t kPixels = 32;
    const std::vector<Scene> scenes = samplingScenes();
    const Light& rect = scenes[0].lights[0];
    const Light& disk = scenes[0].lights[1];
    const Light& sphere = scenes[0].lights[2];
    const Light& sun = scenes[1].lights[1];
    // Squared distance of the sampled point from the emitter's centre (rect, disk).
    auto centreDistance2 = [](const Light& l, const glm::vec3& o, const glm::vec3& d, float t) {
        const glm::dvec3 p = glm::dvec3(o) + glm::dvec3(d) * double(t) - glm::dvec3(l.position);
        return glm::dot(p, p);
    };
    const glm::vec3 below(0.0f);
    const glm::dvec3 toSphere = glm::dvec3(sphere.position) - glm::dvec3(below);
    const double sinAlpha = double(sphere.size.x) / glm::length(toSphere);
    const double cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
    const double cosSun = std::cos(glm::radians(double(sun.angularRadiusDeg)));
    const double w2 = double(rect.size.x) * rect.size.x, h2 = double(rect.size.y) * rect.size.y;
    const double r2 = double(disk.size.x) * disk.size.x;
    const MeasureCase cases[] = {
        // |p - c|^2 = w^2 (u.x - 1/2)^2 + h^2 (u.y - 1/2)^2: mean (w^2 + h^2) / 12, |grad| <= sqrt(w^4 +
        // h^4).
        {"rect", 0, below, (w2 + h2) / 12.0, std::sqrt(w2 * w2 + h2 * h2), centreDistance2},
        // R^2 max(|s.x|, |s.y|)^2 with s = 2u - 1: mean R^2 / 2, |grad| <= 4 R^2.
        {"disk", 1, below, r2 / 2.0, 4.0 * r2, centreDistance2},
        // cos(theta) to the sphere's centre, uniform in solid angle over the cap: mean (1 + cos(alpha)) / 2;
        // cos(theta) = 1 - u.x (1 - cos(alpha)), |grad| = 1 - cos(alpha).
        {"sphere", 2, below, (1.0 + cosAlpha) / 2.0, 1.0 - cosAlpha,
         [](const Light& l, const glm::vec3& o, const glm::vec3& d, float) {
             return glm::dot(glm::dvec3(d), glm::normalize(glm::dvec3(l.position) - glm::dvec3(o)));
         }},
        // cos(theta) to -w within the sun's cone: mean (1 + cos(max)) / 2, |grad| = 1 - cos(max).
        {"sun", 1, below, (1.0 + cosSun) / 2.0, 1.0 - cosSun,
         [](const Light& l, const glm::vec3&, const glm::vec3& d, float) {
             return glm::dot(glm::dvec3(d), -glm::normalize(glm::dvec3(l.direction)));
         }},
    };
    EmitterKernel first(context(), scenes[0]), second(context(), scenes[1]);
    for (const MeasureCase& m : cases) {
        const bool isSun = std::string(m.name) == "sun";
        const Light& light = isSun ? sun : scenes[0].lights[size_t(m.light)];
        const std::vector<GpuResult> gpu =
            (isSun ? second : first).stratified(pixelCases(m.light, m.origin, kPixels), kSide, 0);
        double sum = 0.0;
        for (const GpuResult& r : gpu) {
            ASSERT_EQ(r.uValid.z, 1.0f) << m.name << ": every sample of an emitter seen from below is valid";
            sum += m.f(light, m.origin, glm::vec3(r.directionDistance), r.directionDistance.w);
        }
        const double mean = sum / double(gpu.size());
        const double tolerance = 5.0 * m.lipschitz / (kSide * kSide * std::sqrt(2.0 * kPixels * kPixels));
        EXPECT_NEAR(mean, m.expected, tolerance) << m.name;
    }
}

} // namespace
} // namespace sb
