#include "scenes/ModelLoader.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/Error.h"
#include "core/NameTable.h"

namespace sb {
namespace {

constexpr Named<ModelUp> kUpNames[] = {
    {ModelUp::PosX, "x"},  {ModelUp::NegX, "-x"}, {ModelUp::PosY, "y"},
    {ModelUp::NegY, "-y"}, {ModelUp::PosZ, "z"},  {ModelUp::NegZ, "-z"},
};
constexpr NameTable kUps{kUpNames};

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("model file '" + path + "': " + why);
}

glm::mat4 toGlm(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (m[row][column]); glm is column-major.
    glm::mat4 out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c][r] = m[r][c];
    return out;
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string objectName(const aiNode& node, size_t index) {
    return node.mName.length ? std::string(node.mName.C_Str()) : "object" + std::to_string(index);
}

/// The file's up axis when neither the caller nor the file's metadata gives one: as read.
std::optional<ModelUp> metadataUp(const aiScene& scene) {
    int32_t axis = -1, sign = 1;
    if (!scene.mMetaData || !scene.mMetaData->Get("UpAxis", axis)) return std::nullopt;
    scene.mMetaData->Get("UpAxisSign", sign);
    switch (axis) {
    case 0:
        return sign < 0 ? ModelUp::NegX : ModelUp::PosX;
    case 1:
        return sign < 0 ? ModelUp::NegY : ModelUp::PosY;
    case 2:
        return sign < 0 ? ModelUp::NegZ : ModelUp::PosZ;
    default:
        return std::nullopt;
    }
}

bool isThreeDs(const aiScene& scene, const std::string& path) {
    aiString format;
    if (scene.mMetaData && scene.mMetaData->Get("SourceAsset_Format", format))
        return std::string(format.C_Str()).find("3DS") != std::string::npos;
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".3ds";
}

/// Appends the triangles of one assimp mesh through `transform` (normals through its inverse
/// transpose). Triangulate leaves points and lines as 1- and 2-index faces, which are skipped; a
/// mirroring transform has its winding swapped so front faces stay counter-clockwise.
void appendMesh(Mesh& out, const aiMesh& in, const glm::mat4& transform) {
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
    const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
    const uint32_t base = uint32_t(out.positions.size());
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
        const aiVector3D& p = in.mVertices[v];
        out.positions.emplace_back(transform * glm::vec4(p.x, p.y, p.z, 1.0f));
        glm::vec3 n(0.0f, 1.0f, 0.0f);
        if (in.mNormals) n = normalMatrix * glm::vec3(in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z);
        // GenSmoothNormals can leave zero normals on degenerate faces; Mesh promises unit normals.
        const float len = glm::length(n);
        out.normals.push_back(len > 1e-20f && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0));
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
        const aiFace& face = in.mFaces[f];
        if (face.mNumIndices != 3) continue;
        out.indices.push_back(base + face.mIndices[0]);
        out.indices.push_back(base + face.mIndices[mirrored ? 2 : 1]);
        out.indices.push_back(base + face.mIndices[mirrored ? 1 : 2]);
    }
}

/// The object of one node: each of its assimp meshes a named part (a scene file's shadow planes
/// name them; unnamed ones get "part<N>").
Mesh buildObject(const aiScene& scene, const aiNode& node, const glm::mat4& transform, size_t index) {
    Mesh mesh;
    mesh.name = objectName(node, index);
    // Sized once: growing by doubling held up to twice a large model's vertices at its peak.
    size_t vertices = 0, faces = 0;
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        vertices += scene.mMeshes[node.mMeshes[k]]->mNumVertices;
        faces += scene.mMeshes[node.mMeshes[k]]->mNumFaces;
    }
    mesh.positions.reserve(vertices);
    mesh.normals.reserve(vertices);
    mesh.indices.reserve(3 * faces);
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        const aiMesh& in = *scene.mMeshes[node.mMeshes[k]];
        MeshPart part;
        part.name =
            in.mName.length ? std::string(in.mName.C_Str()) : "part" + std::to_string(node.mMeshes[k]);
        part.firstIndex = uint32_t(mesh.indices.size());
        appendMesh(mesh, in, transform);
        part.indexCount = uint32_t(mesh.indices.size()) - part.firstIndex;
        if (part.indexCount) mesh.parts.push_back(part);
    }
    return mesh;
}

