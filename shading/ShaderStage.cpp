#include "shading/ShaderStage.h"

namespace sb {
namespace {

struct StageNames {
    ShaderStage stage;
    const char* define;
    const char* name;
    const char* file;
};
constexpr StageNames kStages[] = {
    {ShaderStage::Vertex, "SB_VERTEX_SHADER", "vertex", "vertex.vert"},
    {ShaderStage::Geometry, "SB_GEOMETRY_SHADER", "geometry", "geometry.geom"},
    {ShaderStage::Fragment, "SB_FRAGMENT_SHADER", "fragment", "fragment.frag"},
    {ShaderStage::Compute, "SB_COMPUTE_SHADER", "compute", "compute.comp"},
    {ShaderStage::Mesh, "SB_MESH_SHADER", "mesh", "mesh.mesh"},
};

const StageNames& namesOf(ShaderStage stage) {
    for (const StageNames& s : kStages)
        if (s.stage == stage) return s;
    return kStages[0]; // unreachable: every enumerator has a row
}

} // namespace

const char* stageDefine(ShaderStage stage) {
    return namesOf(stage).define;
}
const char* stageName(ShaderStage stage) {
    return namesOf(stage).name;
}
const char* stageFileName(ShaderStage stage) {
    return namesOf(stage).file;
}

} // namespace sb
