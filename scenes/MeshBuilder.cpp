#include "scenes/MeshBuilder.h"

#include <utility>

namespace sb {

MeshBuilder::MeshBuilder(std::string name) {
    mMesh.name = std::move(name);
}

uint32_t MeshBuilder::addVertex(const glm::vec3& position, const glm::vec3& normal) {
    // A zero-length normal would turn into NaN in glm::normalize; every caller handles its poles,
    // so this is only a last line of defence that keeps the "no NaN" guarantee of Mesh.
    const float len = glm::length(normal);
    mMesh.positions.push_back(position);
    mMesh.normals.push_back(len > 1e-20f ? normal / len : glm::vec3(0.0f, 1.0f, 0.0f));
    return uint32_t(mMesh.positions.size() - 1);
}

void MeshBuilder::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    mMesh.indices.insert(mMesh.indices.end(), {a, b, c});
}

void MeshBuilder::addQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    addTriangle(a, b, c);
    addTriangle(a, c, d);
}

void MeshBuilder::addGrid(uint32_t first, int rows, int cols, bool flip) {
    const uint32_t stride = uint32_t(cols + 1);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const uint32_t a = first + uint32_t(r) * stride + uint32_t(c);
            const uint32_t b = a + 1, d = a + stride, e = d + 1;
            if (flip)
                addQuad(a, d, e, b);
            else
                addQuad(a, b, e, d);
        }
    }
}

void MeshBuilder::beginPart(const std::string& name) {
    closePart();
    mMesh.parts.push_back(MeshPart{name, uint32_t(mMesh.indices.size()), 0});
    mPartOpen = true;
}

void MeshBuilder::closePart() {
    if (!mPartOpen) return;
    MeshPart& part = mMesh.parts.back();
    part.indexCount = uint32_t(mMesh.indices.size()) - part.firstIndex;
    mPartOpen = false;
}

Mesh MeshBuilder::finish() {
    closePart();
    return std::move(mMesh);
}

} // namespace sb
