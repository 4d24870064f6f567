#pragma once
// Occluder textures of the occluder-texture technique (Coleman, "Fast Self-Shadowing Using Occluder
// Textures", sections 4.3 and 5): one 8-bit channel over a shadow plane's [0, 1]^2, 0 = occluder
// (black), 255 = clear (white); row 0 is v near 0, so texel (i, j) covers uv around
// ((i + 0.5) / w, (j + 0.5) / h).
//
// bake() automates what the thesis left to an artist (its future work): "render an orthographic view of
// the portion of the model pertinent to the occluder texture ... black on a white background", plus the
// two hand edits of section 5, done geometrically:
//  - the cross-section: where the plane lies inside the mesh's solid it is marked black too, which is
//    what extending the fin's silhouette "down into the object" achieved by hand;
//  - dilation: the silhouette is grown by a few texels, because a raster edge never matches the
//    floating-point geometric edge and shadows must reach the caster.
// load() and write() exchange the same format with PNG files (core/PngFile).
#include <cstdint>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "gl/ProgramCache.h"
#include "scenes/Mesh.h"
#include "scenes/ShadowPlane.h"
#include "techniques/occluder/OccluderTexels.h"

namespace sb {

/// Free functions: baking, image I/O and read-back of occluder textures. Every function needs a current
/// GL context (except write()).
struct OccluderTextures {
    /// Bakes `plane`'s occluder texture from `mesh`: the orthographic projection along plane.normal of
    /// the triangles of plane.parts (the whole mesh when empty), u = right.(p - origin) / width,
    /// v = up.(p - origin) / height (equation 8), black on white; then the cross-section and dilation
    /// of `options`. Returns a new GL_R8 texture (the caller deletes it), resolution^2, 0 = occluder,
    /// 255 = clear, GL_LINEAR filtering, GL_CLAMP_TO_EDGE. Throws sb::Error naming the plane for an
    /// invalid plane or options, or a part name the mesh does not have. Leaves the GL state as found
    /// (gl/GlStateGuard.h: viewport, bindings, enables, masks, stencil state).
    static GLuint bake(ProgramCache& programs, const Mesh& mesh, const ShadowPlane& plane,
                       const OccluderBakeOptions& options);
    /// Asks `programs` for the programs bake() draws with (compiling them there if new), as bake() does
    /// first: a caller that reuses texels an earlier bake made calls it, so the program cache and its
    /// dump (--dump-shaders) see the same programs whether or not it baked.
    static void requestPrograms(ProgramCache& programs);
    /// Loads a PNG file into the same format: the first channel of grey or grey+alpha images; for three
    /// or more channels the Rec. 709 luma of the stored (encoded) values,
    /// round(0.2126 R + 0.7152 G + 0.0722 B); alpha ignored; 16-bit data scaled to 8 bits;
    /// flipped so the image's bottom-left corner (as viewed) is uv (0, 0). Throws sb::Error naming the
    /// file and what was wrong (missing, not a PNG, corrupt).
    static GLuint load(const std::string& path);
    /// Reads level 0 of an R8 texture back: width * height bytes, row 0 = v near 0.
    static std::vector<uint8_t> readBack(GLuint texture, int& width, int& height);
    /// Writes width x height 8-bit single-channel texels (row 0 = v near 0) as a grey PNG, top row =
    /// v near 1, so load(write(x)) round-trips exactly.
    /// Throws sb::Error (ExitCode::Failure) naming the file on failure, BadInput for a size mismatch.
    static void write(const std::string& path, const std::vector<uint8_t>& texels, int width, int height) {
        OccluderTexels::write(path, texels, width, height);
    }
    /// The (2k+1)^2 min filter bake() applies (OccluderTexels::dilate), exposed for tests.
    static std::vector<uint8_t> dilate(const std::vector<uint8_t>& texels, int width, int height, int k) {
        return OccluderTexels::dilate(texels, width, height, k);
    }
};

} // namespace sb
