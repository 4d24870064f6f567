// Direct lighting without shadows: Lambert diffuse with spot cone and range falloff. Techniques
// multiply each light's term by their visibility (1 lit, 0 shadowed).

// Unit vector from the surface towards light i.
vec3 toLight(int i, vec3 worldPos) {
    if (uLightPos[i].w == 0.0) return -uLightDir[i].xyz;
    return normalize(uLightPos[i].xyz - worldPos);
}

// Unshadowed irradiance factor of light i at a surface point with unit normal n.
vec3 lightTerm(int i, vec3 worldPos, vec3 n) {
    vec3 l = toLight(i, worldPos);
    float ndotl = max(dot(n, l), 0.0);
    float atten = 1.0;
    if (uLightPos[i].w != 0.0) {
        float range = uLightColor[i].w;
        if (range > 0.0) {
            float d = length(uLightPos[i].xyz - worldPos);
            atten = clamp(1.0 - d / range, 0.0, 1.0);
        }
        if (uLightPos[i].w == 2.0) {
            float c = dot(-l, uLightDir[i].xyz);
            atten *= smoothstep(uLightDir[i].w, uLightParams[i].x, c);
        }
    }
    return uLightColor[i].rgb * (ndotl * atten);
}

// Whether light i's shadow applies to a fragment of the instance with colour-and-id `colorId`: not for a
// light that casts none (SB_SHADOWLESS_LIGHTS, a bit per light) nor on an instance that receives none
// (SB_NON_RECEIVERS: its id is negative). Both are compile-time, set only for scenes that have them
// (CompileContext::defines): otherwise this is the constant true and costs nothing.
bool lightCastsShadows(int i) {
#ifdef SB_SHADOWLESS_LIGHTS
    return ((uint(SB_SHADOWLESS_LIGHTS) >> uint(i)) & 1u) == 0u;
#else
    return true;
#endif
}

bool shadowApplies(int i, vec4 colorId) {
#ifdef SB_NON_RECEIVERS
    return lightCastsShadows(i) && colorId.w > 0.0;
#else
    return lightCastsShadows(i);
#endif
}
