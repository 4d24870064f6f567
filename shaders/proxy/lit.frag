// `proxy` fragment stage: the ShadowProxy-enabled fragment shader (van der Spek, "ShadowProxies",
// OpenGL Insights, section 1.4). Per fragment: find its IndexMap cell (Listing 1.2), walk the indices
// of the proxies overlapping it (0 ends the list), skip the fragment's own object's proxies (the
// chapter's self-shadow skip), and for each proxy whose influence volume contains the fragment
// accumulate shadow (Listing 1.3), modulated per light to the egg-shaped volume (Listing 1.4), and
// colour bleeding towards the light (section 1.5, the same term with the normal reversed). A receiver
// inside or touching a proxy gets the same halo, continued from the contact line along the receiver
// (exitLocal): soft and continuous there too, never a hard full shadow.
//
// Defines: LIGHT_COUNT; PROXY_GRID (else every proxy in view is tested: grid=off); PROXY_MODULATE
// (Listing 1.4, only when the scene has a light to modulate towards); PROXY_RAYS (with PROXY_MODULATE:
// the modulated halo kept only where the ray towards the light passes through or near the proxy,
// rayShadow); PROXY_BLEED (only when the
// scene asks for colour bleeding); PROXY_EXPONENT_ON_FACTOR (Listing 1.3 as printed: the exponent
// raises the shadow factor, not the attenuation).
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

// One proxy in view, in the order the CPU numbered them (techniques/proxy/ProxyGL.h, GpuProxy).
// The chapter packs each proxy into one mat4 and builds its transform per fragment; here the inverse
// is computed once per proxy on the CPU (Listing 1.1's inverse(proxy) per fragment and proxy would be
// the most expensive line of the loop).
struct Proxy {
    mat4 toLocal;    // world -> unit shape
    mat4 toWorld;    // unit shape -> world (the proxy's frame)
    vec4 diffuse;    // rgb: colour bled towards the light; w: shape 0 sphere, 1 box, 2 cylinder
    vec4 reflective; // rgb: colour bled whatever the light; w: object id of the instance it stands for
};
#ifdef VULKAN
// Set 1 (techniques/proxy/ProxyVulkan.h): the uniforms GL sets by location in one block, then the two
// storage buffers. uViewport.y flips gl_FragCoord's y to GL's lower-left origin (the grid's rows are
// GL's, bottom up).
layout(std140, set = 1, binding = 0) uniform ProxyBlock {
    vec4 uShading;    // x: ProxyOffset, y: shadow factor, z: falloff exponent, w: cutoff
    ivec2 uCells;     // grid cells along x and y
    vec2 uViewport;   // pixels
    float uStart;     // distance from the surface where the falloff starts
    float uPenumbra;  // tan of the penumbra's half-angle seen from the receiver
    float uBleed;     // amount of colour bleeding
    int uCapacity;    // entries per cell
    int uProxyCount;  // proxies in view
};
layout(std430, set = 1, binding = 1) readonly buffer ProxyParams {
    Proxy uProxies[];
};
#ifdef PROXY_GRID
layout(std430, set = 1, binding = 2) readonly buffer ProxyIndexMap {
    uint uIndexMap[];
};
#endif
#else
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
#ifdef PROXY_RAYS
layout(location = 19) uniform float uPenumbra; // tan of the penumbra's half-angle seen from the receiver
#endif
#ifdef PROXY_BLEED
layout(location = 17) uniform float uBleed;    // amount of colour bleeding
#endif
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

// Inside the shape or touching it: within 1e-4 of its size outside counts as touching, so a receiver
// lying on a face (a caster's fitted box standing on the ground) is one case, not a rounding coin toss
// between inside and a distance of 1e-7 in a random direction.
bool touchingLocal(int shape, vec3 local) {
    const float grace = 1.0 + 1e-4;
    vec3 a = abs(local);
    if (shape == 0) return dot(a, a) <= grace * grace;
    if (shape == 1) return all(lessThanEqual(a, vec3(grace)));
    return dot(a.xy, a.xy) <= grace * grace && a.z <= grace;
}

