#pragma once
// A process-wide memo of the occluder technique's two dear pure functions of a mesh: the automatic
// choice of its shadow planes (ShadowPlaneChooser::choose, scenes/ShadowPlaneChooser.h) and the texels
// of each plane's baked occluder texture (OccluderTextures::bake, read back and bordered by
// OccluderGL). Both are set-up work that OccluderGL repeats whenever it is set up again on the same
// meshes, which a process that runs it many times does: the golden matrix (every submission mode) and
// the shader permutations test (2751 set-ups: about 60 ms of choosing and 10 ms of baking at the
// default resolution, 1.8 s at 8192 texels). Nothing about what the technique draws or compiles
// changes: a hit returns what the computation returned for the same inputs.
//
// Entries are matched on their full inputs compared bit for bit, never on a hash alone: the mesh's
// name, positions, indices and parts (normals are read by neither), and the rest of the inputs as a
// byte string the caller builds (chooser: light directions and plane limit; bake: the plane, the bake
// options and the GL renderer that rasterised it). Least recently used entries go first once the
// entries hold more than maxBytes() (256 MiB; a mesh shared by several entries is counted in each, so
// the count errs high).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/ShadowPlaneChooser.h"

namespace sb {

class OccluderMeshCache {
public:
    using Texels = std::shared_ptr<const std::vector<uint8_t>>;

    /// ShadowPlaneChooser::choose(mesh, towardLight, maxPlanes), computed once per distinct input.
    static ShadowPlaneChoice choose(const Mesh& mesh, const std::vector<glm::vec3>& towardLight,
                                    int maxPlanes);
    /// The texels `bake` returns for (mesh, key), calling it once per distinct input; `key` names
    /// every other input of the bake (OccluderGL builds it from the plane, the options and the
    /// renderer). An exception from `bake` (or from choose()) propagates and nothing is stored.
    static Texels texels(const Mesh& mesh, const std::string& key,
                         const std::function<std::vector<uint8_t>()>& bake);

    /// Lookups answered from memory (hits) and computed (misses), per kind, since the start or clear().
    struct Stats {
        size_t choiceHits = 0, choiceMisses = 0, texelHits = 0, texelMisses = 0;
        size_t entries = 0, bytes = 0; ///< held now
    };
    static Stats stats();
    /// Forgets every entry and zeroes the statistics.
    static void clear();
    /// The most bytes the entries may hold (default 256 MiB); lowering it evicts at once. For tests.
    static void setMaxBytes(size_t bytes);
    static size_t maxBytes();
};

} // namespace sb
