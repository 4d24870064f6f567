#include "scenes/ModelLoader.h"

#include <filesystem>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/Error.h"

namespace sb {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("model file '" + path + "': " + why);
}

/// Appends the triangles of one assimp mesh. PreTransformVertices has already applied the node
/// transforms; Triangulate leaves points and lines as 1- and 2-index faces, which are skipped.
void appendMesh(Mesh& out, const aiMesh& in) {
    const uint32_t base = uint32_t(out.positions.size());
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
        const aiVector3D& p = in.mVertices[v];
        out.positions.emplace_back(p.x, p.y, p.z);
        glm::vec3 n(0.0f, 1.0f, 0.0f);
        if (in.mNormals) n = glm::vec3(in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z);
        // GenSmoothNormals can leave zero normals on degenerate faces; Mesh promises unit normals.
        const float len = glm::length(n);
        out.normals.push_back(len > 1e-20f && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0));
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
        const aiFace& face = in.mFaces[f];
        if (face.mNumIndices != 3) continue;
        for (int k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
    }
}

} // namespace

Mesh ModelLoader::load(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
    Assimp::Importer importer;
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                           aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
        fail(path, importer.GetErrorString()[0] ? importer.GetErrorString() : "cannot be read");
    Mesh mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        // Each assimp mesh (an OBJ group or object, a glTF primitive ...) becomes a named part, so a
        // scene file can refer to it (occluder planes bake their texture from named parts). Unnamed
        // ones get "part<N>"; PreTransformVertices may already have joined meshes sharing a material.
        const aiMesh& in = *scene->mMeshes[m];
        MeshPart part;
        part.name = in.mName.length ? std::string(in.mName.C_Str()) : "part" + std::to_string(m);
        part.firstIndex = uint32_t(mesh.indices.size());
        appendMesh(mesh, in);
        part.indexCount = uint32_t(mesh.indices.size()) - part.firstIndex;
        if (part.indexCount) mesh.parts.push_back(part);
    }
    if (mesh.indices.empty()) fail(path, "contains no triangles");
    return mesh;
}

} // namespace sb
