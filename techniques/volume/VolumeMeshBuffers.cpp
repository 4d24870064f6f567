#include "techniques/volume/VolumeMeshBuffers.h"

#include <algorithm>

#include <glm/glm.hpp>

#include "techniques/volume/SilhouetteInputs.h"

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

void uploadAdjacency(VolumeMeshBuffers::Gpu& g) {
    const std::vector<glm::vec4> data = SilhouetteInputs::adjacencyVertices(*g.mesh);
    constexpr GLsizei kStride = SilhouetteInputs::kVec4PerVertex * sizeof(glm::vec4);
    glCreateVertexArrays(1, &g.adjacencyVao);
    glCreateBuffers(1, &g.adjacencyVbo);
    glNamedBufferStorage(g.adjacencyVbo, GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(glm::vec4)),
                         data.data(), 0);
    glVertexArrayVertexBuffer(g.adjacencyVao, 0, g.adjacencyVbo, 0, kStride);
    for (GLuint a = 0; a < GLuint(SilhouetteInputs::kVec4PerVertex); ++a) {
        glEnableVertexArrayAttrib(g.adjacencyVao, a);
        glVertexArrayAttribFormat(g.adjacencyVao, a, 4, GL_FLOAT, GL_FALSE, GLuint(a * sizeof(glm::vec4)));
        glVertexArrayAttribBinding(g.adjacencyVao, a, 0);
    }
}

void uploadFaces(VolumeMeshBuffers::Gpu& g) {
    const std::vector<SilhouetteFace> data = SilhouetteInputs::faces(*g.mesh);
    glCreateBuffers(1, &g.faceBuffer);
    glNamedBufferStorage(g.faceBuffer, GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(SilhouetteFace)),
                         data.data(), 0);
}

} // namespace

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
