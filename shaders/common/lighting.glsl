// Direct lighting without shadows: Lambert diffuse with spot cone and range falloff. Techniques
// multiply each light's term by their visibility (1 lit, 0 shadowed).

// Light i's kind. Under SB_STATIC_LIGHTS the scene's lights are compile-time bits (addSceneDefines in
// techniques/Technique.h): llvmpipe runs both sides of a branch on a uniform under a mask, so a
// directional light's fragments would otherwise pay for the distance, range and cone terms too.
// Without it (a program compiled without the scene's defines) the uniforms say, as frame.glsl packs them.
bool lightBit(uint mask, int i) { return ((mask >> uint(i)) & 1u) != 0u; }

// Light i's colour x intensity (rgb) and range (w, 0 = unlimited), and the cosines of its cone's outer and
// inner half-angles (x, y). Under SB_STATIC_LIGHTS compile-time constants (SB_LIGHT_COLORS, SB_LIGHT_CONES:
// techniques/FrameBlock.h, lightConstants): they are fixed once the scene is loaded, and a uniform read
// costs a fragment stage of llvmpipe far more than a constant (ambientLight below). The positions and
// directions, which motion changes, stay uniforms.
#ifdef SB_STATIC_LIGHTS
const vec4 kLightColorRange[4] = SB_LIGHT_COLORS;
const vec2 kLightConeCos[4] = SB_LIGHT_CONES;
vec4 lightColorRange(int i) { return kLightColorRange[i]; }
vec2 lightConeCos(int i) { return kLightConeCos[i]; }
#else
vec4 lightColorRange(int i) { return uLightColor[i]; }
vec2 lightConeCos(int i) { return vec2(uLightDir[i].w, uLightParams[i].x); }
#endif

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
    return uLightPos[i].w != 0.0 && lightColorRange(i).w > 0.0;
#endif
}

// The scene's ambient light, added unshadowed by every lit pass. Under SB_AMBIENT (the scene's, fixed once
// it is loaded: addLightKindDefines in techniques/Technique.h) a compile-time constant, which a black
// ambient removes altogether. On llvmpipe a uniform costs a fragment stage far more than one load: on
// Mesa 22.3 a vec3 read costs about 8 instructions per fragment, what reading it lane by lane would
// (results/perf/README.md, "Constants where the scene fixes them"). Without SB_AMBIENT (a program
// compiled without the scene's defines) the uniform says.
vec3 ambientLight() {
#ifdef SB_AMBIENT
    return SB_AMBIENT;
#else
    return uAmbient.rgb;
#endif
}

// Unit vector from the surface towards light i.
vec3 toLight(int i, vec3 worldPos) {
    if (!isPositional(i)) return -uLightDir[i].xyz;
    return normalize(uLightPos[i].xyz - worldPos);
}

// Light i's distance and cone falloff at worldPos, for the unit vector l towards it.
float lightFalloff(int i, vec3 worldPos, vec3 l) {
    float atten = 1.0;
    if (isRanged(i)) {
        float d = length(uLightPos[i].xyz - worldPos);
        atten = clamp(1.0 - d / lightColorRange(i).w, 0.0, 1.0);
    }
    if (isSpot(i)) {
        float c = dot(-l, uLightDir[i].xyz);
        atten *= smoothstep(lightConeCos(i).x, lightConeCos(i).y, c);
    }
    return atten;
}

// Unshadowed irradiance factor of light i at the surface point worldPos with unit normal n, evaluated
// there: what the lit passes use per fragment, and what the shadow passes that darken a receiver from
// another primitive (planar, blob) use at the receiver's point.
vec3 lightTermAt(int i, vec3 worldPos, vec3 n) {
    vec3 l = toLight(i, worldPos);
    float ndotl = max(dot(n, l), 0.0);
    return lightColorRange(i).rgb * (ndotl * lightFalloff(i, worldPos, l));
}

// `--lighting vertex` (SB_VERTEX_LIGHTING, Scene::lighting): Gouraud shading. The vertex stage
// evaluates each light at the vertex, writeVertexLighting, and the fragment stage interpolates
// (colour x falloff, n.l) per light: glmark2's and many mobile engines' model, a different image
// wherever the term is not affine across a triangle (point and spot lights, curved meshes). n.l is interpolated with
// its sign and clamped per fragment, so a triangle that turns away from the light fades where n.l
// crosses 0 instead of at its vertices; a back face (drawn only where culling cannot hide it) takes
// -n.l, as the per-fragment path flips its normal. SB_LIGHT_TERMS is the scene's light count (at most
// 4, addLightKindDefines). A stage that shades no surface of its own (planar's and blob's shadow
// polygons darken a receiver from another primitive, lightTermAt) defines SB_NO_LIGHT_TERMS before the
// include: its vertex stage writes no terms, so its fragment stage declares none. Vulkan numbers the
// varyings in declaration order (vk/ShaderModuleCache.cpp), so every stage that declares vLightTerms
// includes this file before its other varyings: the terms come first on both sides.
#if defined(SB_VERTEX_LIGHTING) && !defined(SB_NO_LIGHT_TERMS)
#ifdef SB_VERTEX_SHADER
out vec4 vLightTerms[SB_LIGHT_TERMS]; // rgb: colour times lightFalloff; a: n.l with its sign
void writeVertexLighting(vec3 worldPos, vec3 n) {
    for (int i = 0; i < SB_LIGHT_TERMS; ++i) {
        vec3 l = toLight(i, worldPos);
        vLightTerms[i] = vec4(lightColorRange(i).rgb * lightFalloff(i, worldPos, l), dot(n, l));
    }
}
#else
in vec4 vLightTerms[SB_LIGHT_TERMS];
#endif
#endif

// Light i's unshadowed term for the lit surface being shaded: evaluated at this fragment, or under
// SB_VERTEX_LIGHTING interpolated from the vertices (worldPos and n are then unused).
#if defined(SB_VERTEX_LIGHTING) && !defined(SB_NO_LIGHT_TERMS) && defined(SB_FRAGMENT_SHADER)
vec3 lightTerm(int i, vec3 worldPos, vec3 n) {
    float ndotl = gl_FrontFacing ? vLightTerms[i].a : -vLightTerms[i].a;
    return vLightTerms[i].rgb * max(ndotl, 0.0);
}
#else
vec3 lightTerm(int i, vec3 worldPos, vec3 n) { return lightTermAt(i, worldPos, n); }
#endif

// Whether light i's shadow applies to a fragment of the instance with colour-and-id `colorId`: not for a
// light that casts none (SB_SHADOWLESS_LIGHTS, a bit per light) nor on an instance that receives none
// (SB_NON_RECEIVERS: its id is negative). Both are compile-time, set only for scenes that have them
// (CompileContext::defines): otherwise this is the constant true and costs nothing.
// SB_NON_RECEIVER_DRAWS: the program draws only instances that receive no shadow (a technique that
// draws its receivers and its non-receivers apart, techniques/ReceiverSplit.h), so no shadow
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
