// Screen-space contact shadows (techniques/ContactShadows.h: what the knobs are, and why): a march of
// contact_steps points along contact_length world units from the shaded point towards light i, each
// projected with the camera's view-projection into the view depth pre-pass (techniques/gl/ViewDepthGL.h,
// techniques/vulkan/ViewDepthVulkan.h: the frame's size, the targets' rows); a point the view's depth lies
// in front of (by more than a rounding margin, by less than two steps) is behind a surface, and the light
// is blocked. As Unreal Engine's contact shadows and Filament's screen-space contact shadows. Included by
// the lighting passes of the members that declare `contact` (techniques/ContactShadows.h says which);
// without SB_CONTACT_SHADOWS it adds nothing and contactLimited(i, v, p, n) is v. Needs common/frame.glsl
// and common/lighting.glsl (toLight) first.
#ifdef SB_CONTACT_SHADOWS
// The march's length and steps are uniforms, not defines: they change no program (no permutation per
// value); x = contact_length (world units), y = contact_steps (ContactShadows::block).
#ifdef VULKAN
layout(set = 2, binding = 0) uniform sampler2D uViewDepth;
layout(std140, set = 2, binding = 1) uniform ContactBlock {
    vec4 uContact;
};
#else
layout(binding = 7) uniform sampler2D uViewDepth; // techniques/gl/ViewDepthGL.h's texture
layout(std140, binding = 1) uniform ContactBlock {
    vec4 uContact;
};
#endif

// The view depth (positive) of window depth w under the frame's projection: its ndc z is 2w - 1 on GL and
// w on Vulkan (the frame block's clip space, z in [0, w]), and z_ndc = -A + B / d (perspective) or
// B - A d (orthographic) with A = uProj[2][2], B = uProj[3][2] on both (techniques/ViewDepth.h).
float contactViewDepth(float w) {
#ifdef VULKAN
    const float z = w;
#else
    const float z = 2.0 * w - 1.0;
#endif
    // Both, then a select: no branch on the frame block alone inside the march. lavapipe specializes a
    // branch whose condition reads only uniform blocks into a shader variant it compiles while the frame
    // executes, and Mesa 22.3.6 never frees that variant (LeakSanitizer reported one per lighting
    // pipeline; Mesa 25.0.7 caches and frees its variants). The value not selected may be infinite; unused.
    const float perspective = uProj[3][2] / (z + uProj[2][2]);
    const float orthographic = (uProj[3][2] - z) / uProj[2][2];
    return uProj[2][3] != 0.0 ? perspective : orthographic;
}

// 0 when the march from worldPos (normal n) towards light i meets a surface of the view's depth, else 1.
float contactShadow(int i, vec3 worldPos, vec3 n) {
    const vec3 l = toLight(i, worldPos);
    const int steps = int(uContact.y);
    float len = uContact.x;
    if (isPositional(i)) len = min(len, distance(uLightPos[i].xyz, worldPos));
    const float step = len / float(steps);
    // Half a step off the surface along its normal: a tessellated curve's own facets, a step away, lie
    // within that of its tangent plane.
    const vec3 start = worldPos + n * (0.5 * step);
    const ivec2 size = textureSize(uViewDepth, 0);
    for (int k = 1; k <= steps; ++k) {
        const vec3 q = start + l * (step * float(k));
        const vec4 clip = uViewProj * vec4(q, 1.0);
        if (clip.w <= 0.0) break;
        const vec2 ndc = clip.xy / clip.w;
        if (any(greaterThan(abs(ndc), vec2(1.0)))) break; // off screen: nothing known there
        const ivec2 texel = min(ivec2((ndc * 0.5 + 0.5) * vec2(size)), size - 1);
        const float w = texelFetch(uViewDepth, texel, 0).r;
        if (w >= 1.0) continue; // no surface at that pixel
        const float rayDepth = -(uView * vec4(q, 1.0)).z;
        const float inFront = rayDepth - contactViewDepth(w);
        // Behind a surface by less than two steps: the ray entered it since the last point. Deeper, the
        // surface is taken as passing in front of the ray (the screen-space method's one guess).
        if (inFront > 1e-4 * rayDepth && inFront < 2.0 * step) return 0.0;
    }
    return 1.0;
}

float contactLimited(int i, float visibility, vec3 worldPos, vec3 n) {
    return visibility > 0.0 ? min(visibility, contactShadow(i, worldPos, n)) : visibility;
}
#else
float contactLimited(int i, float visibility, vec3 worldPos, vec3 n) { return visibility; }
#endif
