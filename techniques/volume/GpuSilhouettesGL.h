#pragma once
// The device side of `volume`'s GPU silhouette paths on GL (extrusion=geometry and compute), beside
// VolumeGL's CPU and vertex paths:
//  - the frame's volume triangle count, one atomic uint the geometry or compute shader adds to, cleared
//    at the start of each frame and read back only when the counters are asked for (after the measured
//    frames, untimed): no measured frame waits on it, and the count is the last frame's, exactly;
//  - extrusion=compute: per light, one dispatch per caster (shaders/volume/silhouette.comp) writes the
//    caster's volume as the doubled entries of its vertices into its region of one buffer and their
//    number into its indirect command; the marking pass then draws each with glDrawArraysIndirect, the
//    vertex shader fetching each vertex's entry (no indices: the order the device builds in changes no
//    count).
#include <vector>

#include <epoxy/gl.h>

#include "gl/ProgramCache.h"
#include "techniques/volume/VolumeMeshBuffers.h"
#include "techniques/volume/VolumePlanner.h"

namespace sb {

class GpuSilhouettesGL {
public:
    GpuSilhouettesGL() = default;
    ~GpuSilhouettesGL();
    GpuSilhouettesGL(const GpuSilhouettesGL&) = delete;
    GpuSilhouettesGL& operator=(const GpuSilhouettesGL&) = delete;

    /// Creates the buffers (needs a context); with `compute` also the compute path's output and an
    /// empty vertex array to draw with.
    void create(bool compute);
    /// Clears the count for this frame.
    void beginFrame();
    /// Binds the count at storage binding 0 (the geometry shader's, before its draws).
    void bindCount() const;
    /// The volume triangles of the last frame, read back from the device (waits for it to finish:
    /// for counters(), after the measured frames).
    double readTriangles() const;

    /// extrusion=compute: builds every draw's volume for the current light with `program`
    /// (shaders/volume/silhouette.comp) and leaves the commands bound for drawIndirect().
    void extract(const std::vector<VolumePlanner::Draw>& draws, const VolumeMeshBuffers& buffers,
                 const Program& program);
    /// The vertex array of the marking draws (extrusion=compute): no attributes.
    GLuint vertexArray() const { return mVao; }
    /// Binds caster mesh buffer `doubled` where volume/extrude.vert under PULLED fetches from.
    void bindCaster(GLuint doubled) const;
    /// Draw `i` of the last extract(), with vertexArray() bound and its caster's bindCaster().
    void drawIndirect(size_t i) const;

private:
    void release();
    /// Grows `buffer` (capacity in bytes) to `bytes` at least, contents undefined.
    static void reserve(GLuint buffer, size_t& capacity, size_t bytes);

    GLuint mCount = 0;
    GLuint mVertices = 0, mCommands = 0, mVao = 0;
    size_t mVertexCapacity = 0, mCommandCapacity = 0;
    std::vector<uint32_t> mCommandData; ///< per-frame scratch: the commands' initial values
};

} // namespace sb