// A receiver inside (or touching) a proxy sees it where the proxy over-estimates its caster (the
// proxy encloses the geometry; this fragment is visible through it). Listing 1.1's sphere pushes an
// inside point out to the surface, so its shadow fades with the depth inside; here every shape does,
// and the depth is measured along the receiver: the distance t within the receiver's tangent plane to
// where it leaves the proxy (for a box the nearest of the lines where its faces cross that plane, a
// face the receiver lies in never bounding it), so the halo runs on into the contact region from
// the contact line with the same falloff as outside, and a receiver lying on a face is not a point at
// distance 0 (the hard black footprint the listing would give under every caster on the ground).
// Curved surfaces (sphere, cylinder side) stand in as their tangent plane at the radially nearest
// point: exact at the contact line, a little farther inside. weighted / weights is the direction the
// shadow is cast along: the faces' outward normals weighted by 1 / t_f^2, so it is the crossing
// face's own normal at the contact line (where the halo outside has it too: no seam with modulation)
// and turns smoothly between faces inside (no seam where the nearest face changes).
struct Exit {
    float t;        // in-plane distance to the nearest exit (1e30: none)
    vec3 weighted;  // sum of outward normal / t^2
    float weights;  // sum of 1 / t^2
};

void addExitAt(inout Exit e, vec3 n, float t) {
    e.t = min(e.t, t);
    float w = 1.0 / (t * t + 1e-30);
    e.weighted += w * n;
    e.weights += w;
}

// The two parallel planes local[axis] = +1 and -1 (a box's faces, a cylinder's caps) at once: they
// share the world normal (up to sign) and its angle with the receiver. `gradient` is the world
// gradient of local[axis] (row `axis` of mat3(toLocal)), whose length turns local into world distance.
void addExitPair(inout Exit e, vec3 gradient, float local, vec3 receiverNormal) {
    // |gradient|^2 sin^2 = |g|^2 - (g.N)^2: two inverse square roots, no division.
    float g2 = dot(gradient, gradient), gc = dot(gradient, receiverNormal);
    float s2 = g2 - gc * gc;
    if (!(s2 > 1e-6 * g2)) return; // sine below 1e-3: the receiver's plane is parallel to these faces
    float scale = inversesqrt(s2); // local depth -> in-plane world distance, 1 / (|g| sine)
    vec3 n = gradient * inversesqrt(g2);
    addExitAt(e, n, max(1.0 - local, 0.0) * scale);
    addExitAt(e, -n, max(1.0 + local, 0.0) * scale);
}

// One plane: outward world normal `normal` (unnormalised, as nl * mat3(toLocal)) and local depth.
void addExit(inout Exit e, vec3 normal, float depth, vec3 receiverNormal) {
    float len = length(normal);
    if (!(len > 0.0)) return;
    vec3 n = normal / len;
    float c = dot(n, receiverNormal);
    float sine = sqrt(max(1.0 - c * c, 0.0));
    if (sine < 1e-3) return;
    addExitAt(e, n, max(depth, 0.0) / (len * sine));
}

// Plane of the shape's surface in local coordinates (unit normal nl, points x with dot(nl, x) = 1 for
// the box's faces; for curved surfaces the tangent plane at the radially nearest point) to world:
// normal nl * mat3(toLocal), depth (1 - dot(nl, local)) before dividing by that normal's length.
Exit exitLocal(int shape, vec3 local, mat4 toLocal, vec3 receiverNormal) {
    Exit e = Exit(1e30, vec3(0.0), 0.0);
    mat3 m = mat3(toLocal);
    if (shape == 1) {
        // Written out: an indexed row or component is a dynamic index on llvmpipe.
        addExitPair(e, vec3(m[0].x, m[1].x, m[2].x), local.x, receiverNormal);
        addExitPair(e, vec3(m[0].y, m[1].y, m[2].y), local.y, receiverNormal);
        addExitPair(e, vec3(m[0].z, m[1].z, m[2].z), local.z, receiverNormal);
        return e;
    }
    if (shape == 2) {
        addExitPair(e, vec3(m[0].z, m[1].z, m[2].z), local.z, receiverNormal);
        float r = length(local.xy);
        vec3 nl = r > 0.0 ? vec3(local.xy / r, 0.0) : vec3(1.0, 0.0, 0.0);
        addExit(e, nl * m, 1.0 - r, receiverNormal);
        return e;
    }
    float r = length(local);
    vec3 nl = r > 0.0 ? local / r : vec3(0.0, 0.0, 1.0);
    addExit(e, nl * m, 1.0 - r, receiverNormal);
    return e;
}

#ifdef PROXY_MODULATE
// Direction the light travels at world point p (from the light into the scene).
vec3 lightTravel(int i, vec3 p) {
    if (uLightPos[i].w == 0.0) return uLightDir[i].xyz;
    vec3 d = p - uLightPos[i].xyz;
    float len = length(d);
    return len > 0.0 ? d / len : uLightDir[i].xyz;
}
#endif

