// `projective` blur: one direction of a separable Gaussian (sigma = BLUR_RADIUS / 2, truncated at
// BLUR_RADIUS texels, weights normalised) over the projective texture: the slides' fake softness.
// BLUR_FROM_ARRAY: the horizontal pass, layer uLayer of the texture array into a temporary 2D texture;
// otherwise the vertical pass, the temporary texture back into the layer (the framebuffer's). Texels
// outside the texture count as 1 (lit), like the sampler's white border in the lighting pass.
#ifdef BLUR_FROM_ARRAY
layout(binding = 0) uniform sampler2DArray uSource;
layout(location = 0) uniform int uLayer;
const ivec2 kStep = ivec2(1, 0);
float texel(ivec2 p) { return texelFetch(uSource, ivec3(p, uLayer), 0).r; }
#else
layout(binding = 0) uniform sampler2D uSource;
const ivec2 kStep = ivec2(0, 1);
float texel(ivec2 p) { return texelFetch(uSource, p, 0).r; }
#endif
layout(location = 0) out vec4 oValue;

void main() {
    ivec2 size = textureSize(uSource, 0).xy;
    ivec2 p = ivec2(gl_FragCoord.xy);
    const float sigma = 0.5 * float(BLUR_RADIUS);
    float sum = 0.0, weights = 0.0;
    for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k) {
        ivec2 q = p + k * kStep;
        bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
        float w = exp(-float(k * k) / (2.0 * sigma * sigma));
        sum += w * (inside ? texel(q) : 1.0);
        weights += w;
    }
    oValue = vec4(sum / weights);
}
