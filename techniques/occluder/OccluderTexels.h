#pragma once
// The API-neutral half of occluder textures (techniques/occluder/OccluderTextures.h has the GL half):
// the bake's options, the dilation every bake applies, and the exchange with PNG files, all on texels
// in memory: one 8-bit channel, 0 = occluder (black), 255 = clear (white), row 0 = v near 0.
#include <cstdint>
#include <string>
#include <vector>

#include "scenes/Mesh.h"
#include "scenes/ShadowPlane.h"

namespace sb {

struct OccluderBakeOptions {
    int resolution = 512; ///< texels per side, [1, 16384]
    /// Grow the occluder by this many texels: a min filter over a (2k+1)^2 square (thesis section 5:
    /// raster silhouettes never match the geometric edge exactly). [0, resolution].
    int dilate = 1;
    /// Also mark black where the plane lies inside the whole mesh's solid (all parts, not only the
    /// plane's): the non-zero winding number of the plane point with respect to the mesh. Needs a closed,
    /// consistently wound mesh (overlapping closed parts, as the aircraft's, are fine).
    bool crossSection = true;
    /// Draw the triangles of plane.parts (the silhouette). false: the cross-section alone (tests, and
    /// planes that stand for a solid's section only).
    bool silhouette = true;
};

struct OccluderTexels {
    /// Throws sb::Error naming the plane for an invalid plane, resolution or dilation, or a mesh whose
    /// index count is not a multiple of 3 (what every bake checks first).
    static void validate(const Mesh& mesh, const ShadowPlane& plane, const OccluderBakeOptions& options);
    /// The index ranges plane.parts names (the whole mesh when empty); throws sb::Error naming the
    /// plane and the mesh's parts for an unknown part.
    static std::vector<MeshPart> parts(const Mesh& mesh, const ShadowPlane& plane);
    /// The (2k+1)^2 min filter a bake applies (clamped at the border): rows, then columns.
    static std::vector<uint8_t> dilate(const std::vector<uint8_t>& texels, int width, int height, int k);
    /// A PNG file's texels (OccluderTextures::load documents the conversion); width and height out.
    /// Throws sb::Error naming the file and what was wrong (missing, not a PNG, corrupt).
    static std::vector<uint8_t> load(const std::string& path, int& width, int& height);
    /// Writes width x height texels (row 0 = v near 0) as a grey PNG, top row = v near 1, so
    /// load(write(x)) round-trips exactly. Throws sb::Error (ExitCode::Failure) naming the file on
    /// failure, BadInput for a size mismatch.
    static void write(const std::string& path, const std::vector<uint8_t>& texels, int width, int height);
};

} // namespace sb
