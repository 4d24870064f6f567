// `bench accuracy`'s texels-per-pixel columns end to end (bench/lib/measure/TexelDensity.h): G-buffer,
// judged mask, the technique's own light-space mapping (techniques/MapTexels.h) and the CSV. A square
// plate 2 above a ground under a directional light straight down, seen by a perspective camera straight
// down: every ground sample the map covers lies on one plane parallel to the image, where a pixel's
// footprint is 2 H tan(fov / 2) / W and the orthographic map's texel its fitted extent / resolution, so
// median, 5th percentile and minimum are all the closed form. The plate receives no shadow (no lookup:
// left out). `volume`, which reads no map, leaves the columns empty. About a second.
#include <cmath>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;

namespace {

constexpr const char* kScene = R"({
  "name": "texel_plate",
  "meshes": [
    {"name": "ground", "generator": "plane", "size": 40, "tessellation": 1},
    {"name": "plate", "generator": "plane", "size": 4, "tessellation": 1}
  ],
  "instances": [
    {"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},
    {"mesh": "plate", "position": [0, 2, 0], "receives_shadow": false}
  ],
  "lights": [{"type": "directional", "direction": [0, -1, 0]}],
  "cameras": [{"name": "top", "eye": [0, 10, 0], "target": [0, 0, 0], "fov": 40, "near": 0.1, "far": 100}],
  "effects": ["hard_shadows"]
})";

} // namespace

TEST(TexelDensityCli, ColumnsHoldTheClosedFormForShadowmapAndAreEmptyForVolume) {
    const std::string dir = test::freshTestDir("texel-density");
    test::writeFile(dir + "/plate.json", kScene);
    const std::string csv = dir + "/acc.csv";
    // fit_margin 0.5: the map reaches past the plate's own image, so that ground samples inside it show.
    const auto r =
        test::runCommand(std::string(SB_BENCH_BINARY) +
                         " accuracy -t shadowmap:resolution=256:fit_margin=0.5 -t volume --scene " + dir +
                         "/plate.json --camera top --size 64x64 --frames 2 --warmup 1 "
                         "--no-timer-check --no-stability --csv " +
                         csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u);
    // The plate's 4 x 4 casters, framed with 0.5 x 4 + 1e-3 a side (scenes/LightFit.h): 8.002 units over
    // 256 texels; the camera 10 above the ground, 40 degrees over 64 pixels.
    const double pixel = 2.0 * 10.0 * std::tan(20.0 * 3.14159265358979323846 / 180.0) / 64.0;
    const double expected = 256.0 / 8.002 * pixel;
    for (const char* column :
         {col::kAccTexelsPerPixelP50, col::kAccTexelsPerPixelP5, col::kAccTexelsPerPixelMin}) {
        ASSERT_FALSE(rows[0].at(column).empty()) << column << "\n" << r.output;
        // The CSV's 4 decimals and the G-buffer's float positions: 1e-3.
        EXPECT_NEAR(std::stod(rows[0].at(column)), expected, 1e-3) << column;
        EXPECT_EQ(rows[1].at(col::kTechnique), "volume");
        EXPECT_EQ(rows[1].at(column), "") << column;
    }
}