#ifdef PROXY_RAYS
// Narrows [lo, hi] to the ray's parameters where its coordinate o + t d lies in [-1, 1] (one slab of
// the unit shape); a ray parallel to the slab keeps it whole or empties it.
void clipSlab(float o, float d, inout float lo, inout float hi) {
    if (abs(d) < 1e-12) {
        if (abs(o) > 1.0) hi = -1.0;
        return;
    }
    float a = (-1.0 - o) / d, b = (1.0 - o) / d;
    lo = max(lo, min(a, b));
    hi = min(hi, max(a, b));
}

// Narrows [lo, hi] to where |o + t d| <= 1 (o, d: 2D for the cylinder's side, 3D for the sphere).
// A ray that misses the round shape narrows it to its point nearest the axis or centre (an empty
// interval unless that point is what [lo, hi] holds), the candidate for the miss distance.
void clipRound(float oo, float od, float dd, inout float lo, inout float hi) {
    if (dd < 1e-24) {
        if (oo > 1.0) hi = -1.0;
        return;
    }
    float disc = od * od - dd * (oo - 1.0);
    float root = sqrt(max(disc, 0.0));
    lo = max(lo, (-od - root) / dd);
    hi = min(hi, disc < 0.0 ? -1.0 : (-od + root) / dd);
    if (disc < 0.0) lo = -od / dd;
}

// The ray o + t d, 0 <= t <= reach, against the unit shape (exact: slabs and quadrics): its
// parameters inside the shape are [lo, hi], empty (lo > hi) when it misses; then the gap between
// where it leaves one bound and enters another is where it passes nearest.
vec2 rayInterval(int shape, vec3 o, vec3 d, float reach) {
    float lo = 0.0, hi = reach;
    if (shape == 0) {
        clipRound(dot(o, o), dot(o, d), dot(d, d), lo, hi);
    } else if (shape == 1) {
        clipSlab(o.x, d.x, lo, hi);
        clipSlab(o.y, d.y, lo, hi);
        clipSlab(o.z, d.z, lo, hi);
    } else {
        clipRound(dot(o.xy, o.xy), dot(o.xy, d.xy), dot(d.xy, d.xy), lo, hi);
        clipSlab(o.z, d.z, lo, hi);
    }
    return vec2(lo, hi);
}

// World distance from the ray's point at parameter t to the proxy, over the penumbra's width there.
float missRatio(Proxy p, int shape, vec3 origin, vec3 dir, vec3 pos, vec3 toLight, float t) {
    if (!(t > 0.0)) return 1e30;
    vec3 closest = closestLocal(shape, origin + dir * t);
    return length((p.toWorld * vec4(closest, 1.0)).xyz - (pos + toLight * t)) / (uPenumbra * t);
}

// How much of the light the proxy hides from world point `pos` along the ray towards it (`toLight`,
// unit, `reach` long): 1 where the ray passes through the proxy (exact test in the unit shape's
// space), else falling to 0 where it misses by uPenumbra times the distance along the ray (the
// penumbra of a light of that angular radius: hard at contact, soft far from the caster). Listing
// 1.4's egg only weighs the halo by the direction from the proxy; under a low light a thin caster's
// shadow is a long thin streak, and the egg darkens a half disc round its foot that the light
// reaches. The miss distance is taken at the ends and middle of the gap the clipping leaves (where
// a near miss passes nearest an edge or the round side), continuous with the hit as the gap closes.
float rayShadow(Proxy p, int shape, vec3 pos, vec3 toLight, float reach) {
    vec3 origin = (p.toLocal * vec4(pos, 1.0)).xyz;
    vec3 dir = mat3(p.toLocal) * toLight;
    if (touchingLocal(shape, origin)) return 1.0;
    vec2 span = rayInterval(shape, origin, dir, reach);
    if (span.x <= span.y) return 1.0;
    float a = clamp(span.y, 0.0, reach), b = clamp(span.x, 0.0, reach);
    float ratio = min(missRatio(p, shape, origin, dir, pos, toLight, a),
                      min(missRatio(p, shape, origin, dir, pos, toLight, b),
                          missRatio(p, shape, origin, dir, pos, toLight, 0.5 * (a + b))));
    return 1.0 - clamp(ratio, 0.0, 1.0);
}

