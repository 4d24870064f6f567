// Unit tests of scenes/ModelLoader with the fixture tests/data/cube.obj (8 corners, 6 quads).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scenes/Error.h"
#include "scenes/ModelLoader.h"

using namespace sb;

namespace {

const std::string kCube = std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj";

std::string writeTemp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path) << text;
    return path.string();
}

std::string errorOf(const std::string& path) {
    try {
        ModelLoader::load(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ModelLoaderTest, CubeFixtureLoadsTriangulatedAndWelded) {
    const Mesh m = ModelLoader::load(kCube);
    // 6 quads -> 12 triangles; smooth normals are per position, so the 24 face corners weld to 8.
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_EQ(m.vertexCount(), 8u);
    EXPECT_EQ(m.normals.size(), m.positions.size());
    const Aabb b = m.computeBounds();
    EXPECT_EQ(b.min, glm::vec3(-1.0f));
    EXPECT_EQ(b.max, glm::vec3(1.0f));
    double volume = 0.0; // outward winding kept from the file: +8
    for (size_t t = 0; t < m.triangleCount(); ++t)
        volume += glm::dot(m.positions[m.indices[3 * t]],
                           glm::cross(m.positions[m.indices[3 * t + 1]], m.positions[m.indices[3 * t + 2]])) /
                  6.0;
    EXPECT_NEAR(volume, 8.0, 1e-5);
    for (size_t i = 0; i < m.vertexCount(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-4f);
        // A smooth corner normal points away from the centre, along the corner's diagonal.
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i]), 0.0f);
    }
}

TEST(ModelLoaderTest, MissingFileNamesIt) {
    EXPECT_EQ(errorOf("/nonexistent/model.obj"), "model file '/nonexistent/model.obj': no such file");
}

TEST(ModelLoaderTest, CorruptFileGivesAssimpsReason) {
    const std::string path = writeTemp("sb_corrupt_model.glb", "glTF\x02garbage that is not a binary glTF");
    const std::string error = errorOf(path);
    EXPECT_EQ(error.rfind("model file '" + path + "': ", 0), 0u) << error;
    EXPECT_GT(error.size(), path.size() + 16) << "no reason given: " << error;
    std::remove(path.c_str());
}

TEST(ModelLoaderTest, FileWithoutTrianglesIsRejected) {
    const std::string path = writeTemp("sb_lines_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
    const std::string error = errorOf(path);
    EXPECT_EQ(error.rfind("model file '" + path + "': ", 0), 0u) << error;
    std::remove(path.c_str());
}
