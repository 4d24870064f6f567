#include "techniques/volume/SilhouetteInputs.h"

namespace sb {

namespace {

uint32_t across(const std::vector<uint32_t>& neighbours, size_t face, size_t k) {
    const uint32_t other = neighbours[3 * face + k];
    return other == ShadowVolumeMesh::kNoFace ? uint32_t(face) : other;
}

} // namespace

std::vector<glm::vec4> SilhouetteInputs::adjacencyVertices(const ShadowVolumeMesh& mesh) {
    const std::vector<uint32_t> neighbours = mesh.neighbours();
    const std::vector<uint32_t>& faces = mesh.faces();
    const std::vector<glm::vec3>& p = mesh.positions();
    std::vector<glm::vec4> out;
    out.reserve(mesh.faceCount() * kVerticesPerFace * kVec4PerVertex);
    auto vertex = [&](uint32_t v, size_t face) {
        out.emplace_back(p[v], 1.0f);
        out.emplace_back(mesh.faceNormals()[face], 0.0f);
        out.emplace_back(p[faces[3 * face]], 1.0f);
    };
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < 3; ++k) {
            vertex(faces[3 * f + k], f);
            const uint32_t other = across(neighbours, f, k);
            const uint32_t a = faces[3 * f + k], b = faces[3 * f + (k + 1) % 3];
            uint32_t opposite = faces[3 * other];
            for (size_t j = 0; j < 3; ++j)
                if (faces[3 * other + j] != a && faces[3 * other + j] != b) opposite = faces[3 * other + j];
            vertex(opposite, other);
        }
    return out;
}

std::vector<SilhouetteFace> SilhouetteInputs::faces(const ShadowVolumeMesh& mesh) {
    const std::vector<uint32_t> neighbours = mesh.neighbours();
    const std::vector<uint32_t>& faces = mesh.faces();
    std::vector<SilhouetteFace> out(mesh.faceCount());
    for (size_t f = 0; f < out.size(); ++f) {
        out[f].vertices = {faces[3 * f], faces[3 * f + 1], faces[3 * f + 2], 0u};
        out[f].neighbours = {across(neighbours, f, 0), across(neighbours, f, 1), across(neighbours, f, 2),
                             0u};
        out[f].normal = glm::vec4(mesh.faceNormals()[f], 0.0f);
        out[f].first = glm::vec4(mesh.positions()[faces[3 * f]], 1.0f);
    }
    return out;
}

} // namespace sb