void collectObjects(const aiScene& scene, const aiNode& node, const glm::mat4& parent,
                    std::vector<Mesh>& out) {
    const glm::mat4 transform = parent * toGlm(node.mTransformation);
    Mesh object = buildObject(scene, node, transform, out.size());
    if (!object.indices.empty()) out.push_back(std::move(object));
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        collectObjects(scene, *node.mChildren[c], transform, out);
}

std::string vectorText(double x, double y, double z) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", x, y, z);
    return text;
}

/// Infinite or NaN positions (a coordinate beyond float range reads as inf) reach no technique: as
/// read from the file, and after the node transforms (which could overflow).
void checkFinite(const std::string& path, const aiScene& scene, const std::vector<Mesh>& objects) {
    const std::string why = ": a model with infinite or NaN positions cannot be drawn";
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            if (!isFinite(glm::vec3(p.x, p.y, p.z)))
                fail(path, "vertex " + std::to_string(v) + " of mesh '" + mesh.mName.C_Str() + "' is " +
                               vectorText(p.x, p.y, p.z) + why);
        }
    }
    for (const Mesh& m : objects)
        for (size_t v = 0; v < m.positions.size(); ++v)
            if (const glm::vec3& p = m.positions[v]; !isFinite(p))
                fail(path, "vertex " + std::to_string(v) + " of object '" + m.name + "' is " +
                               vectorText(p.x, p.y, p.z) + " after the file's node transforms" + why);
}

/// Every position within kMaxCoordinate after the node transforms (checkFinite has refused inf/NaN).
void checkBounded(const std::string& path, const std::vector<Mesh>& objects) {
    const double bound = ModelLoader::kMaxCoordinate;
    for (const Mesh& m : objects)
        for (size_t v = 0; v < m.positions.size(); ++v) {
            const glm::vec3& p = m.positions[v];
            if (std::abs(p.x) <= bound && std::abs(p.y) <= bound && std::abs(p.z) <= bound) continue;
            fail(path, "vertex " + std::to_string(v) + " of object '" + m.name + "' is " +
                           vectorText(p.x, p.y, p.z) +
                           ": beyond +-1e18, where squared distances overflow float");
        }
}

/// At least one triangle of non-zero area. The cross product is taken in double so that float
/// underflow cannot make real triangles look degenerate (JoinIdenticalVertices already welds corners
/// closer than 1e-5, so a model that small comes out degenerate and is refused here).
void checkNotDegenerate(const std::string& path, const std::vector<Mesh>& objects) {
    size_t triangles = 0;
    for (const Mesh& m : objects)
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3, ++triangles) {
            const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
                c(m.positions[m.indices[t + 2]]);
            if (glm::length(glm::cross(b - a, c - a)) > 0.0) return;
        }
    fail(path, "all " + std::to_string(triangles) + " triangles are degenerate (zero area): nothing to draw");
}

