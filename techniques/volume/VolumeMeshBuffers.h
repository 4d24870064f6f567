#pragma once
// GPU side of `volume`'s casters, built once per scene (untimed): per caster mesh its
// ShadowVolumeMesh (welded, with adjacency), the doubled vertex buffer (w = 1 and w = 0 copies) in a
// VAO whose element buffer is one shared stream buffer that the CPU path refills every frame, and the
// McGuire-Hughes extrusion mesh (positions + face planes, caps then sides in a static index buffer)
// for the vertex-shader path; for the GPU silhouette paths, the faces as triangles with adjacency
// (extrusion=geometry: 6 vertices per face, each with the normal and first vertex of the face it stands
// for, see shaders/volume/silhouette.geom) or as a storage buffer of faces with their neighbours
// (extrusion=compute, shaders/volume/silhouette.comp).
#include <memory>
#include <vector>

#include <epoxy/gl.h>

#include "scenes/Scene.h"
#include "techniques/volume/ShadowVolumeMesh.h"

namespace sb {

class VolumeMeshBuffers {
public:
    struct Gpu {
        std::unique_ptr<ShadowVolumeMesh> mesh; ///< null for meshes no caster uses
        GLuint doubledVao = 0, doubledVbo = 0;
        GLuint extrusionVao = 0, extrusionVbo = 0, extrusionIbo = 0;
        GLsizei extrusionCapIndices = 0, extrusionSideIndices = 0; ///< sides start after the caps
        GLuint adjacencyVao = 0, adjacencyVbo = 0; ///< extrusion=geometry: 6 vertices per face
        GLuint faceBuffer = 0;                     ///< extrusion=compute: 96 bytes per face (SilhouetteFace)
    };
    /// Which forms upload() builds besides the doubled buffer.
    struct Forms {
        bool extrusion = false; ///< the McGuire-Hughes mesh (extrusion=vertex)
        bool adjacency = false; ///< triangles with adjacency (extrusion=geometry)
        bool faces = false;     ///< the face storage buffer (extrusion=compute)
    };

    VolumeMeshBuffers() = default;
    ~VolumeMeshBuffers();
    VolumeMeshBuffers(const VolumeMeshBuffers&) = delete;
    VolumeMeshBuffers& operator=(const VolumeMeshBuffers&) = delete;

    /// Prepares every mesh a shadow-casting instance uses, with `forms`; the vertex-shader mesh is
    /// built for `policy` (two sheets for open meshes under multiplicity).
    void upload(const Scene& scene, Forms forms, OpenEdgePolicy policy);
    const Gpu& mesh(size_t index) const { return mMeshes[index]; }
    size_t size() const { return mMeshes.size(); }

    /// Replaces the stream buffer's contents (orphaning: the driver may keep the old storage for
    /// draws still in flight) and returns nothing to wait on.
    void streamIndices(const std::vector<uint32_t>& indices);

private:
    void release();
    std::vector<Gpu> mMeshes;
    GLuint mStream = 0;
    size_t mStreamCapacity = 0;
};

} // namespace sb
