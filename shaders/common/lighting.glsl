// Direct lighting without shadows: Lambert diffuse with spot cone and range falloff. Techniques
// multiply each light's term by their visibility (1 lit, 0 shadowed).

// Light i's kind. Under SB_STATIC_LIGHTS the scene's lights are compile-time bits (addSceneDefines in
// techniques/Technique.h): llvmpipe runs both sides of a branch on a uniform under a mask, so a
// directional light's fragments would otherwise pay for the distance, range and cone terms too.
// Without it (a program compiled without the scene's defines) the uniforms say, as frame.glsl packs them.
bool lightBit(uint mask, int i) { return ((mask >> uint(i)) & 1u) != 0u; }

bool isPositional(int i) {
#ifdef SB_STATIC_LIGHTS
    return lightBit(SB_POSITIONAL_LIGHTS, i);
#else
    return uLightPos[i].w != 0.0;
#endif
}

bool isSpot(int i) {
#ifdef SB_STATIC_LIGHTS
    return lightBit(SB_SPOT_LIGHTS, i);
#else
    return uLightPos[i].w == 2.0;
#endif
}

bool isRanged(int i) {
#ifdef SB_STATIC_LIGHTS
    return lightBit(SB_RANGED_LIGHTS, i);
#else
    return uLightPos[i].w != 0.0 && uLightColor[i].w > 0.0;
#endif
}

// Unit vector from the surface towards light i.
vec3 toLight(int i, vec3 worldPos) {
    if (!isPositional(i)) return -uLightDir[i].xyz;
    return normalize(uLightPos[i].xyz - worldPos);
}

// Unshadowed irradiance factor of light i at a surface point with unit normal n.
vec3 lightTerm(int i, vec3 worldPos, vec3 n) {
    vec3 l = toLight(i, worldPos);
    float ndotl = max(dot(n, l), 0.0);
    float atten = 1.0;
    if (isRanged(i)) {
        float d = length(uLightPos[i].xyz - worldPos);
        atten = clamp(1.0 - d / uLightColor[i].w, 0.0, 1.0);
    }
    if (isSpot(i)) {
        float c = dot(-l, uLightDir[i].xyz);
        atten *= smoothstep(uLightDir[i].w, uLightParams[i].x, c);
    }
    return uLightColor[i].rgb * (ndotl * atten);
}

// Whether light i's shadow applies to a fragment of the instance with colour-and-id `colorId`: not for a
// light that casts none (SB_SHADOWLESS_LIGHTS, a bit per light) nor on an instance that receives none
// (SB_NON_RECEIVERS: its id is negative). Both are compile-time, set only for scenes that have them
// (CompileContext::defines): otherwise this is the constant true and costs nothing.
// SB_NON_RECEIVER_DRAWS: the program draws only instances that receive no shadow (a technique that
// draws its receivers and its non-receivers apart, ShadowMap::drawsNonReceiversApart), so no shadow
// applies and the lookup is compiled out. llvmpipe (Mesa 22.3.6) runs the lookup under the mask of the
// branch on colorId.w, so a non-receiver's fragments would otherwise pay for the lookup they discard.
bool lightCastsShadows(int i) {
#ifdef SB_SHADOWLESS_LIGHTS
    return ((uint(SB_SHADOWLESS_LIGHTS) >> uint(i)) & 1u) == 0u;
#else
    return true;
#endif
}

bool shadowApplies(int i, vec4 colorId) {
#if defined(SB_NON_RECEIVER_DRAWS)
    return false;
#elif defined(SB_NON_RECEIVERS)
    return lightCastsShadows(i) && colorId.w > 0.0;
#else
    return lightCastsShadows(i);
#endif
}