/// One property of a PLY element: a scalar of `size` bytes, or (countSize > 0) a list whose count
/// takes countSize bytes and each item `size` bytes.
struct PlyProperty {
    int size = 0;
    int countSize = 0;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

/// The size of a PLY scalar type, 0 for an unknown one.
int plyTypeSize(const std::string& type) {
    static const std::pair<const char*, int> kSizes[] = {
        {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

/// A PLY file's format and elements from its header, and the offset of the body; nothing for a file
/// that is not PLY or whose header this reader does not follow (assimp then reports what it finds).
struct PlyLayout {
    std::string format;
    std::vector<PlyElement> elements;
    size_t body = 0;
};

std::optional<PlyLayout> readPlyHeader(const std::string& data) {
    if (data.rfind("ply", 0) != 0) return std::nullopt;
    PlyLayout ply;
    for (size_t at = 0; at < data.size();) {
        const size_t eol = data.find('\n', at);
        if (eol == std::string::npos) return std::nullopt;
        std::string line = data.substr(at, eol - at);
        at = eol + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "end_header") {
            ply.body = at;
            return ply;
        }
        if (keyword == "format") {
            words >> ply.format;
        } else if (keyword == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count)) return std::nullopt;
            ply.elements.push_back(e);
        } else if (keyword == "property") {
            std::string type, countType, itemType;
            words >> type;
            PlyProperty p;
            if (type == "list") {
                words >> countType >> itemType;
                p.countSize = plyTypeSize(countType);
                p.size = plyTypeSize(itemType);
                if (!p.countSize) return std::nullopt;
            } else {
                p.size = plyTypeSize(type);
            }
            if (!p.size || ply.elements.empty()) return std::nullopt;
            ply.elements.back().properties.push_back(p);
        }
    }
    return std::nullopt;
}

/// How many records of each element the body holds, in the header's order (each at most its count).
/// ASCII: one record per non-blank line. Binary: the records walked by the property sizes, a list
/// by its stored count.
std::vector<uint64_t> plyRecordsPresent(const std::string& data, const PlyLayout& ply) {
    std::vector<uint64_t> present;
    if (ply.format == "ascii") {
        uint64_t lines = 0;
        for (size_t at = ply.body; at < data.size();) {
            size_t eol = data.find('\n', at);
            if (eol == std::string::npos) eol = data.size();
            if (data.find_first_not_of(" \t\r", at) < eol) ++lines;
            at = eol + 1;
        }
        for (const PlyElement& e : ply.elements) {
            present.push_back(std::min(lines, e.count));
            lines -= present.back();
        }
        return present;
    }
    const bool bigEndian = ply.format == "binary_big_endian";
    size_t at = ply.body;
    for (const PlyElement& e : ply.elements) {
        uint64_t records = 0;
        for (; records < e.count; ++records) {
            bool complete = true;
            for (const PlyProperty& p : e.properties) {
                uint64_t items = 1;
                if (p.countSize) {
                    if (data.size() - at < size_t(p.countSize)) {
                        complete = false;
                        break;
                    }
                    items = 0;
                    for (int b = 0; b < p.countSize; ++b) {
                        const int byte = bigEndian ? b : p.countSize - 1 - b;
                        items = (items << 8) | static_cast<unsigned char>(data[at + size_t(byte)]);
                    }
                    at += size_t(p.countSize);
                }
                // Divided, not multiplied: a hostile count times the item size could wrap around.
                if (items > (data.size() - at) / size_t(p.size)) {
                    complete = false;
                    break;
                }
                at += size_t(items) * size_t(p.size);
            }
            if (!complete) break;
        }
        present.push_back(records);
        if (records < e.count) break;
    }
    present.resize(ply.elements.size(), 0);
    return present;
}

/// assimp reads a truncated PLY file as far as it goes and repeats the last record it read for the
/// missing ones (an ASCII file cut after 50 of its 200 faces loaded as 50 triangles plus 150 copies
/// of the 50th), so the body is checked against the header's counts before assimp reads it.
void checkPlyComplete(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    if (!in.read(magic, 3) || std::string(magic) != "ply") return;
    in.seekg(0);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::optional<PlyLayout> ply = readPlyHeader(data);
    if (!ply || (ply->format != "ascii" && ply->format != "binary_little_endian" &&
                 ply->format != "binary_big_endian"))
        return;
    const std::vector<uint64_t> present = plyRecordsPresent(data, *ply);
    for (size_t i = 0; i < ply->elements.size(); ++i)
        if (present[i] < ply->elements[i].count)
            fail(path, "the PLY header declares " + std::to_string(ply->elements[i].count) + " '" +
                           ply->elements[i].name + "' records but the file ends after " +
                           std::to_string(present[i]) + " of them: the file is truncated");
}

/// Calls `chunk(data, size)` for the file in pieces of 1 MiB: the counters below never hold the file.
template <class Chunk>
void streamFile(const std::string& path, Chunk&& chunk) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buffer(1 << 20);
    while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0)
        chunk(buffer.data(), size_t(in.gcount()));
}

