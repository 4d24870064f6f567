// Unit tests of scenes/ModelLoader with the fixture tests/data/cube.obj (8 corners, 6 quads) and the real
// model files of glmark2-data and assimp-testmodels (scripts/install-deps.sh installs both).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "core/Error.h"
#include "scenes/ModelLoader.h"

using namespace sb;

namespace {

const std::string kCube = std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj";
const std::string kInfinite = std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.obj";
const std::string kHorse = "/usr/share/glmark2/models/horse.3ds";
const std::string kRoom = "/usr/share/assimp/models/3DS/test1.3ds";    // a box room, nine 3DS objects
const std::string kSpider = "/usr/share/assimp/models/OBJ/spider.obj"; // nineteen OBJ groups

/// Skips a test whose model file is not installed (scripts/install-deps.sh installs it).
#define REQUIRE_FILE(path)                                                                                   \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not installed (scripts/install-deps.sh)"

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

TEST(ModelLoaderTest, NonFiniteVertexIsRefusedNamingTheFile) {
    // tests/data/infinite_vertex.obj has x = 1e39, beyond float range: it reads as inf. A NaN written
    // out in the file is refused the same way. Every technique downstream got an empty or NaN frame.
    EXPECT_EQ(errorOf(kInfinite), "model file '" + kInfinite +
                                      "': vertex 1 of mesh 'defaultobject' is (inf, 0, 0): a model with "
                                      "infinite or NaN positions cannot be drawn");
    const std::string nan = writeTemp("sb_nan_vertex.obj", "v 0 0 0\nv 0 nan 0\nv 0 1 0\nf 1 2 3\n");
    const std::string error = errorOf(nan);
    EXPECT_EQ(error.rfind("model file '" + nan + "': vertex 1 ", 0), 0u) << error;
    EXPECT_NE(error.find("(0, nan, 0)"), std::string::npos) << error;
    std::remove(nan.c_str());
}

TEST(ModelLoaderTest, RotationToYUpTakesEachAxisToPlusY) {
    // Closed form: R * up = +Y, and R is a rotation (orthonormal columns, determinant +1), so a model
    // is stood up, never mirrored.
    const std::map<ModelUp, glm::vec3> axes = {{ModelUp::PosX, {1, 0, 0}}, {ModelUp::NegX, {-1, 0, 0}},
                                               {ModelUp::PosY, {0, 1, 0}}, {ModelUp::NegY, {0, -1, 0}},
                                               {ModelUp::PosZ, {0, 0, 1}}, {ModelUp::NegZ, {0, 0, -1}}};
    for (const auto& [up, axis] : axes) {
        const glm::mat3 r = ModelLoader::rotationToYUp(up);
        EXPECT_EQ(r * axis, glm::vec3(0, 1, 0)) << modelUpName(up);
        EXPECT_EQ(glm::determinant(r), 1.0f) << modelUpName(up);
        EXPECT_EQ(glm::transpose(r) * r, glm::mat3(1.0f)) << modelUpName(up);
        EXPECT_EQ(parseModelUp(modelUpName(up)), up);
    }
}

TEST(ModelLoaderTest, HorseStandsUpright) {
    REQUIRE_FILE(kHorse);
    // glmark2's rearing horse is Y-up as stored: 1.254 wide (x), 1.704 tall (y), 0.773 from side to
    // side (z) (the extents of the file's vertices, read with a 3DS dump). assimp's fixed 3ds Max
    // rotation made it 0.773 tall and 1.704 deep: lying on its side. Tolerance 1e-3: printed digits.
    const glm::vec3 e = ModelLoader::load(kHorse).computeBounds().extent();
    EXPECT_NEAR(e.x, 1.2537f, 1e-3f);
    EXPECT_NEAR(e.y, 1.7038f, 1e-3f);
    EXPECT_NEAR(e.z, 0.7732f, 1e-3f);
    EXPECT_GT(e.y, std::max(e.x, e.z)) << "the height of a rearing horse is its longest extent";
}

TEST(ModelLoaderTest, RoomStandsOnItsFloor) {
    REQUIRE_FILE(kRoom);
    // assimp's test1.3ds: a floor slab Box01, a ceiling slab Box10, four walls, and a pyramid of three
    // crates: Box05 and Box06 on the floor, Box07 resting on both. Up is +Y when the floor is the thin
    // slab below the crates and each crate's bottom touches what carries it. Tolerance 0.01: the
    // file's crates overlap their supports by about 0.004.
    std::map<std::string, Aabb> box;
    for (const Mesh& m : ModelLoader::loadObjects(kRoom)) box[m.name] = m.computeBounds();
    ASSERT_EQ(box.size(), 9u);
    const Aabb floor = box["Box01"], ceiling = box["Box10"];
    EXPECT_LT(floor.extent().y, 0.05f * floor.extent().x) << "the floor is a horizontal slab";
    EXPECT_LT(floor.max.y, ceiling.min.y);
    for (const char* crate : {"Box05", "Box06"}) {
        EXPECT_NEAR(box[crate].min.y, floor.max.y, 0.01f) << crate << " stands on the floor";
        EXPECT_NEAR(box["Box07"].min.y, box[crate].max.y, 0.01f) << "Box07 rests on " << crate;
    }
}

namespace {

/// The bounds of each `g` group of an OBJ file, read as text: the independent answer to the loader.
std::map<std::string, Aabb> objGroupBounds(const std::string& path) {
    std::ifstream in(path);
    std::vector<glm::vec3> vertices;
    std::map<std::string, Aabb> groups;
    std::string group = "default", line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            glm::vec3 v;
            ls >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (tag == "g" || tag == "o") {
            ls >> group;
        } else if (tag == "f") {
            for (std::string corner; ls >> corner;) {
                const long i = std::stol(corner.substr(0, corner.find('/')));
                groups[group].extend(vertices[size_t(i > 0 ? i - 1 : long(vertices.size()) + i)]);
            }
        }
    }
    return groups;
}

} // namespace

