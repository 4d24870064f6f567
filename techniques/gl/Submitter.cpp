#include "techniques/submit/Submitter.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "techniques/submit/DisplayListSubmitter.h"
#include "techniques/submit/ImmediateSubmitter.h"
#include "techniques/submit/InstancedSubmitter.h"
#include "techniques/submit/RetainedSubmitter.h"

namespace sb {

namespace {

template <typename T>
std::unique_ptr<Submitter> make() {
    return std::make_unique<T>();
}

// The one table of submission modes, in kAllSubmitModes's order.
constexpr SubmitModeEntry kSubmitModes[] = {
    {SubmitMode::Immediate, "immediate", make<ImmediateSubmitter>},
    {SubmitMode::DisplayList, "displaylist", make<DisplayListSubmitter>},
    {SubmitMode::Retained, "retained", make<RetainedSubmitter>},
    {SubmitMode::Instanced, "instanced", make<InstancedSubmitter>},
};
constexpr NameTable kSubmitModeTable{kSubmitModes};

} // namespace

const NameTable<SubmitModeEntry>& submitModes() {
    return kSubmitModeTable;
}

const char* submitModeName(SubmitMode m) {
    return kSubmitModeTable.name(m);
}

std::optional<SubmitMode> parseSubmitMode(const std::string& name) {
    return kSubmitModeTable.parse(name);
}

std::unique_ptr<Submitter> Submitter::create(SubmitMode mode) {
    const SubmitModeEntry* e = kSubmitModeTable.find(mode);
    return e ? e->create() : nullptr;
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
    case DrawSet::NonReceivers:
        return !inst.receivesShadow;
    }
    return false;
}

InstanceMask Submitter::narrowToScope(InstanceMask keep) {
    mScoped.resize(mScope.size());
    for (size_t i = 0; i < mScope.size(); ++i) mScoped[i] = mScope[i] && kept(keep, i) ? 1 : 0;
    return mScoped;
}

float Submitter::shadowSignedId(const Instance& inst) {
    return inst.receivesShadow ? float(inst.objectId) : -float(inst.objectId);
}

void Submitter::setInstanceUniforms(const Instance& inst) {
    // Fixed locations (layout(location=...) in common/instance.glsl): no glGetUniformLocation per draw.
    glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(inst.model));
    glUniform4f(4, inst.color.r, inst.color.g, inst.color.b, shadowSignedId(inst));
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
