// The same technique, scene, camera and properties rendered by GL (llvmpipe) and by Vulkan (lavapipe):
// the colour and visibility images compared pixel for pixel. Both drivers run the same gallivm
// rasteriser and the same GLSL (one source, `#ifdef VULKAN` for layout only), the Vulkan frame block
// converts GL's clip space exactly (a y flip and z to [0, w]: multiplications by 1, -1 and 0.5), and the
// maps use the same 24-bit depth, so the images agree up to rounding: the tolerance is one 8-bit step
// of colour and one step of the half-float visibility target at 1 (2^-10) on at most 0.5% of the
// pixels. Measured on this machine (160 x 160): 0-2 pixels differ in colour by one step, 0-34 in
// visibility by at most 2^-10 (the filtered comparisons' last bit: the two compilers, GLSL IR and
// SPIR-V, round the bilinear weights and the kernel sums differently); a caster or a filter tap on
// the other side would move a value by 1/64 at least. Every Vulkan frame runs with the validation
// layer on and must leave no validation error.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

struct Case {
    const char* name;
    const char* scene;
    const char* camera;
    const char* technique; ///< a spec: "shadowmap:pcf=3"
    SubmitMode submit = SubmitMode::Retained;
    const char* light = ""; ///< --light: replaces every light's type
    /// Pixels whose visibility may differ by more than rounding, as a fraction: 0 but for volumes, whose
    /// sides reach infinity (w = 0) and are clipped by the near plane in each driver's own arithmetic:
    /// a triangle edge through a pixel centre can land on either side. Measured at 256^2 on the
    /// aircraft: 1-4 isolated one-pixel specks (0.006%), every one a GL speck Vulkan does not have.
    double flipFraction = 0.0;
    /// Pixels whose colour may differ by one 8-bit step, as a fraction. 0.5% but for volumes with two
    /// lights: two additive light passes, each blended into the 8-bit target, and the two drivers'
    /// blends round the last bit of the sum differently on about 1.7% of the pixels (measured 430 of
    /// 25,600 on the exceptions scene), never by more than one step.
    double colourFraction = 0.005;
    /// Pixels whose visibility may differ by rounding (at most one half-float step), as a fraction: 0.5%
    /// but for msm, whose umbra is not 0 but the moment bias's remainder (about 2e-5, where the half-float
    /// target's steps are 6e-8): the two compilers' last bits show on every umbra pixel of a large
    /// shadow (measured 527 of 25,600 under the spot light, none by more than 1.5e-6 in the umbra).
    double roundingFraction = 0.005;
};
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

