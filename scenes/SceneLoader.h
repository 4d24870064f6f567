#pragma once
// Reads a scene JSON file (docs/ARCHITECTURE.md, "Scenes") into a Scene, applying SceneOptions.
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
//   "ambient": [0.15, 0.15, 0.15],
//   "lighting": "fragment"
// }
// Details:
// - "description": free text, ignored. Files may contain // comments.
// - "lighting": "fragment" (default) or "vertex": where the lit passes evaluate the lights
//   (scenes/LightingRate.h); SceneOptions::lighting (`--lighting`) replaces it.
// - meshes: exactly one of "generator" or "file". A model file (scenes/ModelLoader.h) comes out Y-up;
//   "up" ("x", "-x", "y", "-y", "z", "-z") names the file's up axis where the file does not (a Z-up 3DS
//   export: "up": "z"). Each object of a multi-object file becomes its own mesh "<name>:<object>",
//   and every instance of the entry (explicit or from the layout) one instance per object with the
//   same transform, so each object is a caster of its own (a fitted proxy, a blob); with
//   "shadow_planes" the file stays one mesh, its objects named parts a plane can name together.
//   Generator parameters (each generator accepts only
//   its own): sphere "radius" (1), box "half_extent" ([1,1,1]), cylinder "radius" (1), "height" (2),
//   plane "size" (100), lantern "radius" (1), "thickness" (0.08) (a closed shell with four holes cut
//   through, the jack-o'-lantern of GPU Gems 9); "tessellation" defaults: sphere/cylinder/aircraft/
//   plane/lantern 16, teapot 8, box 1.
//   SceneOptions::tessellation replaces it for every generator but the plane (the ground receiver), and
//   SceneOptions::tessellationFactor then multiplies it (rounded, clamped to the generator minimum).
// - meshes, "shadow_planes" (either kind of mesh): the occluder technique's planes (scenes/ShadowPlane.h)
//   in the object space of the final mesh (after tessellation and "radius"/"size" scaling):
//     "shadow_planes": [ {"name": "fin", "origin": [x,y,z], "normal": [x,y,z], "right": [x,y,z],
//                         "up": [x,y,z], "width": w, "height": h, "solid": false, "parts": ["fin_right"],
//                         "texture": "auto" | "textures/fin.png", "texture_of": "other plane"} ]
//   "name", "origin" (the texture's (0, 0) corner), "normal", "right", "up", "width", "height" required.
//   normal, right and up must be unit (within 1e-3; not normalised on load: a wrong vector is an error)
//   and perpendicular to each other; width and height > 0. "parts" (default: the whole mesh) must name
//   parts of the mesh. "texture": "auto" (default: baked from the parts) or an image file, relative to
//   the JSON file's directory, made absolute, and it must exist. "texture_of": another plane of the same
//   mesh whose texture this one uses; that plane may not itself have a texture_of, nor be solid.
//   "solid": true (every uv in [0, 1]^2 is shadow) takes neither a texture file nor texture_of.
//   "section_only": true bakes only the plane's cross-section with the solid (not the parts'
//   silhouette; the teapot knob's plane). "receivers" (default: every part) names the parts of the mesh
//   that receive the plane's shadow (the thesis's receiver sections). Names
//   are unique per mesh. Without the key a generated mesh gets its built-in planes
//   (scenes/BuiltinShadowPlanes.h: aircraft 3, teapot 11) and every other mesh none given: the
//   occluder technique chooses its planes (Mesh::shadowPlanesAuto); "shadow_planes": [] means none. A mesh
//   that --model replaces takes no planes along (its planes were for the replaced geometry): the occluder
//   technique chooses the model's automatically (Mesh::shadowPlanesAuto, scenes/ShadowPlaneChooser.h).
// - meshes, "proxies" (either kind of mesh): the proxy technique's ShadowProxies (scenes/ShadowProxy.h)
//   in the mesh's object space:
//     "proxies": [ {"shape": "sphere" | "box" | "cylinder", "position": [x,y,z], "rotation": [deg x,y,z],
//                   "size": s | [x, y, z], "diffuse": [r,g,b], "reflective": [r,g,b]} ]
//   frame = T(position) * Rx * Ry * Rz * S(size) (the instances' Euler convention) maps the unit shape
//   (sphere radius 1, box [-1, 1]^3, cylinder radius 1 around z, z in [-1, 1]): "size" is radii / half
//   extents / (radius x, radius y, half height), one number for all three or [x, y, z], required, each
//   finite and >= 0 (zero: a degenerate proxy, allowed). "position" and "rotation" (degrees) default
//   to 0. "diffuse" (the colour bled towards the light) defaults to the colour of each instance
//   (ShadowProxy::diffuseFromInstance); "reflective" (bled whatever the light) to black; channels in
//   [0, 1]. Without the key the technique fits the tightest sphere, box or cylinder to each instance;
//   "proxies": [] means none. A mesh that --model replaces takes no proxies along (they were for the
//   replaced geometry): the model gets fitted ones.
// - instances: "mesh" (required), "position", "rotation" (Euler degrees), "scale", "color",
//   "casts_shadow", "receives_shadow". Explicit instances come first, then the layout's.
// - layout: "mesh", "count" (<= 1000000), "region" required; "seed" (1), "scale" (1), "yaw_only"
//   (true), "max_tilt" (degrees of pitch/roll when yaw_only is false, 10), "color", "casts_shadow",
//   "receives_shadow". SplitMix64-seeded, identical on every platform.
// - lights: "type", "direction", "position", "color", "intensity", "range", "spot_outer_deg",
//   "spot_inner_deg", "shape", "size", "angular_radius_deg", "casts_shadows" (default true; false: a
//   light that illuminates and casts no shadow, so no technique renders a shadow pass for it). Without
//   "lights", one default directional light. "size" (a point or spot light's rect [w, h], disk or
//   sphere radius) lies in [0, 1e18], the bound on coordinates; "angular_radius_deg" is taken by a
//   directional light with "shape": "disk" only (on any other light it is an error, not ignored).
// - cameras: "name" (required, unique), "eye", "target", "up", "fov", "near", "far"; or "follow":
//   "first_instance" with "offset" (in units of that instance's scale, so --scale keeps the framing):
//   eye = first layout instance + offset * scale, target = that instance. An up parallel to the view
//   direction (looking straight down) is replaced by -Z.
// - motion (scenes/Motion.h): paths over a path time t in [0, 1], measured frame f at t = (f mod
//   "frames") / "frames" (default 60, at least 2); at least one of
//     "sun": {"light": 0, "azimuth_deg": [-60, 60], "elevation_deg": [15, 70]}   a directional light
//       (azimuth 0 = +X, 90 = +Z; elevation low + (high - low) sin(pi t), each in [0, 90])
//     "orbit": {"light": 0, "centre": [x,y,z], "radius": r, "turns": 1, "target": [x,y,z]}  a point or
//       spot light on a horizontal circle (a spot aims at "target", default below the centre at y = 0)
//     "camera": ["far", {"eye": [..], "target": [..], "fov": 45}, "near"]  key cameras (names of the
//       scene's cameras or camera objects without "name"/"follow"), at least two, piecewise linear;
//       the scene gets a camera named "path" that follows them (--camera path). At no measured frame
//       may the eye reach the target (a path through its target has no view direction there: an
//       error naming the frame and the keys it lies between)
//     "casters": {"instances": "layout" | "casters" | [i, ...], "translate": [x,y,z], "yaw_deg": a}
//       casters moved by translate and turned by yaw over the path ("layout", the default: the layout's
//       instances); an instance that casts no shadow may not move (receivers stay put)
//   A light may follow one path. Under --light the path still moves the light: a sun path moves a point
//   or spot light over the sky at its distance from the casters' centre, an orbit turns a directional
//   light to shine from the orbit towards its target.
// SceneOptions: --instances/--model need a layout (error otherwise); --model's meshes are named after the
// model file ("horse.3ds", "test1.3ds:Box01"), so errors about them name it; --light moves a directional
// light to centre - direction * 2 * radius of the casters' bounds, a spot's cone then encloses them.
// Memory estimate (limit SceneOptions::memoryLimitBytes; docs/USAGE.md, "What --max-memory-gib
// covers"), each part checked before it is paid: the file's text and its parsed document
// (SceneDocumentCost, counted before the document is made) with the least each explicit instance
// costs; mesh vertex (24 B) + index bytes, plus per instance its triangles * 3 * 24 B (immediate /
// display-list copies) + 128 B, for the explicit instances before any is made and for the layout
// before it is placed; a model file's import (ModelLoader::estimateImport) before assimp reads it.
// Every error throws sb::Error naming the file, the JSON path ("/meshes/2/generator") and what was
// expected, e.g. `scenes/data/x.json: /layout/count: expected a positive integer, got "ten"`.
// Limits that keep hostile files from crashing or poisoning a run (each refused as bad input): arrays
// and objects nest at most JsonReader::kMaxDepth (64) deep; every number fits a double, and every
// number read as a float fits a float; every mesh's bounds, every instance's world bounds (position +
// scale * size), and every camera eye/target and light position lie within ModelLoader::kMaxCoordinate
// (1e18), the error naming the mesh's or instance's JSON path ("/layout" for layout instances).
#include <cstdint>
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
    /// The memory estimate above of a loaded scene (every instance counted), in bytes: the run adds
    /// the techniques' and the frame targets' to it (registry/MemoryBudget.h).
    static uint64_t estimateBytes(const Scene& scene);
};

} // namespace sb
