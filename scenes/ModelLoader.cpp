#include "scenes/ModelLoader.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

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

} // namespace

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
    Assimp::Importer importer;
    const unsigned flags =
        aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices;
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