const Case kCases[] = {
    {"none_aircraft", "aircraft", "far", "none"},
    {"none_instanced", "aircraft", "mid", "none", SubmitMode::Instanced},
    {"shadowmap_aircraft", "aircraft", "far", "shadowmap"},
    {"shadowmap_instanced", "aircraft", "near", "shadowmap", SubmitMode::Instanced},
    {"shadowmap_spot", "sphere_plane", "far", "shadowmap:resolution=1024", SubmitMode::Retained, "spot"},
    {"shadowmap_shader_compare_pcf3", "aircraft", "mid", "shadowmap:hardware_compare=false:pcf=3"},
    {"shadowmap_poisson_normal_offset", "aircraft", "mid", "shadowmap:kernel=poisson:normal_offset=2"},
    {"shadowmap_rotated_grid_receiver_plane", "aircraft", "mid",
     "shadowmap:kernel=rotated_grid:receiver_plane=true"},
    {"shadowmap_no_cull", "aircraft", "near", "shadowmap:cull=false"},
    {"shadowmap_exceptions", "exceptions", "far", "shadowmap"},
    {"cubemap_point_layered", "point_light", "far", "cubemap"},
    {"cubemap_point_six_pass", "point_light", "far", "cubemap:layered=false"},
    {"cubemap_point_instanced_pcf3", "point_light", "near", "cubemap:pcf=3", SubmitMode::Instanced},
    {"cubemap_spot_flat", "aircraft", "far", "cubemap", SubmitMode::Retained, "spot"},
    {"cubemap_directional_flat", "aircraft", "mid", "cubemap:pcf=3"},
    {"paraboloid_point_split", "point_light", "far", "paraboloid"},
    {"paraboloid_point_per_vertex_instanced", "point_light", "near", "paraboloid:split=false:pcf=3",
     SubmitMode::Instanced},
    {"paraboloid_room", "room", "wall", "paraboloid"},
    {"paraboloid_jack_o_lantern", "jack_o_lantern", "mid", "paraboloid"},
    {"paraboloid_spot_flat", "aircraft", "far", "paraboloid", SubmitMode::Retained, "spot"},
    {"cascaded_aircraft", "aircraft", "far", "cascaded"},
    // cascaded's lighting pass computes each cascade's map coordinate per fragment from the interpolated
    // world position, whose last bits differ between the two drivers; a near cascade magnifies its texels
    // many times, so on a few pixels of a shadow's edge the bilinear compare filter lands on the other
    // side of a weight step: visibility 0.001 to 0.01 apart, never a whole tap (measured: 1 pixel of
    // 25,600 in each; from teapot's near camera 55 to 94, so that scene is checked from afar).
    {"cascaded_city_tight_no_blend", "city", "mid", "cascaded:stabilize=false:blend=0", SubmitMode::Retained,
     "", 0.0002},
    {"cascaded_teapot_instanced_uniform_pcf3", "teapot", "far", "cascaded:cascades=3:lambda=0:pcf=3",
     SubmitMode::Instanced, "", 0.0002},
    {"cascaded_spot", "sphere_plane", "far", "cascaded", SubmitMode::Retained, "spot"},
    // fit=sdsm: both APIs' pre-pass and reduction find the same interval (tests/CascadedSdsmVkTest.cpp), so
    // the same cascades: the tolerance of cascaded's other cases.
    {"cascaded_sdsm_city", "city", "mid", "cascaded:fit=sdsm", SubmitMode::Retained, "", 0.0002},
    {"cascaded_exceptions", "exceptions", "far", "cascaded:cascades=2"},
    // pcss: a blocker-search tap that the two compilers round to either side of the receiver's depth
    // changes the pixel's penumbra width and so every filter tap: measured 0-6 pixels of 25,600 whose
    // visibility moves by more than rounding (4-6 on teapot), 0.05%.
    {"pcss_aircraft", "aircraft", "far", "pcss", SubmitMode::Retained, "", 0.0005},
    {"pcss_instanced_light_size", "aircraft", "mid", "pcss:light_size=0.05", SubmitMode::Instanced, "",
     0.0005},
    {"pcss_spot", "sphere_plane", "far", "pcss:resolution=1024", SubmitMode::Retained, "spot", 0.0005},
    {"pcss_teapot", "teapot", "far", "pcss", SubmitMode::Retained, "", 0.0005},
    {"pcss_exceptions", "exceptions", "far", "pcss", SubmitMode::Retained, "", 0.0005},
    // vsm: Chebyshev's bound divides by the variance M2 - M1^2, a difference of two nearly equal sums
    // (the blur's and the bilinear filter's, rounded differently by the two compilers), so where the
    // filtered variance is near min_variance the last bits of the moments move the bound by more than
    // rounding: measured 0-12 pixels of 25,600 (12 on teapot without the receiver background), 0.05%.
    {"vsm_aircraft", "aircraft", "far", "vsm", SubmitMode::Retained, "", 0.0005},
    {"vsm_instanced_blur5", "aircraft", "mid", "vsm:blur=5", SubmitMode::Instanced, "", 0.0005},
    {"vsm_spot", "sphere_plane", "far", "vsm:resolution=512", SubmitMode::Retained, "spot", 0.0005},
    {"vsm_teapot_no_background", "teapot", "far", "vsm:receiver_background=false", SubmitMode::Retained, "",
     0.0005},
    {"vsm_exceptions", "exceptions", "far", "vsm", SubmitMode::Retained, "", 0.0005},
    {"esm_aircraft", "aircraft", "far", "esm"},
    {"esm_instanced_no_blur", "aircraft", "mid", "esm:blur=0", SubmitMode::Instanced},
    {"esm_spot", "sphere_plane", "far", "esm:resolution=512:exponent=80", SubmitMode::Retained, "spot"},
    {"esm_teapot", "teapot", "far", "esm"},
    {"esm_exceptions", "exceptions", "far", "esm"},
    // evsm and msm: vsm's bound (per warp) and the Hamburger reconstruction divide by differences of nearly
    // equal filtered sums too; measured 13 and 5 pixels (evsm), 57 (msm, aircraft) differing by rounding.
    // msm under the spot light: 19 pixels of 25,600 (0.074%, unorm16; 4 with the float map) on one arc of
    // the sphere's penumbra differ by up to 0.022, where the filter region holds the sphere's and the
    // ground's nearly equal depths and the Hamburger solve's 3x3 Hankel matrix is nearly singular: the
    // receiver's interpolated distance to the light, rounded differently by the two compilers (making
    // the solve `precise` changes none of them), moves the reconstruction there. Bounded at 0.1%.
    {"evsm_aircraft", "aircraft", "far", "evsm", SubmitMode::Retained, "", 0.0005},
    {"evsm_spot_components2", "sphere_plane", "far", "evsm:resolution=512:components=2", SubmitMode::Retained,
     "spot", 0.0005},
    {"msm_aircraft", "aircraft", "far", "msm", SubmitMode::Retained, "", 0.0005},
    {"msm_spot", "sphere_plane", "far", "msm:resolution=512", SubmitMode::Retained, "spot", 0.001, 0.005,
     0.03},
    // virtual: the level a pixel reads is the floor of a log2 of screen derivatives on both APIs (the same
    // GLSL), the page counts are the CPU's from the same marks (VirtualVkTest). A pixel whose level or
    // nearest tap sits on a boundary within the two compilers' rounding changes sides: measured 1 of
    // 25,600 on the teapot with pcf 3, none on the other rows.
    {"virtual_aircraft", "aircraft", "far", "virtual"},
    {"virtual_teapot_instanced_pcf3", "teapot", "far", "virtual:pcf=3", SubmitMode::Instanced, "", 0.0002},
    {"virtual_exceptions", "exceptions", "far", "virtual"},
    {"virtual_spot", "sphere_plane", "far", "virtual", SubmitMode::Retained, "spot"},
    {"reference_aircraft", "aircraft", "far", "reference"},
    {"reference_point_light_instanced", "point_light", "far", "reference", SubmitMode::Instanced},
    {"reference_sphere_plane_spot", "sphere_plane", "far", "reference", SubmitMode::Retained, "spot"},
    {"volume_aircraft", "aircraft", "far", "volume", SubmitMode::Retained, "", 0.001},
    {"volume_vertex_instanced", "aircraft", "mid", "volume:extrusion=vertex", SubmitMode::Instanced, "",
     0.001},
    {"volume_depth_clamp_spot", "aircraft", "mid", "volume:far=depth_clamp", SubmitMode::Retained, "spot",
     0.001},
    {"volume_point_range", "point_light", "far", "volume", SubmitMode::Retained, "", 0.001},
    {"volume_zpass_finite", "aircraft", "near", "volume:mode=zpass:finite_volumes=true", SubmitMode::Retained,
     "point", 0.001},
    {"volume_exceptions", "exceptions", "far", "volume:far=depth_clamp", SubmitMode::Retained, "", 0.001,
     0.03},
    {"occluder_teapot", "teapot", "far", "occluder"},
    {"occluder_aircraft_per_instance", "aircraft", "mid", "occluder:light_space=per_instance"},
    {"occluder_aircraft_texture_matrix_instanced", "aircraft", "near", "occluder:light_space=texture_matrix",
     SubmitMode::Instanced},
    // receivers=all tests other instances' planes per fragment and stops at the plane's rectangle (uv in
    // [0, 1], a solid plane is full shadow inside): a fragment whose uv lands on the edge within the two
    // compilers' rounding changes sides. Measured 11 of 25,600 pixels (0.043%), isolated, on the edges.
    {"occluder_aircraft_receivers_all", "aircraft", "far", "occluder:receivers=all", SubmitMode::Retained, "",
     0.001},
    {"proxy_point_light", "point_light", "far", "proxy"},
    {"proxy_painting_machine", "painting_machine", "far", "proxy"},
    {"proxy_instanced_room", "room", "far", "proxy", SubmitMode::Instanced},
    {"proxy_primitives_no_grid", "primitives", "far", "proxy:grid=false"},
    {"proxy_jack_cells_8", "jack_o_lantern", "far", "proxy:cells=8:modulate=on:bleeding=on"},
    // hybrid: the tolerance of its parts (a volume part's specks).
    {"hybrid_volume_shadowmap_aircraft", "aircraft", "far", "hybrid:self=volume:cast=shadowmap",
     SubmitMode::Retained, "", 0.001},
    {"hybrid_cubemap_volume_point", "point_light", "far", "hybrid:self=cubemap:cast=volume",
     SubmitMode::Retained, "", 0.001},
    {"hybrid_none_shadowmap_instanced", "sphere_plane", "mid", "hybrid:self=none:cast=shadowmap",
     SubmitMode::Instanced},
    // synthetic draws the instances' flat colours unlit: the aircraft scene's 0.5 and 0.7 channels are
    // exact ties in 8 bits (127.5, 178.5), so the last bit of each driver's interpolation picks the
    // step on most covered pixels (measured 4,289 of 25,600, never more than one step).
    {"synthetic_scene_aircraft", "aircraft", "far", "synthetic", SubmitMode::Retained, "", 0.0, 0.2},
    {"synthetic_fill_sphere_plane", "sphere_plane", "mid",
     "synthetic:fragment_iterations=20:draw_scene=false"},
    {"synthetic_vertex_fill_teapot", "teapot", "far", "synthetic:vertex_iterations=10:fragment_iterations=5",
     SubmitMode::Instanced},
    {"planar_aircraft", "aircraft", "far", "planar"},
    {"planar_proxy_instanced", "aircraft", "mid", "planar:occluder=proxy", SubmitMode::Instanced},
    {"planar_no_stencil", "sphere_plane", "far", "planar:stencil=false"},
    {"planar_point_no_guards", "point_light", "far", "planar:guards=false"},
    {"planar_exceptions", "exceptions", "far", "planar"},
    {"blob_aircraft", "aircraft", "far", "blob"},
    {"blob_spot_instanced", "sphere_plane", "far", "blob:softness=0.25", SubmitMode::Instanced, "spot"},
    {"blob_point", "point_light", "far", "blob"},
    {"blob_exceptions", "exceptions", "far", "blob"},
    {"projective_aircraft", "aircraft", "far", "projective"},
    {"projective_spot_instanced", "sphere_plane", "far", "projective", SubmitMode::Instanced, "spot"},
    {"projective_point_no_cull_256", "point_light", "far", "projective:cull=false:resolution=256"},
    {"projective_exceptions", "exceptions", "far", "projective"},
    {"projective_blur4_exceptions", "exceptions", "far", "projective:blur=4"},
    // A third built-in scene for the techniques above that had two (the exceptions scene is the test's).
    {"none_sphere_plane", "sphere_plane", "far", "none"},
    {"none_teapot_instanced", "teapot", "far", "none", SubmitMode::Instanced},
    {"shadowmap_teapot", "teapot", "far", "shadowmap"},
    {"volume_teapot", "teapot", "far", "volume", SubmitMode::Retained, "", 0.001},
    {"cubemap_room", "room", "wall", "cubemap"},
    {"occluder_aircraft_day", "aircraft_day", "path", "occluder"},
};