/// OBJ: the corners and triangles of its "f" lines (an n-gon has n corners and n - 2 triangles), and
/// in `bytes` what its "v" lines (positions assimp keeps besides) take.
ModelLoader::ImportEstimate countObj(const std::string& path) {
    ModelLoader::ImportEstimate e;
    uint64_t positions = 0, tokens = 0;
    int column = 0;
    char first = 0;
    bool face = false, inToken = false;
    auto endLine = [&] {
        if (face && tokens > 1) {
            const uint64_t n = tokens - 1;
            e.corners += n;
            if (n >= 3) e.triangles += n - 2;
        }
        face = inToken = false;
        tokens = 0;
        column = 0;
    };
    streamFile(path, [&](const char* data, size_t size) {
        for (size_t i = 0; i < size; ++i) {
            const char c = data[i];
            const bool space = c == ' ' || c == '\t' || c == '\r';
            if (c == '\n') {
                endLine();
            } else if (column == 0) {
                first = c;
                column = 1;
            } else if (column == 1) {
                if (space && first == 'f') face = true, tokens = 1;
                if (space && first == 'v') ++positions;
                column = 2;
            } else if (face) {
                if (!space && !inToken) ++tokens;
                inToken = !space;
            }
        }
    });
    endLine();
    // assimp keeps every position of the file besides the corners it makes: 12 B each, twice over
    // while its vector grows (measured: 9 * 10^5 corners and as many positions took 614 MB at peak).
    e.bytes = positions * 24;
    return e;
}

/// ASCII STL: one corner per "vertex" keyword, three to a triangle.
ModelLoader::ImportEstimate countAsciiStl(const std::string& path) {
    static const std::string kKeyword = "vertex";
    ModelLoader::ImportEstimate e;
    std::string carry;
    streamFile(path, [&](const char* data, size_t size) {
        // The last bytes of the previous piece go first, so a keyword split between pieces counts once.
        std::string text = carry + std::string(data, size);
        for (size_t at = text.find(kKeyword); at != std::string::npos; at = text.find(kKeyword, at + 1))
            ++e.corners;
        const size_t keep = std::min(text.size(), kKeyword.size() - 1);
        carry = text.substr(text.size() - keep);
        // A keyword wholly inside the carried bytes was counted already: the carry is shorter than it.
    });
    e.triangles = e.corners / 3;
    return e;
}

/// STL: binary when the size is 84 + 50 * (the count at byte 80), as assimp decides; ASCII when it
/// starts with "solid"; anything else is refused here with both numbers (assimp said only that it
/// could not tell the representation, after reading the whole file).
ModelLoader::ImportEstimate countStl(const std::string& path, uint64_t fileSize) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[84] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const size_t got = size_t(in.gcount());
    if (got == sizeof head) {
        const uint64_t count = uint64_t(head[80]) | uint64_t(head[81]) << 8 | uint64_t(head[82]) << 16 |
                               uint64_t(head[83]) << 24;
        if (84 + 50 * count == fileSize) return {count, 3 * count, 0};
    }
    const std::string text(reinterpret_cast<const char*>(head), got);
    const size_t start = text.find_first_not_of(" \t\r\n");
    if (start != std::string::npos && text.compare(start, 5, "solid") == 0) return countAsciiStl(path);
    if (got < sizeof head)
        fail(path,
             "a binary STL file needs at least 84 bytes (a header and a triangle count), this one has " +
                 std::to_string(fileSize));
    const uint64_t count =
        uint64_t(head[80]) | uint64_t(head[81]) << 8 | uint64_t(head[82]) << 16 | uint64_t(head[83]) << 24;
    fail(path, "the binary STL header declares " + std::to_string(count) +
                   " triangles, which take 84 + 50 * " + std::to_string(count) + " = " +
                   std::to_string(84 + 50 * count) + " bytes, but the file has " + std::to_string(fileSize) +
                   ": truncated, or not an STL file");
}

