#include "techniques/Submitter.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "techniques/DisplayListSubmitter.h"
#include "techniques/ImmediateSubmitter.h"
#include "techniques/InstancedSubmitter.h"
#include "techniques/RetainedSubmitter.h"

namespace sb {

const char* submitModeName(SubmitMode m) {
    switch (m) {
    case SubmitMode::Immediate:
        return "immediate";
    case SubmitMode::DisplayList:
        return "displaylist";
    case SubmitMode::Retained:
        return "retained";
    case SubmitMode::Instanced:
        return "instanced";
    }
    return "?";
}

std::optional<SubmitMode> parseSubmitMode(const std::string& name) {
    for (SubmitMode m : kAllSubmitModes)
        if (name == submitModeName(m)) return m;
    return std::nullopt;
}

std::unique_ptr<Submitter> Submitter::create(SubmitMode mode) {
    switch (mode) {
    case SubmitMode::Immediate:
        return std::make_unique<ImmediateSubmitter>();
    case SubmitMode::DisplayList:
        return std::make_unique<DisplayListSubmitter>();
    case SubmitMode::Retained:
        return std::make_unique<RetainedSubmitter>();
    case SubmitMode::Instanced:
        return std::make_unique<InstancedSubmitter>();
    }
    return nullptr;
}

bool Submitter::inSet(const Instance& inst, DrawSet set) {
    switch (set) {
    case DrawSet::All:
        return true;
    case DrawSet::Casters:
        return inst.castsShadow;
    case DrawSet::Receivers:
        return inst.receivesShadow;
    case DrawSet::NonCasters:
        return !inst.castsShadow;
    }
    return false;
}

void Submitter::setInstanceUniforms(const Instance& inst) {
    // Fixed locations (layout(location=...) in common/instance.glsl): no glGetUniformLocation per draw.
    glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
    glUniform4f(4, inst.color.r, inst.color.g, inst.color.b, float(inst.objectId));
}

void Submitter::emitImmediate(const Mesh& mesh) {
    glBegin(GL_TRIANGLES);
    for (uint32_t idx : mesh.indices) {
        glVertexAttrib3fv(1, &mesh.normals[idx].x);
        glVertexAttrib3fv(0, &mesh.positions[idx].x);
    }
    glEnd();
}

} // namespace sb