struct Images {
    std::vector<unsigned char> colour;
    std::vector<float> visibility;
};

/// A scene with both shadow exceptions: a box that receives no shadow and a second light that casts
/// none (the permutation defines SB_NON_RECEIVERS and SB_SHADOWLESS_LIGHTS on both APIs).
std::string exceptionsScene() {
    static const std::string path = [] {
        const std::string p = test::freshTestDir("gl_vulkan_exceptions") + "/scene.json";
        test::writeFile(p, R"({"name": "exceptions",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.5, 0.5, 0.5]},
             {"name": "ball", "generator": "sphere", "radius": 0.7, "tessellation": 24},
             {"name": "floor", "generator": "plane", "size": 10, "tessellation": 4}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "color": [0.5, 0.5, 0.5], "casts_shadow": false},
                {"mesh": "box", "position": [1, 0.5, 0], "color": [0.6, 0.4, 0.3], "receives_shadow": false},
                {"mesh": "ball", "position": [0.5, 3, 0], "color": [0.3, 0.4, 0.6]}],
  "lights": [{"type": "directional", "direction": [0.5, -1, 0]},
             {"type": "directional", "direction": [-0.3, -1, 0.2], "casts_shadows": false}],
  "ambient": [0.2, 0.2, 0.2],
  "effects": ["hard_shadows", "self_shadowing", "non_planar_receivers", "multiple_lights"],
  "cameras": [{"name": "far", "eye": [1.2, 9, 0.001], "target": [1.2, 0, 0], "up": [0, 0, -1], "fov": 40,
               "near": 0.5, "far": 50}]})");
        return p;
    }();
    return path;
}