// Where the ray towards light i from `pos` ends: a directional light's never does.
float lightReach(int i, vec3 pos) {
    return uLightPos[i].w == 0.0 ? 1e30 : length(uLightPos[i].xyz - pos);
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

void applyProxy(int index, int self, vec3 receiverNormal, inout Accum acc) {
    Proxy p = uProxies[index];
    if (int(p.reflective.w + 0.5) == self) return; // Listing 1.2: ignore self-shadows
    int shape = int(p.diffuse.w + 0.5);
    vec3 local = (p.toLocal * vec4(vWorldPos, 1.0)).xyz;
    vec3 closest = closestLocal(shape, local);
    vec3 surface = (p.toWorld * vec4(closest, 1.0)).xyz;
    float dist;
    vec3 castDir; // the direction the shadow is cast along (section 1.5), towards the fragment
    if (touchingLocal(shape, local)) {
        Exit e = exitLocal(shape, local, p.toLocal, receiverNormal);
        dist = e.t;
        // Unit where one or two faces dominate (at a box's corner the bisector, as the halo outside
        // has it there), shrinking smoothly to 0 where opposite faces balance (no direction to cast).
        vec3 w = e.weights > 0.0 ? e.weighted / e.weights : vec3(0.0);
        castDir = w / max(length(w), 0.5);
    } else {
        vec3 away = vWorldPos - surface;
        dist = length(away);
        castDir = dist > 0.0 ? away / dist : vec3(0.0);
    }
    if (dist > uShading.x) return; // outside the influence volume
    float shadow = attenuation(dist, uShading.y);
    acc.ambient *= 1.0 - clamp(shadow, 0.0, 1.0);
#ifdef PROXY_BLEED
    float bleed = attenuation(dist, uBleed);
    acc.bleed += bleed * p.reflective.rgb * ambientLight();
#endif
#ifdef PROXY_MODULATE
    // Section 1.5: the direction the shadow is cast along is the one from the closest surface point to
    // the fragment (inside or touching: the exits' normals, see exitLocal). Unlike the normal of the
    // face a point is pushed onto, it turns continuously round a box's edges and corners (no seams).
    vec3 n = castDir;
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 travel = lightTravel(i, surface);
        // Listing 1.4: the shadow stretched away from the light (normal along the light's travel) ...
        float lobe = clamp(dot(travel, n), uShading.w, 1.0);
#ifdef PROXY_RAYS
        // ... where the light's ray passes the proxy (past the chapter: the long thin streak of a low light).
        if (lobe > 0.0) lobe *= rayShadow(p, shape, vWorldPos, -lightTravel(i, vWorldPos), lightReach(i, vWorldPos));
#endif
        acc.visibility[i] *= 1.0 - clamp(shadow * lobe, 0.0, 1.0);
#ifdef PROXY_BLEED
        // ... and the bleeding towards it, the same with the normal reversed.
        acc.bleed += bleed * max(clamp(dot(-travel, n), uShading.w, 1.0), 0.0) * p.diffuse.rgb * lightColorRange(i).rgb;
#endif
    }
#else
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        acc.visibility[i] *= 1.0 - clamp(shadow, 0.0, 1.0);
#ifdef PROXY_BLEED
        acc.bleed += bleed * p.diffuse.rgb * lightColorRange(i).rgb;
#endif
    }
#endif
}

Accum proxies(int self, vec3 receiverNormal) {
    Accum acc = Accum(vec4(1.0), 1.0, vec3(0.0));
#ifdef PROXY_GRID
    // Listing 1.2: the cell of this fragment, then its indices until a 0.
    vec2 pixel = gl_FragCoord.xy;
#ifdef VULKAN
    pixel.y = uViewport.y - pixel.y; // GL's lower-left origin: the grid's rows are GL's
#endif
    ivec2 cell = clamp(ivec2(floor(pixel / uViewport * vec2(uCells))), ivec2(0), uCells - 1);
    int base = (cell.y * uCells.x + cell.x) * uCapacity;
    for (int k = 0; k < uCapacity; ++k) {
        uint entry = uIndexMap[base + k];
        if (entry == 0u) break;
        applyProxy(int(entry) - 1, self, receiverNormal, acc);
    }
#else
    for (int k = 0; k < uProxyCount; ++k) applyProxy(k, self, receiverNormal, acc);
#endif
    return acc;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
#ifdef SB_NON_RECEIVERS
    // An instance that receives no shadow gets none of the proxies' darkening or bleeding.
    Accum acc = vColorId.w > 0.0 ? proxies(int(vColorId.w + 0.5), n) : Accum(vec4(1.0), 1.0, vec3(0.0));
#else
    Accum acc = proxies(int(vColorId.w + 0.5), n);
#endif
#ifdef SB_SHADOWLESS_LIGHTS
    for (int i = 0; i < LIGHT_COUNT; ++i)
        if (!shadowApplies(i, vColorId)) acc.visibility[i] = 1.0;
#endif
    vec3 light = ambientLight() * acc.ambient;
    for (int i = 0; i < LIGHT_COUNT; ++i) light += acc.visibility[i] * lightTerm(i, vWorldPos, n);
#ifdef PROXY_BLEED
    light += acc.bleed;
#endif
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = acc.visibility;
}