TEST(ModelLoaderTest, EachObjGroupIsItsOwnObjectWithItsOwnBounds) {
    REQUIRE_FILE(kSpider);
    // Every group of spider.obj is one object, with the bounds of the vertices its faces use in the
    // file (OBJ has no node transforms, and no up axis: read as is). Tolerance 1e-4 (coordinates up to
    // 110): assimp's number parser rounds the last bit differently from iostream's.
    const std::map<std::string, Aabb> expected = objGroupBounds(kSpider);
    const std::vector<Mesh> objects = ModelLoader::loadObjects(kSpider);
    ASSERT_EQ(expected.size(), 19u);
    ASSERT_EQ(objects.size(), expected.size());
    for (const Mesh& m : objects) {
        ASSERT_TRUE(expected.count(m.name)) << m.name;
        const Aabb b = m.computeBounds(), e = expected.at(m.name);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(b.min[a], e.min[a], 1e-4f) << m.name << " axis " << a;
            EXPECT_NEAR(b.max[a], e.max[a], 1e-4f) << m.name << " axis " << a;
        }
    }
    // load() joins them, each object's triangles a part of the one mesh.
    const Mesh joined = ModelLoader::load(kSpider);
    EXPECT_EQ(joined.parts.size(), 19u);
}

TEST(ModelLoaderTest, FbxUpAxisIsHonoured) {
    const std::string box = "/usr/share/assimp/models/FBX/maxPbrMaterial_metalRough.fbx";
    REQUIRE_FILE(box);
    // An ASCII FBX box standing on y = 0 with "UpAxis" 1 (Y). The same file saying "UpAxis" 2 (Z) must
    // come out turned by -90 degrees about X, (x, y, z) -> (x, z, -y): a closed-form swap of bounds.
    // Tolerance 1e-4 of extents around 20: float rounding of the rotation.
    std::ifstream in(box);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string yUp = "P: \"UpAxis\", \"int\", \"Integer\", \"\",1";
    const size_t at = text.find(yUp);
    ASSERT_NE(at, std::string::npos);
    const std::string zUpPath =
        writeTemp("sb_z_up.fbx", text.replace(at, yUp.size(), yUp.substr(0, yUp.size() - 1) + "2"));
    const Aabb y = ModelLoader::load(box).computeBounds(), z = ModelLoader::load(zUpPath).computeBounds();
    EXPECT_NEAR(y.min.y, 0.0f, 1e-4f) << "the box stands on y = 0 as the file says";
    EXPECT_NEAR(z.min.x, y.min.x, 1e-4f);
    EXPECT_NEAR(z.max.x, y.max.x, 1e-4f);
    EXPECT_NEAR(z.min.y, y.min.z, 1e-4f);
    EXPECT_NEAR(z.max.y, y.max.z, 1e-4f);
    EXPECT_NEAR(z.min.z, -y.max.y, 1e-4f);
    EXPECT_NEAR(z.max.z, -y.min.y, 1e-4f);
    std::remove(zUpPath.c_str());
}

