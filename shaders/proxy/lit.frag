// `proxy` fragment stage: the ShadowProxy-enabled fragment shader (van der Spek, "ShadowProxies",
// OpenGL Insights, section 1.4). Per fragment: find its IndexMap cell (Listing 1.2), walk the indices
// of the proxies overlapping it (0 ends the list), skip the fragment's own object's proxies (the
// chapter's self-shadow skip), and for each proxy whose influence volume contains the fragment
// accumulate shadow (Listing 1.3), modulated per light to the egg-shaped volume (Listing 1.4), and
// colour bleeding towards the light (section 1.5, the same term with the normal reversed).
//
// Defines: LIGHT_COUNT; PROXY_GRID (else every proxy in view is tested: grid=off); PROXY_MODULATE
// (Listing 1.4, only when the scene has a light to modulate towards); PROXY_BLEED (only when the
// scene asks for colour bleeding); PROXY_EXPONENT_ON_FACTOR (Listing 1.3 as printed: the exponent
// raises the shadow factor, not the attenuation).
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

// One proxy in view, in the order the CPU numbered them (techniques/ProxyTechnique.h, GpuProxy).
// The chapter packs each proxy into one mat4 and builds its transform per fragment; here the inverse
// is computed once per proxy on the CPU (Listing 1.1's inverse(proxy) per fragment and proxy would be
// the most expensive line of the loop).
struct Proxy {
    mat4 toLocal;    // world -> unit shape
    mat4 toWorld;    // unit shape -> world (the proxy's frame)
    vec4 diffuse;    // rgb: colour bled towards the light; w: shape 0 sphere, 1 box, 2 cylinder
    vec4 reflective; // rgb: colour bled whatever the light; w: object id of the instance it stands for
};
layout(std430, binding = 2) readonly buffer ProxyParams {
    Proxy uProxies[];
};
#ifdef PROXY_GRID
// The IndexMap: per cell uCapacity entries, each a proxy index + 1, 0 ending the list. 32-bit
// entries: the chapter's GLubyte texels capped the indices at 255.
layout(std430, binding = 3) readonly buffer ProxyIndexMap {
    uint uIndexMap[];
};
layout(location = 20) uniform ivec2 uCells;    // grid cells along x and y
layout(location = 21) uniform vec2 uViewport;  // pixels
layout(location = 22) uniform int uCapacity;   // entries per cell
#else
layout(location = 23) uniform int uProxyCount; // proxies in view
#endif
layout(location = 16) uniform vec4 uShading;   // x: ProxyOffset, y: shadow factor, z: falloff exponent, w: cutoff
layout(location = 18) uniform float uStart;    // distance from the surface where the falloff starts
#ifdef PROXY_BLEED
layout(location = 17) uniform float uBleed;    // amount of colour bleeding
#endif

// Listing 1.1 in the proxy's local frame: the positive octant's boundary point, signs put back.
// sign(0) is 0 in GLSL, which would put a point on a symmetry plane onto the axis instead of the
// surface; 0 is taken as +1. The sphere's centre (normalize(0) = NaN) maps to the local +z pole.
vec3 closestLocal(int shape, vec3 local) {
    vec3 sgn = mix(vec3(1.0), vec3(-1.0), lessThan(local, vec3(0.0)));
    vec3 a = abs(local);
    if (shape == 0) {
        float len = length(a);
        a = len > 0.0 ? a / len : vec3(0.0, 0.0, 1.0);
    } else if (shape == 1) {
        a = min(a, vec3(1.0));
    } else {
        float r = length(a.xy);
        if (r > 1.0) a.xy /= r;
        a.z = min(a.z, 1.0);
    }
    return sgn * a;
}

// Inside any of the three shapes the fragment is in the full shadow (distance 0). The listing's
// sphere pushes an inside point out to the surface, which would lighten the shadow towards the
// sphere's centre; box and cylinder leave inside points where they are. All three behave alike here.
bool insideLocal(int shape, vec3 local) {
    vec3 a = abs(local);
    if (shape == 0) return dot(a, a) <= 1.0;
    if (shape == 1) return all(lessThanEqual(a, vec3(1.0)));
    return dot(a.xy, a.xy) <= 1.0 && a.z <= 1.0;
}

#ifdef PROXY_MODULATE
// The outward normal at the closest point (Listing 1.4's surface.normal), local, then to world through
// the inverse transpose: n_world ~ transpose(mat3(toLocal)) * n_local = n_local * mat3(toLocal).
vec3 surfaceNormal(int shape, vec3 local, vec3 closest, mat4 toLocal) {
    vec3 n;
    if (shape == 0) {
        n = closest;
    } else if (shape == 1) {
        // The face the point is pushed onto: the axis of largest |local| (inside: the nearest face).
        vec3 a = abs(local);
        int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        n = vec3(0.0);
        n[axis] = closest[axis] < 0.0 ? -1.0 : 1.0;
    } else {
        float radial = length(local.xy);
        n = abs(local.z) >= 1.0 && radial <= 1.0 ? vec3(0.0, 0.0, local.z < 0.0 ? -1.0 : 1.0)
            : (radial > 0.0 ? vec3(local.xy / radial, 0.0) : vec3(0.0, 0.0, local.z < 0.0 ? -1.0 : 1.0));
    }
    return normalize(n * mat3(toLocal));
}

