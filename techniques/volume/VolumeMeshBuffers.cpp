#include "techniques/volume/VolumeMeshBuffers.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace sb {

VolumeMeshBuffers::~VolumeMeshBuffers() {
    release();
}

void VolumeMeshBuffers::release() {
    for (Gpu& g : mMeshes) {
        glDeleteVertexArrays(1, &g.doubledVao);
        glDeleteBuffers(1, &g.doubledVbo);
        glDeleteVertexArrays(1, &g.extrusionVao);
        glDeleteBuffers(1, &g.extrusionVbo);
        glDeleteBuffers(1, &g.extrusionIbo);
        glDeleteVertexArrays(1, &g.adjacencyVao);
        glDeleteBuffers(1, &g.adjacencyVbo);
        glDeleteBuffers(1, &g.faceBuffer);
    }
    mMeshes.clear();
    if (mStream) glDeleteBuffers(1, &mStream);
    mStream = 0;
    mStreamCapacity = 0;
}

namespace {

void uploadDoubled(VolumeMeshBuffers::Gpu& g, GLuint stream) {
    const std::vector<glm::vec4> vertices = g.mesh->doubledVertices();
    glCreateVertexArrays(1, &g.doubledVao);
    glCreateBuffers(1, &g.doubledVbo);
    glNamedBufferStorage(g.doubledVbo, GLsizeiptr(vertices.size() * sizeof(glm::vec4)), vertices.data(), 0);
    glVertexArrayVertexBuffer(g.doubledVao, 0, g.doubledVbo, 0, GLsizei(sizeof(glm::vec4)));
    glEnableVertexArrayAttrib(g.doubledVao, 0);
    glVertexArrayAttribFormat(g.doubledVao, 0, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(g.doubledVao, 0, 0);
    glVertexArrayElementBuffer(g.doubledVao, stream);
}

void uploadExtrusion(VolumeMeshBuffers::Gpu& g, OpenEdgePolicy policy) {
    const ExtrusionMesh m = g.mesh->buildExtrusionMesh(policy);
    // Interleaved (x, y, z, 1) position and (N, dot(N, P0)) plane: 32 bytes, two aligned vec4 loads.
    std::vector<glm::vec4> interleaved;
    interleaved.reserve(m.positions.size() * 2);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        interleaved.push_back(glm::vec4(m.positions[i], 1.0f));
        interleaved.push_back(m.facePlanes[i]);
    }
    std::vector<uint32_t> indices = m.capIndices;
    indices.insert(indices.end(), m.sideIndices.begin(), m.sideIndices.end());
    glCreateVertexArrays(1, &g.extrusionVao);
    glCreateBuffers(1, &g.extrusionVbo);
    glCreateBuffers(1, &g.extrusionIbo);
    glNamedBufferStorage(g.extrusionVbo,
                         GLsizeiptr(std::max<size_t>(1, interleaved.size()) * sizeof(glm::vec4)),
                         interleaved.data(), 0);
    glNamedBufferStorage(g.extrusionIbo, GLsizeiptr(std::max<size_t>(1, indices.size()) * sizeof(uint32_t)),
                         indices.data(), 0);
    glVertexArrayVertexBuffer(g.extrusionVao, 0, g.extrusionVbo, 0, GLsizei(2 * sizeof(glm::vec4)));
    glVertexArrayElementBuffer(g.extrusionVao, g.extrusionIbo);
    for (GLuint a : {0u, 1u}) {
        glEnableVertexArrayAttrib(g.extrusionVao, a);
        glVertexArrayAttribFormat(g.extrusionVao, a, a == 0 ? 3 : 4, GL_FLOAT, GL_FALSE,
                                  GLuint(a * sizeof(glm::vec4)));
        glVertexArrayAttribBinding(g.extrusionVao, a, 0);
    }
    g.extrusionCapIndices = GLsizei(m.capIndices.size());
    g.extrusionSideIndices = GLsizei(m.sideIndices.size());
}

/// The face across each directed edge, or the face itself where there is none (an open edge: the
/// face then sees itself across it and never builds a side there).
uint32_t across(const std::vector<uint32_t>& neighbours, size_t face, size_t k) {
    const uint32_t other = neighbours[3 * face + k];
    return other == ShadowVolumeMesh::kNoFace ? uint32_t(face) : other;
}

void uploadAdjacency(VolumeMeshBuffers::Gpu& g) {
    // Per face 6 vertices of 3 vec4 (position w = 1, normal, first vertex): slot 2k its vertex k with
    // its own face's data, slot 2k + 1 the vertex of the face across edge (k, k + 1) that is not on
    // the edge, with that face's data (GL_TRIANGLES_ADJACENCY's layout).
    const ShadowVolumeMesh& m = *g.mesh;
    const std::vector<uint32_t> neighbours = m.neighbours();
    const std::vector<uint32_t>& faces = m.faces();
    const std::vector<glm::vec3>& p = m.positions();
    auto faceData = [&](std::vector<glm::vec4>& out, uint32_t vertex, size_t face) {
        out.emplace_back(p[vertex], 1.0f);
        out.emplace_back(m.faceNormals()[face], 0.0f);
        out.emplace_back(p[faces[3 * face]], 1.0f);
    };
    std::vector<glm::vec4> data;
    data.reserve(m.faceCount() * 18);
    for (size_t f = 0; f < m.faceCount(); ++f)
        for (size_t k = 0; k < 3; ++k) {
            faceData(data, faces[3 * f + k], f);
            const uint32_t other = across(neighbours, f, k);
            const uint32_t a = faces[3 * f + k], b = faces[3 * f + (k + 1) % 3];
            uint32_t opposite = faces[3 * other];
            for (size_t j = 0; j < 3; ++j)
                if (faces[3 * other + j] != a && faces[3 * other + j] != b) opposite = faces[3 * other + j];
            faceData(data, opposite, other);
        }
    glCreateVertexArrays(1, &g.adjacencyVao);
    glCreateBuffers(1, &g.adjacencyVbo);
    glNamedBufferStorage(g.adjacencyVbo, GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(glm::vec4)),
                         data.data(), 0);
    glVertexArrayVertexBuffer(g.adjacencyVao, 0, g.adjacencyVbo, 0, GLsizei(3 * sizeof(glm::vec4)));
    for (GLuint a : {0u, 1u, 2u}) {
        glEnableVertexArrayAttrib(g.adjacencyVao, a);
        glVertexArrayAttribFormat(g.adjacencyVao, a, 4, GL_FLOAT, GL_FALSE, GLuint(a * sizeof(glm::vec4)));
        glVertexArrayAttribBinding(g.adjacencyVao, a, 0);
    }
}