// ---- hostile model files: refused with one line naming the file (exit 2), never a crash ------------

namespace {

/// An n x n grid of quads on y = 0 as (n + 1)^2 vertices and 2 n^2 triangles: the PLY fixtures below.
struct Grid {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<int32_t, 3>> faces;
};

Grid grid(int n) {
    Grid g;
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) g.vertices.emplace_back(float(x), 0.0f, float(z));
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const int a = z * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            g.faces.push_back({a, c, b});
            g.faces.push_back({b, c, d});
        }
    return g;
}

std::string plyHeader(const Grid& g, const char* format) {
    return std::string("ply\nformat ") + format + " 1.0\nelement vertex " +
           std::to_string(g.vertices.size()) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
           std::to_string(g.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string asciiPly(const Grid& g) {
    std::ostringstream out;
    out << plyHeader(g, "ascii");
    for (const glm::vec3& v : g.vertices) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (const auto& f : g.faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    return out.str();
}

/// Little-endian binary PLY: 12 bytes per vertex, 13 per face (a uchar count and three int32).
std::string binaryPly(const Grid& g) {
    std::string out = plyHeader(g, "binary_little_endian");
    const auto append = [&](const void* data, size_t size) {
        out.append(static_cast<const char*>(data), size);
    };
    for (const glm::vec3& v : g.vertices) append(&v, 12);
    for (const auto& f : g.faces) {
        const uint8_t three = 3;
        append(&three, 1);
        append(f.data(), 12);
    }
    return out;
}

std::string writeTempBinary(const std::string& name, const std::string& bytes) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return path.string();
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
}

} // namespace

TEST(ModelLoaderTest, CompletePlyFilesLoad) {
    // The fixtures of the tests below, whole: 121 vertices, 200 triangles, in both encodings.
    const Grid g = grid(10);
    for (const auto& [name, bytes] :
         {std::pair{"sb_grid_ascii.ply", asciiPly(g)}, std::pair{"sb_grid_binary.ply", binaryPly(g)}}) {
        const std::string path = writeTempBinary(name, bytes);
        const Mesh m = ModelLoader::load(path);
        EXPECT_EQ(m.triangleCount(), 200u) << name;
        EXPECT_EQ(m.vertexCount(), 121u) << name;
        std::remove(path.c_str());
    }
}

TEST(ModelLoaderTest, TruncatedBinaryPlyIsRefused) {
    // Cut inside the faces, the last face's indices were garbage and assimp's post-processing crashed
    // (SIGSEGV); cut at a face boundary, assimp repeated the last face for the missing ones and the
    // file loaded. Cut inside the vertices, both.
    const Grid g = grid(10);
    const std::string whole = binaryPly(g);
    const size_t body = plyHeader(g, "binary_little_endian").size();
    const struct {
        size_t size;
        std::string why;
    } cuts[] = {
        {whole.size() - whole.size() / 3, "200 'face' records but the file ends after 91 of them"},
        {body + 121 * 12 + 50 * 13, "200 'face' records but the file ends after 50 of them"},
        {body + 10 * 12 + 5, "121 'vertex' records but the file ends after 10 of them"},
    };
    for (const auto& cut : cuts) {
        const std::string path = writeTempBinary("sb_truncated_binary.ply", whole.substr(0, cut.size));
        EXPECT_EQ(errorOf(path), "model file '" + path + "': the PLY header declares " + cut.why +
                                     ": the file is truncated");
        std::remove(path.c_str());
    }
}

TEST(ModelLoaderTest, TruncatedAsciiPlyIsRefused) {
    // A file cut after 50 of its 200 faces loaded as 200 triangles: assimp read the 50 and repeated
    // the 50th for the rest, without a word.
    const Grid g = grid(10);
    const std::string whole = asciiPly(g);
    size_t at = whole.find("end_header\n") + 11;
    for (int line = 0; line < 121 + 50; ++line) at = whole.find('\n', at) + 1;
    const std::string path = writeTemp("sb_truncated_ascii.ply", whole.substr(0, at));
    EXPECT_EQ(errorOf(path),
              "model file '" + path +
                  "': the PLY header declares 200 'face' records but the file ends after 50 of "
                  "them: the file is truncated");
    std::remove(path.c_str());
}

TEST(ModelLoaderTest, FaceIndexBeyondTheVerticesIsRefused) {
    // PLY: assimp copied the index through and its post-processing crashed (SIGSEGV); assimp's
    // validation names the face. OBJ: assimp's OBJ reader refused it already (kept as a guard).
    Grid g = grid(10);
    g.faces.back()[2] = 100000;
    const std::string ply = writeTemp("sb_bad_index.ply", asciiPly(g));
    EXPECT_EQ(errorOf(ply), "model file '" + ply +
                                "': Validation failed: aiMesh::mFaces[199]::mIndices[2] is out of range");
    std::remove(ply.c_str());
    const std::string obj = writeTemp("sb_bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 99\n");
    EXPECT_EQ(errorOf(obj), "model file '" + obj + "': OBJ: vertex index out of range");
    std::remove(obj.c_str());
}

TEST(ModelLoaderTest, CoordinatesBeyondTheBoundAreRefused) {
    // 3e38 is a finite float, but every length through it is inf (3e38 squared): the model loaded and
    // its fits and normals turned to inf/NaN. The bound is ModelLoader::kMaxCoordinate, 1e18.
    const std::string huge = writeTemp("sb_huge.obj", "v 0 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n");
    EXPECT_EQ(errorOf(huge),
              "model file '" + huge +
                  "': vertex 1 of object 'defaultobject' is (3e+38, 0, 0): beyond +-1e18, where "
                  "squared distances overflow float");
    std::remove(huge.c_str());
    // Just inside the bound loads, and so does a small triangle (assimp welds corners closer than
    // 1e-5, so a smaller one comes out degenerate and is refused by the test below).
    for (const char* scale : {"1e17", "1e-3"}) {
        const std::string s = scale;
        const std::string path =
            writeTemp("sb_scaled.obj", "v 0 0 0\nv " + s + " 0 0\nv 0 " + s + " 0\nf 1 2 3\n");
        EXPECT_EQ(ModelLoader::load(path).triangleCount(), 1u) << scale;
        std::remove(path.c_str());
    }
}

TEST(ModelLoaderTest, OnlyDegenerateTrianglesAreRefused) {
    // Collinear and repeated corners: zero area, nothing to draw or fit; it loaded as two triangles.
    const std::string path = writeTemp("sb_degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n");
    const std::string error = errorOf(path);
    EXPECT_TRUE(startsWith(error, "model file '" + path + "': all ")) << error;
    EXPECT_NE(error.find(" triangles are degenerate (zero area): nothing to draw"), std::string::npos)
        << error;
    std::remove(path.c_str());
}

TEST(ModelLoaderTest, ImportEstimateCountsCornersBeforeTheFileIsRead) {
    // assimp makes one vertex per face corner before it welds them: an OBJ quad is 4 corners and 2
    // triangles, a triangle 3 and 1 (4 "v" lines are positions, 24 B each on top); an ASCII STL facet
    // 3 corners. bytes = corners * kImportBytesPerCorner + the file's size (+ the OBJ positions).
    const std::string obj = writeTemp("sb_estimate.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                         "f 1 2 3 4\nf 1 2 3\n");
    const auto o = ModelLoader::estimateImport(obj);
    ASSERT_TRUE(o.has_value());
    EXPECT_EQ(o->corners, 7u);
    EXPECT_EQ(o->triangles, 3u);
    EXPECT_EQ(o->bytes, 7 * ModelLoader::kImportBytesPerCorner + std::filesystem::file_size(obj) + 4 * 24);
    std::remove(obj.c_str());
    const std::string stl = writeTemp("sb_estimate.stl", "solid t\nfacet normal 0 0 1\nouter loop\n"
                                                         "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                                         "endloop\nendfacet\nendsolid t\n");
    const auto s = ModelLoader::estimateImport(stl);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->corners, 3u);
    EXPECT_EQ(s->triangles, 1u);
    std::remove(stl.c_str());
    // A format without a count known before the import: nothing (checked after it instead).
    const std::string gltf = writeTemp("sb_estimate.gltf", "{}");
    EXPECT_FALSE(ModelLoader::estimateImport(gltf).has_value());
    std::remove(gltf.c_str());
}
