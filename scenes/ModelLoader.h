#pragma once
// Model files through assimp (--model path.obj|.gltf|.glb|.3ds|.ply ..., a scene file's "file" mesh):
// triangulated, normals generated where missing, node transforms applied, Y up, every vertex finite.
//
// Objects: each node of the file that carries triangles (an OBJ `o` or `g`, a 3DS object, a glTF
// node) is one object; its assimp meshes (one per material) are its named parts. loadObjects keeps
// the objects apart, so every object is its own caster (one proxy, one blob each); load joins them.
//
// Up axis: the geometry comes out Y-up. The file's up axis is, in order: the caller's `up`; the
// file's own "UpAxis"/"UpAxisSign" metadata (FBX); otherwise the coordinates as read. The 3DS format
// stores no up axis; assimp rotates every 3DS file by -90 degrees about X (3ds Max's Z-up), but the
// 3DS files this benchmark is run with (glmark2's horse, cat, asteroids and cube; assimp's test1.3ds)
// are Y-up as stored, and that rotation laid them on their side, so a 3DS file is read as stored
// (give `up` = +Z for a Z-up 3DS export).
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"

namespace sb {

/// The axis that is up in a model file's coordinates: "x", "-x", "y", "-y", "z", "-z" in scene files
/// and on the command line.
enum class ModelUp { PosX, NegX, PosY, NegY, PosZ, NegZ };
std::optional<ModelUp> parseModelUp(const std::string& text);
const char* modelUpName(ModelUp up);
std::string modelUpChoices(); ///< "x, -x, y, -y, z or -z"

class ModelLoader {
public:
    /// The largest |coordinate| a model vertex (after the file's node transforms) may have, and the
    /// scene loader's bound on world-space points. Techniques square distances in float (lengths,
    /// normalisation, light fits): with every coordinate within 1e18 a difference is within 2e18 and a
    /// squared length within 1.2e37, below FLT_MAX (3.4e38) with a margin for further products; a
    /// 3e38 coordinate is finite but turns every length through it into inf. No real model or scene
    /// comes near (metres from the Planck length to light years fit well inside).
    static constexpr double kMaxCoordinate = 1e18;

    /// What importing a file will cost, known before it is read: `corners` are the vertices assimp
    /// makes before it welds them (one per face corner in STL, OBJ and PLY), `bytes` the importer's
    /// peak for them (kImportBytesPerCorner each, measured), the file's own bytes and an OBJ file's
    /// positions (24 B each). Binary STL: the
    /// triangle count at byte 80, which must match the file's size (84 + 50 per triangle; a truncated
    /// or lying header is refused, naming both); ASCII STL: its "vertex" lines; OBJ: the corners of
    /// its "f" lines; PLY: the header's face (three corners each) and vertex counts. Each read in one
    /// streamed pass, never the whole file at once. Other formats: nothing (their cost is known after
    /// the import, from what it made).
    struct ImportEstimate {
        uint64_t triangles = 0;
        uint64_t corners = 0;
        uint64_t bytes = 0;
    };
    /// Bytes assimp holds per vertex it makes (as measured at peak: a binary STL of 10^6 separate
    /// triangles, 3 * 10^6 corners, took 2.03 GB inside ReadFile): the vertex and its normal, and
    /// JoinIdenticalVertices' record of every corner (assimp's Vertex, 272 B, with its lookup
    /// structures), which is where a model's memory goes.
    static constexpr uint64_t kImportBytesPerCorner = 700;
    static std::optional<ImportEstimate> estimateImport(const std::string& path);

    /// One mesh per object of the file (see above), in the file's model space made Y-up. A mesh is
    /// named after its node ("object<N>" when unnamed), its parts after the assimp meshes ("part<N>").
    /// Throws sb::Error "model file 'x.obj': <reason>" (exit 2) for a missing, unreadable or empty
    /// file; for a file assimp's validation refuses (a face index beyond the vertices, a truncated
    /// binary file); for a PLY file with fewer faces than its header declares (a truncated ASCII
    /// file, which assimp reads as far as it goes); for a vertex that is infinite or NaN (no
    /// technique can draw it, and a fit of the layout onto it would turn every vertex into NaN) or
    /// beyond kMaxCoordinate; and for a file whose triangles all have zero area (nothing to draw or
    /// to cast a shadow, and no plane or proxy can be fitted to it).
    static std::vector<Mesh> loadObjects(const std::string& path, std::optional<ModelUp> up = {});
    /// All objects joined into one mesh named after the file's stem, every object's parts kept.
    static Mesh load(const std::string& path, std::optional<ModelUp> up = {});
    /// `objects` joined into one mesh called `name` (what load returns), every object's parts kept.
    static Mesh join(const std::vector<Mesh>& objects, const std::string& name);
    /// The rotation that takes a file's up axis to +Y (a proper rotation: determinant 1).
    static glm::mat3 rotationToYUp(ModelUp up);
};

} // namespace sb
