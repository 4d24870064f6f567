// The depth-range reduction of `cascaded` fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution
// Shadow Maps, I3D: the min and max of the view's depth samples that its z-partitions are fitted to),
// on both APIs (techniques/shadowmap/DepthRangeGL.h, DepthRangeVulkan.h): every texel of the camera's
// depth pre-pass that a surface covers (window depth below 1, the clear value) takes part, each work group
// reduces its 16 x 16 texels in shared memory, then one invocation folds the group's answer into the
// result buffer with two atomics. Window depths are >= 0, where an IEEE float's bits order as the float
// does, so atomicMin/atomicMax on the bits are the float min and max, exact: no rounding anywhere. The
// buffer is cleared to (+inf bits, 0) before the dispatch; an untouched one means no pixel was covered.
layout(local_size_x = 16, local_size_y = 16) in;

#ifdef VULKAN
layout(set = 0, binding = 0) uniform sampler2D uDepth;
layout(std430, set = 0, binding = 1) buffer DepthRange {
#else
layout(binding = 0) uniform sampler2D uDepth;
layout(std430, binding = 0) buffer DepthRange {
#endif
    uint uMinBits; ///< floatBitsToUint of the smallest covered window depth
    uint uMaxBits; ///< and of the largest
};

shared uint sMin;
shared uint sMax;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sMin = 0x7f800000u; // +inf: above every depth
        sMax = 0u;
    }
    barrier();
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(texel, textureSize(uDepth, 0)))) {
        const float d = texelFetch(uDepth, texel, 0).r;
        if (d < 1.0) {
            // max(d, 0): a -0.0 would order as the largest uint.
            const uint bits = floatBitsToUint(max(d, 0.0));
            atomicMin(sMin, bits);
            atomicMax(sMax, bits);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && sMin <= sMax) {
        atomicMin(uMinBits, sMin);
        atomicMax(uMaxBits, sMax);
    }
}