RunConfig configOf(const Case& c) {
    const std::string scene = std::string(c.scene) == "exceptions" ? exceptionsScene() : c.scene;
    RunConfig cfg = test::quickConfig(scene, c.camera, 160, c.submit);
    if (std::string(c.scene) == "aircraft") cfg.sceneOptions.instances = 20;
    if (*c.light) cfg.sceneOptions.lightType = *lightTypeNames().parse(c.light);
    return cfg;
}

Images renderGl(const Case& c) {
    Harness h(configOf(c));
    auto t = TechniqueRegistry::create(TechniqueSpec::parse(c.technique));
    h.prepare(*t);
    h.renderFrame(*t);
    return {h.targets().readColorRGBA8(), h.targets().readVisibilityRGBA32F()};
}

Images renderVulkan(const Case& c) {
    test::VulkanFrame frame(configOf(c), c.technique);
    VulkanTargets& targets = frame.harness().targets();
    return {targets.readColorRGBA8(), targets.readVisibilityRGBA32F()};
}

class GlVulkanImage : public ::testing::TestWithParam<Case> {};

TEST_P(GlVulkanImage, SamePixelsOnBothApis) {
    const Case& c = GetParam();
    const Images gl = renderGl(c);
    const Images vk = renderVulkan(c);
    ASSERT_EQ(gl.colour.size(), vk.colour.size());
    ASSERT_EQ(gl.visibility.size(), vk.visibility.size());
    const size_t pixels = gl.colour.size() / 4;
    constexpr float kHalfStep = 1.0f / 1024.0f; // one step of RGBA16F at 1
    size_t colourOff = 0, visibilityOff = 0, flips = 0, shadowed = 0;
    int worstColour = 0;
    float worstRounding = 0.0f;
    for (size_t i = 0; i < pixels; ++i) {
        int d = 0;
        for (int k = 0; k < 3; ++k)
            d = std::max(d, std::abs(int(gl.colour[i * 4 + k]) - int(vk.colour[i * 4 + k])));
        float v = 0.0f;
        for (int k = 0; k < 4; ++k)
            v = std::max(v, std::abs(gl.visibility[i * 4 + k] - vk.visibility[i * 4 + k]));
        visibilityOff += v > 0.0f;
        shadowed += gl.visibility[i * 4] < 0.5f;
        if (v > kHalfStep) { // more than rounding: the pixel changed sides (volumes only)
            ++flips;
            continue;
        }
        worstRounding = std::max(worstRounding, v);
        worstColour = std::max(worstColour, d);
        colourOff += d > 0;
    }
    EXPECT_LE(double(flips), c.flipFraction * double(pixels)) << "pixels whose visibility changed sides";
    // A case whose image has no shadow would compare nothing a shadow technique does (none and the
    // synthetic workloads draw none).
    if (std::string(c.technique).rfind("none", 0) != 0 &&
        std::string(c.technique).rfind("synthetic", 0) != 0) {
        EXPECT_GT(shadowed, 0u) << "no shadowed pixel on GL";
    }
    EXPECT_LE(worstColour, 1) << colourOff << " pixels differ in colour (where visibility agrees)";

    EXPECT_LE(double(colourOff), c.colourFraction * double(pixels))
        << "pixels whose colour differs (any amount)";
    EXPECT_LE(double(visibilityOff), c.roundingFraction * double(pixels))
        << "pixels whose visibility differs (any amount)";
    RecordProperty("colour_pixels_differing", int(colourOff));
    RecordProperty("visibility_pixels_differing", int(visibilityOff));
    std::cout << c.name << ": " << colourOff << " pixels differ in colour, " << visibilityOff
              << " in visibility (by rounding at most " << worstRounding << "), " << flips
              << " changed sides\n";
}

