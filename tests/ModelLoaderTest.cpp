// Unit tests of scenes/ModelLoader with the fixture tests/data/cube.obj (8 corners, 6 quads).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "core/Error.h"
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

TEST(ModelLoaderTest, ObjGroupsBecomeNamedParts) {
    // Two groups with their own materials (so the pre-transform step cannot join them): a plate of
    // 2 triangles at y = 1 and a base quad of 2 triangles at y = 0. Each group is a named part covering
    // exactly its own triangles.
    const std::string path = writeTemp("sb_parts.obj", "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"
                                                       "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\n"
                                                       "g plate\nusemtl plateMaterial\nf 1 3 2\nf 1 4 3\n"
                                                       "g base\nusemtl baseMaterial\nf 5 7 6\nf 5 8 7\n");
    const Mesh m = ModelLoader::load(path);
    ASSERT_EQ(m.parts.size(), 2u);
    for (const MeshPart& part : m.parts) {
        ASSERT_EQ(part.indexCount, 6u) << part.name;
        const float y = part.name == "plate" ? 1.0f : 0.0f;
        EXPECT_TRUE(part.name == "plate" || part.name == "base") << part.name;
        for (uint32_t k = part.firstIndex; k < part.firstIndex + part.indexCount; ++k)
            EXPECT_EQ(m.positions[m.indices[k]].y, y) << part.name;
    }
    std::remove(path.c_str());
}
