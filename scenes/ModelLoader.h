#pragma once
// Model files through assimp (--model path.obj|.gltf|.glb|.3ds|.ply ...): triangulated, normals
// generated where missing, all meshes of the file flattened into one Mesh (node transforms applied).
#include <string>

#include "scenes/Mesh.h"

namespace sb {

class ModelLoader {
public:
    /// Throws sb::Error "model file 'x.obj': <reason>" for a missing, unreadable or empty file.
    static Mesh load(const std::string& path);
};

} // namespace sb
