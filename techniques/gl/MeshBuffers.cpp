#include "techniques/gl/MeshBuffers.h"

#include <glm/glm.hpp>

#include "techniques/SubmissionPlan.h"

namespace sb {

MeshBuffers::~MeshBuffers() {
    release();
}

void MeshBuffers::release() {
    for (Gpu& g : mMeshes) {
        glDeleteVertexArrays(1, &g.vao);
        glDeleteBuffers(1, &g.vbo);
        glDeleteBuffers(1, &g.ibo);
    }
    mMeshes.clear();
}

void MeshBuffers::upload(const Scene& scene) {
    release();
    for (const Mesh& mesh : scene.meshes) {
        const std::vector<glm::vec3> interleaved = interleavedVertices(mesh);
        Gpu g;
        glCreateVertexArrays(1, &g.vao);
        glCreateBuffers(1, &g.vbo);
        glCreateBuffers(1, &g.ibo);
        glNamedBufferStorage(g.vbo, GLsizeiptr(interleaved.size() * sizeof(glm::vec3)), interleaved.data(),
                             0);
        glNamedBufferStorage(g.ibo, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                             0);
        glVertexArrayVertexBuffer(g.vao, 0, g.vbo, 0, GLsizei(kVertexStride));
        glVertexArrayElementBuffer(g.vao, g.ibo);
        glEnableVertexArrayAttrib(g.vao, 0);
        glEnableVertexArrayAttrib(g.vao, 1);
        glVertexArrayAttribFormat(g.vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribFormat(g.vao, 1, 3, GL_FLOAT, GL_FALSE, GLuint(kNormalOffset));
        glVertexArrayAttribBinding(g.vao, 0, 0);
        glVertexArrayAttribBinding(g.vao, 1, 0);
        g.indexCount = GLsizei(mesh.indices.size());
        mMeshes.push_back(g);
    }
}

} // namespace sb