// Direction the light travels at world point p (from the light into the scene).
vec3 lightTravel(int i, vec3 p) {
    if (uLightPos[i].w == 0.0) return uLightDir[i].xyz;
    vec3 d = p - uLightPos[i].xyz;
    float len = length(d);
    return len > 0.0 ? d / len : uLightDir[i].xyz;
}
#endif

// Listing 1.3: 1 at the surface, 0 at ProxyOffset; ProxyOffset <= 0 shrinks the volume to the surface
// (no division by zero). The exponent shapes the attenuation (section 1.2: "the falloff of the
// shadows as the exponent to the attenuation function") unless PROXY_EXPONENT_ON_FACTOR reproduces the
// listing as printed (the exponent applied to the constant shadow factor).
// uStart (section 1.2's "cutoff ... an offset between the surface and the start of the shadow
// falloff") keeps the full shadow up to that distance; 0 is Listing 1.3 exactly.
float attenuation(float dist, float factor) {
    float span = uShading.x - uStart, d = max(dist - uStart, 0.0);
    float base = span > 0.0 ? 1.0 - clamp(min(d / span, 1.0), 0.0, 1.0) : (d <= 0.0 ? 1.0 : 0.0);
#ifdef PROXY_EXPONENT_ON_FACTOR
    return base * pow(factor, uShading.z);
#else
    return base > 0.0 ? pow(base, uShading.z) * factor : 0.0;
#endif
}

struct Accum {
    vec4 visibility; // per light, product of (1 - shadow)
    float ambient;   // unmodulated halo: the chapter's light subtraction in a diffusely lit scene
    vec3 bleed;      // added light from colour bleeding
};

void applyProxy(int index, int self, inout Accum acc) {
    Proxy p = uProxies[index];
    if (int(p.reflective.w + 0.5) == self) return; // Listing 1.2: ignore self-shadows
    int shape = int(p.diffuse.w + 0.5);
    vec3 local = (p.toLocal * vec4(vWorldPos, 1.0)).xyz;
    vec3 closest = closestLocal(shape, local);
    vec3 surface = (p.toWorld * vec4(closest, 1.0)).xyz;
    vec3 away = vWorldPos - surface;
    float dist = insideLocal(shape, local) ? 0.0 : length(away);
    if (!(dist > 0.0)) dist = 0.0; // a fragment on the surface within rounding
    if (dist > uShading.x) return; // outside the influence volume
    float shadow = attenuation(dist, uShading.y);
    acc.ambient *= 1.0 - clamp(shadow, 0.0, 1.0);
#ifdef PROXY_BLEED
    float bleed = attenuation(dist, uBleed);
    acc.bleed += bleed * p.reflective.rgb * uAmbient.rgb;
#endif
#ifdef PROXY_MODULATE
    // Section 1.5: the direction the shadow is cast along is the one from the closest surface point to
    // the fragment; on the surface (or inside) the surface normal. Unlike the normal of the face a
    // point is pushed onto, it turns continuously round a box's edges and corners (no seams).
    vec3 n = dist > 0.0 ? away / dist : surfaceNormal(shape, local, closest, p.toLocal);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 travel = lightTravel(i, surface);
        // Listing 1.4: the shadow stretched away from the light (normal along the light's travel) ...
        acc.visibility[i] *= 1.0 - clamp(shadow * clamp(dot(travel, n), uShading.w, 1.0), 0.0, 1.0);
#ifdef PROXY_BLEED
        // ... and the bleeding towards it, the same with the normal reversed.
        acc.bleed += bleed * max(clamp(dot(-travel, n), uShading.w, 1.0), 0.0) * p.diffuse.rgb * uLightColor[i].rgb;
#endif
    }
#else
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        acc.visibility[i] *= 1.0 - clamp(shadow, 0.0, 1.0);
#ifdef PROXY_BLEED
        acc.bleed += bleed * p.diffuse.rgb * uLightColor[i].rgb;
#endif
    }
#endif
}

Accum proxies(int self) {
    Accum acc = Accum(vec4(1.0), 1.0, vec3(0.0));
#ifdef PROXY_GRID
    // Listing 1.2: the cell of this fragment, then its indices until a 0.
    ivec2 cell = clamp(ivec2(floor(gl_FragCoord.xy / uViewport * vec2(uCells))), ivec2(0), uCells - 1);
    int base = (cell.y * uCells.x + cell.x) * uCapacity;
    for (int k = 0; k < uCapacity; ++k) {
        uint entry = uIndexMap[base + k];
        if (entry == 0u) break;
        applyProxy(int(entry) - 1, self, acc);
    }
#else
    for (int k = 0; k < uProxyCount; ++k) applyProxy(k, self, acc);
#endif
    return acc;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    Accum acc = proxies(int(vColorId.w + 0.5));
    vec3 light = uAmbient.rgb * acc.ambient;
    for (int i = 0; i < LIGHT_COUNT; ++i) light += acc.visibility[i] * lightTerm(i, vWorldPos, n);
#ifdef PROXY_BLEED
    light += acc.bleed;
#endif
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = acc.visibility;
}
