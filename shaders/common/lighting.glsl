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