/// PLY: from the header alone (at most its first MiB): three corners per face, one per vertex.
std::optional<ModelLoader::ImportEstimate> countPly(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(1 << 20, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    const std::optional<PlyLayout> ply = readPlyHeader(head);
    if (!ply) return std::nullopt;
    ModelLoader::ImportEstimate e;
    for (const PlyElement& element : ply->elements) {
        if (element.name == "face") e.triangles += element.count;
        if (element.name == "vertex") e.corners += element.count;
    }
    e.corners += 3 * e.triangles;
    return e;
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

} // namespace

std::optional<ModelLoader::ImportEstimate> ModelLoader::estimateImport(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
    const uint64_t fileSize = std::filesystem::file_size(path, ec);
    const std::string ext = lowerExtension(path);
    std::optional<ImportEstimate> e;
    if (ext == ".stl")
        e = countStl(path, fileSize);
    else if (ext == ".obj")
        e = countObj(path);
    else if (ext == ".ply")
        e = countPly(path);
    if (!e) return std::nullopt;
    // Multiplied in double and capped: a hostile count times the per-corner bytes must not wrap.
    e->bytes = uint64_t(std::min(1e19, double(e->corners) * double(kImportBytesPerCorner) + double(fileSize) +
                                           double(e->bytes)));
    return e;
}

std::optional<ModelUp> parseModelUp(const std::string& text) {
    return kUps.parse(text);
}

const char* modelUpName(ModelUp up) {
    return kUps.name(up, "y");
}

std::string modelUpChoices() {
    return kUps.choices();
}

glm::mat3 ModelLoader::rotationToYUp(ModelUp up) {
    // Columns are the images of the x, y and z axes (glm is column-major).
    switch (up) {
    case ModelUp::PosX:
        return {{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}; // +90 degrees about Z
    case ModelUp::NegX:
        return {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}; // -90 degrees about Z
    case ModelUp::PosY:
        return glm::mat3(1.0f);
    case ModelUp::NegY:
        return {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}}; // 180 degrees about X
    case ModelUp::PosZ:
        return {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}; // -90 degrees about X
    case ModelUp::NegZ:
        return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}; // +90 degrees about X
    }
    return glm::mat3(1.0f);
}

std::vector<Mesh> ModelLoader::loadObjects(const std::string& path, std::optional<ModelUp> up) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
    checkPlyComplete(path);
    Assimp::Importer importer;
    // ValidateDataStructure runs before the other steps: a face index beyond the vertices (a hostile
    // PLY, a truncated binary one) crashed inside them; the validation refuses it with a reason.
    const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                           aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
        fail(path, importer.GetErrorString()[0] ? importer.GetErrorString() : "cannot be read");
    // 3DS: the root node's transform is assimp's fixed Z-up rotation, not part of the file: dropped.
    const bool asStored = isThreeDs(*scene, path);
    if (!up) up = metadataUp(*scene);
    const glm::mat4 toYUp(rotationToYUp(up.value_or(ModelUp::PosY)));
    const glm::mat4 root = asStored ? glm::mat4(1.0f) : toGlm(scene->mRootNode->mTransformation);
    std::vector<Mesh> objects;
    Mesh rootObject = buildObject(*scene, *scene->mRootNode, toYUp * root, 0);
    if (!rootObject.indices.empty()) objects.push_back(std::move(rootObject));
    for (unsigned c = 0; c < scene->mRootNode->mNumChildren; ++c)
        collectObjects(*scene, *scene->mRootNode->mChildren[c], toYUp * root, objects);
    if (objects.empty()) fail(path, "contains no triangles");
    checkFinite(path, *scene, objects);
    checkBounded(path, objects);
    checkNotDegenerate(path, objects);
    return objects;
}

Mesh ModelLoader::load(const std::string& path, std::optional<ModelUp> up) {
    return join(loadObjects(path, up), std::filesystem::path(path).stem().string());
}

Mesh ModelLoader::join(const std::vector<Mesh>& objects, const std::string& name) {
    Mesh joined;
    joined.name = name;
    for (const Mesh& object : objects) {
        const uint32_t base = uint32_t(joined.positions.size()), firstIndex = uint32_t(joined.indices.size());
        joined.positions.insert(joined.positions.end(), object.positions.begin(), object.positions.end());
        joined.normals.insert(joined.normals.end(), object.normals.begin(), object.normals.end());
        for (uint32_t i : object.indices) joined.indices.push_back(base + i);
        for (MeshPart part : object.parts) {
            part.firstIndex += firstIndex;
            joined.parts.push_back(part);
        }
    }
    return joined;
}

} // namespace sb
