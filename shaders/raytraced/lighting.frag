// `raytraced` lighting pass (techniques/raytraced/RayTracedVulkan.h): the scene lit as common/lit.frag
// lights it, each light's term times its visibility, which rays traced from this fragment decide
// (Boksansky, Wimmer and Bittner, "Ray Traced Shadows: Maintaining Real-Time Frame Rates", Ray Tracing
// Gems ch. 13: the visible surface from the rasteriser, shadow rays from it towards the lights).
// Vulkan only: GL has no ray queries.
//
// Per light i, in the Embree reference's order (reference/ReferenceTracer.h), with n the geometric normal
// of the side the camera sees:
//   no light arrives (n faces away from the light, or the point is outside a spot's cone or beyond a
//   light's range): visibility 0, no ray;
//   the light casts no shadow or the instance receives none (shadowApplies): 1, no ray;
//   otherwise the mode's rays decide, each counted in uRayCount.
// Modes (one define each, techniques/raytraced/RayTraced.h):
//   RT_MODE_HARD  one ray towards the light's centre: to a point or spot light's position, stopping
//                 2^-12 of the distance short of it (as the reference does, so geometry at the light,
//                 a lantern's bulb, does not occlude), or against a directional light's direction.
//   RT_MODE_SOFT  an area light (SB_EMITTERS, raytraced/emitter.glsl): RT_SIDE^2 rays from the offset
//                 origin to the jittered strata of its emitter, as the reference's soft shadows
//                 (reference/ReferenceTracer.cpp, softPixel): an emitter point on the emitter's dark
//                 side or under the surface's horizon counts as not seen, without a ray; the others
//                 are seen unless a ray to them (stopping 2^-12 short, as above) is occluded; the
//                 visibility is the fraction seen of all RT_SIDE^2. Where the light's shadow does not
//                 apply no ray is traced and every valid point above the horizon is seen (the
//                 reference's rule, so near the horizon it is below 1). A delta light: as RT_MODE_HARD.
//                 The strata's jitter depends on the pixel alone (emitter.glsl's sequence, frame 0): a
//                 static scene draws the same frame every time.
//   RT_TEMPORAL   (with RT_MODE_SOFT) the jitter is drawn afresh each frame (emitter.glsl's sequence at
//                 frame uFrame) and the visibility shown is a moving average over frames, kept in uHistory
//                 (a channel per light; layer uFrame & 1 written, the other read): the running mean of
//                 the uHistoryFrames frames before and this one, the new frame weighing at least
//                 RT_HISTORY_WEIGHT (techniques/raytraced/RayTraced.h). uHistoryFrames is 0 after the
//                 camera or the scene moved (RayTracedVulkan): the history is not read then.
//   RT_MODE_GUIDED  hard's ray only where the light's depth map is unsure (raytraced/guided.glsl); the
//                 decisions taken without a ray are counted in uDecided.
#extension GL_EXT_ray_query : require
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec3 vEyeRelativePos; // SB_EYE_RELATIVE_POSITION (common/scene.vert)
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

// The ray counter below is a side effect: without this, the depth test would move after the shader and
// hidden fragments would trace too. Early tests draw the same image (no discard, no depth written here).
layout(early_fragment_tests) in;

layout(set = 1, binding = 0) uniform accelerationStructureEXT uScene;
// Rays this frame (the `rays_traced` counter: 64 bits in two words, raytraced/count64.glsl), zeroed by the
// frame before the pass; the frame's index and the frames the history holds (RT_TEMPORAL), written by the
// frame before the pass.
layout(std430, set = 1, binding = 1) buffer FrameState {
    uint uRayCount;
    uint uRayCountHigh;
    uint uFrame;
    uint uHistoryFrames;
};
#ifdef RT_TEMPORAL
layout(set = 1, binding = 2, rgba32f) uniform image2DArray uHistory;
#endif

#include "raytraced/count64.glsl"
#include "raytraced/rays.glsl"

// Directional lights: as far as the scene can reach (finite, as the ray query's limits ask).
const float kFarAway = 1.0e30;
// Rays towards a point stop this fraction of the distance short of it (reference/ReferenceTracer.cpp).
const float kShortOfLight = 1.0 - 1.0 / 4096.0;

// Unit geometric normal of the side the camera sees: the plane of the screen-space derivatives of the
// position (every fragment of a triangle lies in its plane), turned towards the eye. Taken from the
// eye-relative position, whose small coordinates keep the derivatives exact enough where the world's are
// large. The shading normal where the derivatives are degenerate (a triangle seen edge-on covers no area).
vec3 seenGeometricNormal(vec3 fromEye, vec3 shading) {
    vec3 g = cross(dFdx(fromEye), dFdy(fromEye));
    float len2 = dot(g, g);
    if (!(len2 > 0.0)) return shading;
    g *= inversesqrt(len2);
    return dot(g, fromEye) > 0.0 ? -g : g;
}