void uploadFaces(VolumeMeshBuffers::Gpu& g) {
    // shaders/volume/silhouette.comp's Face: uvec4 vertices, uvec4 neighbours, vec4 normal, vec4 first.
    const ShadowVolumeMesh& m = *g.mesh;
    const std::vector<uint32_t> neighbours = m.neighbours();
    const std::vector<uint32_t>& faces = m.faces();
    struct Face {
        glm::uvec4 vertices, neighbours;
        glm::vec4 normal, first;
    };
    std::vector<Face> data(m.faceCount());
    for (size_t f = 0; f < m.faceCount(); ++f) {
        data[f].vertices = {faces[3 * f], faces[3 * f + 1], faces[3 * f + 2], 0u};
        data[f].neighbours = {across(neighbours, f, 0), across(neighbours, f, 1), across(neighbours, f, 2),
                              0u};
        data[f].normal = glm::vec4(m.faceNormals()[f], 0.0f);
        data[f].first = glm::vec4(m.positions()[faces[3 * f]], 1.0f);
    }
    glCreateBuffers(1, &g.faceBuffer);
    glNamedBufferStorage(g.faceBuffer, GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(Face)),
                         data.data(), 0);
}

} // namespace

void VolumeMeshBuffers::setElementBuffer(GLuint buffer) {
    for (Gpu& g : mMeshes)
        if (g.doubledVao) glVertexArrayElementBuffer(g.doubledVao, buffer);
}

void VolumeMeshBuffers::upload(const Scene& scene, Forms forms, OpenEdgePolicy policy) {
    release();
    glCreateBuffers(1, &mStream);
    mMeshes.resize(scene.meshes.size());
    std::vector<bool> casts(scene.meshes.size(), false);
    for (const Instance& inst : scene.instances)
        if (inst.castsShadow) casts[inst.mesh] = true;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (!casts[i]) continue;
        Gpu& g = mMeshes[i];
        g.mesh = std::make_unique<ShadowVolumeMesh>(scene.meshes[i]);
        uploadDoubled(g, mStream);
        if (forms.extrusion) uploadExtrusion(g, policy);
        if (forms.adjacency) uploadAdjacency(g);
        if (forms.faces) uploadFaces(g);
    }
}

void VolumeMeshBuffers::streamIndices(const std::vector<uint32_t>& indices) {
    const size_t bytes = std::max<size_t>(indices.size(), 1) * sizeof(uint32_t);
    if (bytes > mStreamCapacity) {
        // Grow geometrically so a frame with a few more silhouette edges does not reallocate.
        mStreamCapacity = std::max(bytes, mStreamCapacity * 2);
        glNamedBufferData(mStream, GLsizeiptr(mStreamCapacity), nullptr, GL_STREAM_DRAW);
    } else {
        glInvalidateBufferData(mStream); // orphan: no wait on last frame's draws
    }
    glNamedBufferSubData(mStream, 0, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data());
}

} // namespace sb