INSTANTIATE_TEST_SUITE_P(Techniques, GlVulkanImage, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace

// A scene in motion: the harnesses move the casters, the sun and the camera along the path at the start
// of each frame and the techniques follow (sceneChanged). At several steps of the path the two APIs must
// draw the same images (the tolerances above) and count the same work (the technique's counters), in
// both Vulkan submission modes: retained pushes each instance's transform as it is now, instanced
// rewrites its instance buffer.
namespace {

struct MotionCase {
    const char* name;
    const char* technique;
    SubmitMode submit;
    double flipFraction; ///< as Case::flipFraction
};
void PrintTo(const MotionCase& c, std::ostream* os) {
    *os << c.name;
}

const MotionCase kMotionCases[] = {
    {"shadowmap_instanced", "shadowmap:resolution=1024", SubmitMode::Instanced, 0.0},
    {"volume_retained", "volume", SubmitMode::Retained, 0.001},
};

class GlVulkanMotion : public ::testing::TestWithParam<MotionCase> {};

TEST_P(GlVulkanMotion, SameImagesAndCountersAlongThePath) {
    const MotionCase& c = GetParam();
    RunConfig cfg = test::quickConfig("aircraft_day", "path", 160, c.submit);
    Harness gl(cfg);
    cfg.api = RunConfig::Api::Vulkan;
    cfg.vulkan.validation = true;
    VulkanHarness vk(cfg);
    auto glTechnique = TechniqueRegistry::create(TechniqueSpec::parse(c.technique));
    auto vkTechnique = TechniqueRegistry::createVulkan(TechniqueSpec::parse(c.technique));
    gl.prepare(*glTechnique);
    vk.prepare(*vkTechnique);
    for (uint64_t step : {uint64_t(5), uint64_t(30), uint64_t(55)}) {
        SCOPED_TRACE("path step " + std::to_string(step));
        gl.seekPath(step);
        vk.seekPath(step);
        gl.renderFrame(*glTechnique);
        vk.renderFrame(*vkTechnique);
        ASSERT_EQ(gl.pathTime(), vk.pathTime());
        const std::vector<unsigned char> gc = gl.readColor(), vc = vk.readColor();
        const std::vector<float> gv = gl.readVisibility(), vv = vk.readVisibility();
        ASSERT_EQ(gc.size(), vc.size());
        ASSERT_EQ(gv.size(), vv.size());
        const size_t pixels = gc.size() / 4;
        size_t colourOff = 0, visibilityOff = 0, flips = 0, shadowed = 0;
        int worstColour = 0;
        for (size_t i = 0; i < pixels; ++i) {
            float v = 0.0f;
            for (int k = 0; k < 4; ++k) v = std::max(v, std::abs(gv[i * 4 + k] - vv[i * 4 + k]));
            shadowed += gv[i * 4] < 0.5f;
            visibilityOff += v > 0.0f;
            if (v > 1.0f / 1024.0f) {
                ++flips;
                continue;
            }
            int d = 0;
            for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(gc[i * 4 + k]) - int(vc[i * 4 + k])));
            worstColour = std::max(worstColour, d);
            colourOff += d > 0;
        }
        EXPECT_GT(shadowed, 0u);
        EXPECT_LE(double(flips), c.flipFraction * double(pixels));
        EXPECT_LE(worstColour, 1);
        EXPECT_LE(colourOff, pixels / 200);
        EXPECT_LE(visibilityOff, pixels / 200);
        // Counters are equal, but for the samples the volumes' clipped edges may flip (flipFraction).
        Counters glCounters = glTechnique->counters(), vkCounters = vkTechnique->counters();
        ASSERT_EQ(glCounters.size(), vkCounters.size());
        for (size_t k = 0; k < glCounters.size(); ++k) {
            EXPECT_EQ(glCounters[k].first, vkCounters[k].first);
            if (glCounters[k].first == "stencil_samples_passed")
                EXPECT_LE(std::abs(glCounters[k].second - vkCounters[k].second),
                          c.flipFraction * double(pixels));
            else
                EXPECT_EQ(glCounters[k].second, vkCounters[k].second) << glCounters[k].first;
        }
        std::cout << c.name << " step " << step << ": " << colourOff << " pixels differ in colour, "
                  << visibilityOff << " in visibility, " << flips << " changed sides\n";
    }
    EXPECT_EQ(test::validationErrorLog(vk.context()), "");
    vkTechnique.reset(); // before the harness's device
}