// Whether light i reaches a point at p with normal n at all, the direction towards it and how far a
// shadow ray may go (`reach`): the light's centre.
bool lightArrives(int i, vec3 p, vec3 n, out vec3 towards, out float reach) {
    if (isPositional(i)) {
        vec3 d = uLightPos[i].xyz - p;
        reach = length(d);
        if (!(reach > 0.0)) return false;
        towards = d / reach;
    } else {
        towards = -uLightDir[i].xyz;
        reach = kFarAway;
    }
    if (!(dot(n, towards) > 0.0)) return false;
    return lightFalloff(i, p, towards) > 0.0;
}

// One ray from the offset origin to light i's centre (`towards` it, for a directional light): 1 lit,
// 0 shadowed; 1 without a ray where its shadow does not apply.
float traceCentre(int i, vec3 p, vec3 n, vec3 towards, bool occludable, inout uint rays) {
    if (!occludable) return 1.0;
    vec3 o = offsetRayOrigin(p, n);
    ++rays;
    if (!isPositional(i)) return occluded(o, towards, kFarAway) ? 0.0 : 1.0;
    vec3 d = uLightPos[i].xyz - o;
    float len = length(d);
    return occluded(o, d / len, len * kShortOfLight) ? 0.0 : 1.0;
}

#ifdef RT_MODE_HARD
float traceVisibility(int i, vec3 p, vec3 n, vec3 towards, bool occludable, inout uint rays) {
    return traceCentre(i, p, n, towards, occludable, rays);
}
#endif

#ifdef RT_MODE_SOFT
#include "raytraced/emitter.glsl"

float traceVisibility(int i, vec3 p, vec3 n, vec3 towards, bool occludable, inout uint rays) {
    vec4 emitter = lightEmitter(i);
    if (emitterIsDelta(emitter)) return traceCentre(i, p, n, towards, occludable, rays);
    vec3 o = offsetRayOrigin(p, n);
#ifdef RT_TEMPORAL
    uint state = emitterSeed(uvec2(gl_FragCoord.xy), uFrame);
#else
    uint state = emitterSeed(uvec2(gl_FragCoord.xy), 0u);
#endif
    int seen = 0;
    for (int k = 0; k < RT_SIDE * RT_SIDE; ++k) {
        EmitterSample s =
            emitterSample(emitter, uLightPos[i].xyz, uLightDir[i].xyz, o, emitterStratum(k, RT_SIDE, state));
        if (!s.valid || !(dot(n, s.direction) > 0.0)) continue; // sends no light here: not seen, no ray
        if (occludable) {
            ++rays;
            if (occluded(o, s.direction, min(s.distance * kShortOfLight, kFarAway))) continue;
        }
        ++seen;
    }
    return float(seen) / float(RT_SIDE * RT_SIDE);
}
#endif

#ifdef RT_TEMPORAL
// This frame's visibility averaged with the history's, and stored for the next frame.
vec4 accumulate(vec4 vis) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int written = int(uFrame & 1u);
    vec4 mean = vis;
    if (uHistoryFrames > 0u) {
        float weight = max(1.0 / float(uHistoryFrames + 1u), RT_HISTORY_WEIGHT);
        mean = mix(imageLoad(uHistory, ivec3(pixel, 1 - written)), vis, weight);
    }
    imageStore(uHistory, ivec3(pixel, written), mean);
    return mean;
}
#endif

#ifdef RT_MODE_GUIDED
#include "raytraced/guided.glsl"
#endif

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 ng = seenGeometricNormal(vEyeRelativePos, n); // before any branch: derivatives
    vec4 vis = vec4(1.0);
    uint rays = 0u;
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 towards;
        float reach;
        if (!lightArrives(i, vWorldPos, ng, towards, reach))
            vis[i] = 0.0;
        else
#ifdef RT_MODE_GUIDED
            vis[i] = shadowApplies(i, vColorId) ? guidedOrTraced(i, vWorldPos, ng, towards, rays) : 1.0;
#else
            vis[i] = traceVisibility(i, vWorldPos, ng, towards, shadowApplies(i, vColorId), rays);
#endif
    }
    if (rays > 0u) COUNT64_ADD(uRayCount, uRayCountHigh, rays);
#ifdef RT_MODE_GUIDED
    if (gGuideDecided > 0u) COUNT64_ADD(uDecided, uDecidedHigh, gGuideDecided);
#endif
#ifdef RT_TEMPORAL
    vis = accumulate(vis);
#endif
    vec3 light = ambientLight();
    for (int i = 0; i < LIGHT_COUNT; ++i) light += vis[i] * lightTerm(i, vWorldPos, n);
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
