#pragma once
// Reads a scene JSON file (DESIGN.md section 8) into a Scene, applying SceneOptions.
//
// File format (all keys optional unless marked):
// {
//   "name": "aircraft",
//   "meshes": [ {"name": "f35", "generator": "aircraft", "tessellation": 16},
//               {"name": "ground", "generator": "plane", "size": 400},
//               {"name": "statue", "file": "models/statue.obj"} ],          // path relative to the JSON
//   "instances": [ {"mesh": "ground", "position": [0,0,0], "casts_shadow": false} ],
//   "layout": {"mesh": "f35", "count": 200, "seed": 1, "region": [[-60,4,-60],[60,12,60]],
//              "scale": 1.0, "yaw_only": true, "color": [0.7,0.72,0.75]},
//   "lights": [ {"type": "directional", "direction": [-0.4,-1,-0.3]} ],
//   "cameras": [ {"name": "far", "eye": [0,90,140], "target": [0,0,0], "fov": 45} ],
//   "effects": ["hard_shadows", "self_shadowing"],
//   "ambient": [0.15, 0.15, 0.15]
// }
// Every error throws sb::Error naming the file, the JSON path ("/meshes/2/generator") and what was
// expected, e.g. `scenes/data/x.json: /layout/count: expected a positive integer, got "ten"`.
#include <string>

#include "scenes/Scene.h"
#include "scenes/SceneOptions.h"

namespace sb {

class SceneLoader {
public:
    /// `nameOrPath` is a built-in scene name ("aircraft", "teapot", "primitives", "sphere_plane" ...,
    /// resolved to scenes/data/<name>.json next to the binary or in the source tree) or a file path.
    static Scene load(const std::string& nameOrPath, const SceneOptions& options = {});
    /// Parses JSON text; `sourceName` is used in error messages and to resolve relative model paths.
    static Scene parse(const std::string& jsonText, const std::string& sourceName,
                       const SceneOptions& options = {});
    /// Names of the built-in scene files found (for --help and --list).
    static std::vector<std::string> listBuiltinScenes();
};

} // namespace sb
