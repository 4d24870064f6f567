// Test fixture (ShaderModuleCacheVkTest): compiles only where VULKAN is predefined (glslang targeting
// Vulkan), so a successful compile proves `#ifdef VULKAN` blocks are taken.
#ifndef VULKAN
#error VULKAN is not defined
#endif
layout(location = 0) out vec4 oColor;
void main() {
#ifdef VULKAN
    oColor = vec4(1.0);
#else
    undeclared_identifier = 1.0;
#endif
}
