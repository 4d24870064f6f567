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
    /// One mesh per object of the file (see above), in the file's model space made Y-up. A mesh is
    /// named after its node ("object<N>" when unnamed), its parts after the assimp meshes ("part<N>").
    /// Throws sb::Error "model file 'x.obj': <reason>" (exit 2) for a missing, unreadable or empty
    /// file, and for a vertex that is infinite or NaN (no technique can draw it, and a fit of the
    /// layout onto it would turn every vertex into NaN).
    static std::vector<Mesh> loadObjects(const std::string& path, std::optional<ModelUp> up = {});
    /// All objects joined into one mesh named after the file's stem, every object's parts kept.
    static Mesh load(const std::string& path, std::optional<ModelUp> up = {});
    /// `objects` joined into one mesh called `name` (what load returns), every object's parts kept.
    static Mesh join(const std::vector<Mesh>& objects, const std::string& name);
    /// The rotation that takes a file's up axis to +Y (a proper rotation: determinant 1).
    static glm::mat3 rotationToYUp(ModelUp up);
};

} // namespace sb