INSTANTIATE_TEST_SUITE_P(Motion, GlVulkanMotion, ::testing::ValuesIn(kMotionCases),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace

// volume's stencil_samples_passed: GL_SAMPLES_PASSED on GL, a precise occlusion query on Vulkan (where the
// device offers occlusionQueryPrecise: lavapipe does), around the same marking passes and read as late.
// Three frames, so the counter holds the first frame's samples on both APIs; scenes on which the two
// drivers' volumes cover the same pixels (on teapot and city one or two of ~10^4 samples differ: the
// clipped volume edges of the image tests' flipFraction).
TEST(GlVulkanVolumeSamples, SameStencilSamplesOnBothApis) {
    for (const char* scene : {"aircraft", "point_light", "sphere_plane"}) {
        SCOPED_TRACE(scene);
        RunConfig cfg = test::quickConfig(scene, "far", 160);
        if (std::string(scene) == "aircraft") cfg.sceneOptions.instances = 20;
        Harness gl(cfg);
        cfg.api = RunConfig::Api::Vulkan;
        cfg.vulkan.validation = true;
        VulkanHarness vk(cfg);
        if (!vk.context().occlusionQueryPrecise()) GTEST_SKIP() << "no occlusionQueryPrecise on this device";
        auto glVolume = TechniqueRegistry::create(TechniqueSpec::parse("volume"));
        auto vkVolume = TechniqueRegistry::createVulkan(TechniqueSpec::parse("volume"));
        gl.prepare(*glVolume);
        vk.prepare(*vkVolume);
        for (int i = 0; i < 3; ++i) {
            gl.renderFrame(*glVolume);
            vk.renderFrame(*vkVolume);
        }
        const double samples = test::counter(glVolume->counters(), "stencil_samples_passed");
        EXPECT_GT(samples, 0.0);
        EXPECT_EQ(test::counter(vkVolume->counters(), "stencil_samples_passed"), samples);
        EXPECT_EQ(test::validationErrorLog(vk.context()), "");
        vkVolume.reset(); // before the harness's device
    }
}
