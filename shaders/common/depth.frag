// Depth only: the map's framebuffer has no colour attachment (draw buffer GL_NONE) and colour writes are
// masked off, so this stage computes nothing. llvmpipe still runs its generated fragment function once per
// 4x4 stamp a triangle touches: the early depth test and the depth write live there, whatever the shader.
// Nothing in GL lets Mesa 22.3.6 skip it or stop counting it. Its NIR scan marks every shader non-empty,
// so llvmpipe's exception for a null shader never applies and the pipeline statistics count 16 fragment
// invocations per stamp, this body included; 25.0.7 marks a shader without instructions empty and counts
// none. A program without this stage (legal in GL 4.5) is drawn with a fragment shader of Mesa's own (in
// 22.3's source, its fixed-function program) and does exactly the same work on both releases: the same
// counts and the same instructions per frame within 0.001 % (bench ci's layers A and B,
// shadowmap:resolution=2048 on the glmark2 horse at 1024x1024). The Vulkan forms leave the stage out
// (techniques/vulkan/VulkanDepthMapSet.h).
void main() {}
