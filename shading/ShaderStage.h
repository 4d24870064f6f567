#pragma once
// The shader stages, named once for both APIs: the preprocessor's stage define, the stage's word in
// messages, and the file name a dumped stage gets (the extension glslangValidator reads the stage from).
// gl/ maps a stage to its GLenum, vk/ to glslang's language and VkShaderStageFlagBits. Mesh is
// VK_EXT_mesh_shader's mesh stage (GL_EXT_mesh_shader, `.mesh`): Vulkan only (no task stage is used);
// gl/ refuses it.
namespace sb {

enum class ShaderStage { Vertex, Geometry, Fragment, Compute, Mesh };

/// "SB_VERTEX_SHADER" etc.: defined to 1 in the stage being built, so one file can serve several stages.
const char* stageDefine(ShaderStage stage);
/// "vertex", "geometry", "fragment", "compute", "mesh".
const char* stageName(ShaderStage stage);
/// "vertex.vert", "geometry.geom", "fragment.frag", "compute.comp", "mesh.mesh".
const char* stageFileName(ShaderStage stage);

} // namespace sb
