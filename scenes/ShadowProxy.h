#pragma once
// A shadow proxy of the ShadowProxies technique (van der Spek, "ShadowProxies", OpenGL Insights,
// sections 1.2-1.5): an analytic sphere, box or cylinder standing for an object, whose influence
// volume (the points within ProxyOffset of its surface) darkens and tints receivers.
//
// The proxy's frame maps the unit shape (sphere of radius 1, box [-1, 1]^3, cylinder of radius 1 around
// z with z in [-1, 1]) to world space: position, orientation and size in one matrix, as the chapter
// packs them. closestPoint() is Listing 1.1: the three shapes are symmetric in the xy, xz and yz planes,
// so the local point's absolute value is pushed onto the positive octant's boundary and the signs put
// back. For a non-uniformly scaled sphere or cylinder that is the closest point in the proxy's local
// metric (Listing 1.1's own behaviour), not the Euclidean one.
//
// This is the CPU form of shaders/proxy/ (the technique's fragment stage); the fitting picks the
// tightest of the three shapes around a mesh for proxies the scene does not declare.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/NameTable.h"

namespace sb {

struct Mesh;

struct ShadowProxy {
    enum class Shape { Sphere, Box, Cylinder };
    Shape shape = Shape::Sphere;
    glm::mat4 frame{1.0f};      ///< unit shape -> world (position, orientation, size)
    glm::vec3 diffuse{0.5f};    ///< colour of the object (colour bleeding)
    glm::vec3 reflective{0.0f}; ///< colour reflected whatever the light's direction (ambient bleeding)
    /// Fitted proxies, and declared ones without "diffuse", take the colour of the instance they stand
    /// for (so a mesh's proxy can be declared once for differently coloured instances).
    bool diffuseFromInstance = true;

    /// Listing 1.1: the nearest point on the proxy's surface to `p` (world space). Points inside the
    /// box or cylinder map to themselves (distance 0: fully inside the influence volume). The sphere's
    /// centre, where normalize(0) would be NaN, maps to the top of the sphere (+z local).
    glm::vec3 closestPoint(const glm::vec3& p) const;
    /// The outward unit normal at closestPoint(p) (Listing 1.4's surface.normal), world space: the
    /// gradient of the shape's local distance function taken through the frame's inverse transpose.
    glm::vec3 surfaceNormal(const glm::vec3& p) const;
    /// Volume of the proxy (for picking the tightest fit).
    float volume() const;

    /// The tightest of sphere, box and cylinder around `mesh` (object space) placed by `model`:
    /// axis-aligned in the mesh's frame (box: the bounds; cylinder: around the longest axis through the
    /// bounds' centre; sphere: around the bounds' centre), by volume.
    static ShadowProxy fit(const Mesh& mesh, const glm::mat4& model);
    /// "sphere", "box", "cylinder": scene files' proxy "shape".
    static const NameTable<Named<Shape>>& shapeNames();
    static const char* shapeName(Shape s);
};

/// Listing 1.3: the shadow (or bleeding) factor of a fragment at `distance` from the proxy's surface:
/// 1 at the surface falling to 0 at ProxyOffset, times pow(shadowFactor, falloffExponent). ProxyOffset
/// <= 0 (the chapter divides by it) gives 1 on the surface (distance 0) and 0 elsewhere: the volume
/// shrinks to the surface, no division by zero, no NaN. As printed, the listing raises the shadow
/// factor (not the falloff term) to the exponent; reproduced as printed.
float proxyShadow(float distance, float proxyOffset, float shadowFactor, float falloffExponent);

} // namespace sb
