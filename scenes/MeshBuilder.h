#pragma once
// Incremental construction of an sb::Mesh with named parts, shared by the procedural generators.
#include <string>

#include "scenes/Mesh.h"

namespace sb {

class MeshBuilder {
public:
    explicit MeshBuilder(std::string name);

    /// Appends a vertex and returns its index. `normal` is normalised here (a zero normal becomes +Y).
    uint32_t addVertex(const glm::vec3& position, const glm::vec3& normal);
    /// Appends one triangle (counter-clockwise seen from the front).
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    /// Appends a quad a-b-c-d (counter-clockwise) as the two triangles a-b-c and a-c-d.
    void addQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
    /// Triangulates a grid of (rows+1) x (cols+1) vertices stored row-major from `first`. Row r and
    /// column c span the quad (r,c),(r,c+1),(r+1,c+1),(r+1,c); `flip` reverses the winding.
    void addGrid(uint32_t first, int rows, int cols, bool flip = false);

    /// Starts a named part: every index appended until the next beginPart/finish belongs to it.
    void beginPart(const std::string& name);
    /// Closes the open part (if any) and hands the mesh over.
    Mesh finish();

    uint32_t vertexCount() const { return uint32_t(mMesh.positions.size()); }

private:
    void closePart();

    Mesh mMesh;
    bool mPartOpen = false;
};

} // namespace sb
