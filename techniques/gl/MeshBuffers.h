#pragma once
// GPU copies of a scene's meshes: one VAO per mesh with an interleaved position+normal VBO (location 0
// and 1; the stream of techniques/SubmissionPlan.h's interleavedVertices) and an index buffer. Shared by
// the retained and instanced submitters.
#include <vector>

#include <epoxy/gl.h>

#include "scenes/Scene.h"

namespace sb {

class MeshBuffers {
public:
    MeshBuffers() = default;
    ~MeshBuffers();
    MeshBuffers(const MeshBuffers&) = delete;
    MeshBuffers& operator=(const MeshBuffers&) = delete;

    void upload(const Scene& scene);
    GLuint vao(size_t mesh) const { return mMeshes[mesh].vao; }
    GLsizei indexCount(size_t mesh) const { return mMeshes[mesh].indexCount; }

private:
    struct Gpu {
        GLuint vao = 0, vbo = 0, ibo = 0;
        GLsizei indexCount = 0;
    };
    void release();
    std::vector<Gpu> mMeshes;
};

} // namespace sb
