// The separable Gaussian of techniques/gl/SeparableBlur.h: one direction, 2 BLUR_RADIUS + 1 taps one
// texel apart.
// BLUR_FROM_ARRAY: the horizontal pass, layer uLayer of the texture array into the intermediate 2D
// texture; otherwise the vertical pass, the intermediate back into the layer (the bound framebuffer's).
// Weights: uWeights[|k|], computed on the CPU (the integral of the truncated Gaussian over each texel;
// they sum to 1). BLUR_POINT_SAMPLED (`projective`): the Gaussian's values at the taps, sigma =
// BLUR_RADIUS / 2, computed here, the sum divided by the sum of the weights; the first channel only.
// Taps outside the texture read the edge texel; BLUR_OUTSIDE_ONE (`projective`): they read 1 (lit), like
// the white border colour of the lighting pass's sampler.
// LOG_SPACE (`esm`): the channel holds depth d; the pass writes log(sum w_k exp(c d_k)) / c (Salvi 2008,
// Rendering Filtered Shadows with Exponential Shadow Maps, ShaderX6), as
// m + log(sum w_k exp(c (d_k - m))) / c with m the largest d_k: every exp() is at most 1 and the sum at
// least the largest tap's weight, so no exponent overflows or takes the log of 0. Otherwise (`vsm`) every
// channel is filtered linearly.
#ifdef VULKAN
// Set 0 (techniques/vulkan/VulkanSeparableBlur.h): the source and a block written once per compile; the
// layer of the horizontal pass in a push constant. std140: each float of the array takes 16 bytes.
#define SB_SOURCE_BINDING set = 0, binding = 0
layout(std140, set = 0, binding = 1) uniform BlurBlock {
    float uExponent;
    float uWeights[BLUR_RADIUS + 1];
};
layout(push_constant) uniform BlurPush {
    int uLayer;
};
#else
#define SB_SOURCE_BINDING binding = 0
layout(location = 0) uniform int uLayer;
layout(location = 1) uniform float uExponent;
layout(location = 2) uniform float uWeights[BLUR_RADIUS + 1];
#endif
#ifdef BLUR_FROM_ARRAY
layout(SB_SOURCE_BINDING) uniform sampler2DArray uSource;
const ivec2 kStep = ivec2(1, 0);
vec4 texel(ivec2 p) { return texelFetch(uSource, ivec3(p, uLayer), 0); }
#else
layout(SB_SOURCE_BINDING) uniform sampler2D uSource;
const ivec2 kStep = ivec2(0, 1);
vec4 texel(ivec2 p) { return texelFetch(uSource, p, 0); }
#endif
layout(location = 0) out vec4 oValue;

#ifdef BLUR_OUTSIDE_ONE
vec4 tap(ivec2 p, int k, ivec2 size) {
    ivec2 q = p + k * kStep;
    bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
    return inside ? texel(q) : vec4(1.0);
}
#else
vec4 tap(ivec2 p, int k, ivec2 size) { return texel(clamp(p + k * kStep, ivec2(0), size - 1)); }
#endif

void main() {
    ivec2 size = textureSize(uSource, 0).xy;
    ivec2 p = ivec2(gl_FragCoord.xy);
#if defined(LOG_SPACE)
    float d[2 * BLUR_RADIUS + 1];
    float m = -3.0e38;
    for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k) {
        d[k + BLUR_RADIUS] = tap(p, k, size).r;
        m = max(m, d[k + BLUR_RADIUS]);
    }
    float sum = 0.0;
    for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k)
        sum += uWeights[abs(k)] * exp(uExponent * (d[k + BLUR_RADIUS] - m));
    oValue = vec4(m + log(sum) / uExponent);
#elif defined(BLUR_POINT_SAMPLED)
    const float sigma = 0.5 * float(BLUR_RADIUS);
    float sum = 0.0, weights = 0.0;
    for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k) {
        float w = exp(-float(k * k) / (2.0 * sigma * sigma));
        sum += w * tap(p, k, size).r;
        weights += w;
    }
    oValue = vec4(sum / weights);
#else
    vec4 sum = uWeights[0] * tap(p, 0, size);
    for (int k = 1; k <= BLUR_RADIUS; ++k) sum += uWeights[k] * (tap(p, k, size) + tap(p, -k, size));
    oValue = sum;
#endif
}
