// Emitter samples for ray-traced soft shadows: the maps of the Embree reference's reference/LightSampler
// (the same frames, the same area- and solid-angle-preserving maps, the same validity rules), so that a
// ray-traced soft shadow estimates the quantity the reference computes: the UNWEIGHTED fraction of the
// emitter that a point sees (reference/LightSampler.h says what that is for each shape). Self-contained
// (no include, no uniform): the caller passes the light's position and direction, which motion changes,
// and its emitter constant (techniques/raytraced/LightEmitter.h), which it does not.
//
// The stratified sequence (emitterStratum): a side x side grid over [0,1)^2 (side = the rays' square root,
// LightSampler::gridSide), stratum k = (k % side, k / side), each jittered by two uniforms drawn from a
// per-pixel stream, as LightSampler::stratumPoint jitters each stratum:
//   state_0   = emitterSeed(pixel, frame) = hash(pixel.x ^ hash(pixel.y ^ hash(frame)))
//   state_n+1 = hash(state_n),  uniform_n = (state_n+1 >> 8) * 2^-24   (24 bits: exact in a float)
//   u_k       = min((vec2(k % side, k / side) + vec2(uniform_2k, uniform_2k+1)) / side, 1 - 2^-24)
// hash is the PCG hash of Jarzynski and Olano, "Hash Functions for GPU Rendering" (JCGT 9(3), 2020),
// section 3 (pcg, their recommended all-round 32-bit hash). The image depends on the pixel and the frame
// index only: a static scene draws the same frame every time (frame 0), and temporal accumulation draws
// a fresh jitter per frame by passing the frame index.

const int kEmitterPoint = 0;     // positional delta light: towards the position, valid from everywhere
const int kEmitterDirection = 1; // directional delta light: along -direction, infinitely far
const int kEmitterRect = 2;      // one-sided rect: constant.y by constant.z
const int kEmitterDisk = 3;      // one-sided disk: radius constant.y
const int kEmitterSphere = 4;    // sphere: radius constant.y
const int kEmitterCone = 5;      // the sun: cos(angular radius) in constant.w

// One emitter sample seen from a ray origin (LightSampler::Sample).
struct EmitterSample {
    vec3 direction; // unit, from the origin towards the emitter point
    float distance; // to the emitter point; +infinity for directional lights
    bool valid;     // false: the point cannot receive light from this sample
};

float emitterInfinity() { return uintBitsToFloat(0x7f800000u); }

#ifdef SB_EMITTERS
// Light i's emitter constant (techniques/raytraced/LightEmitter.h, addEmitterDefines).
const vec4 kLightEmitters[4] = SB_EMITTERS;
vec4 lightEmitter(int i) { return kLightEmitters[i]; }
#endif

int emitterKind(vec4 emitter) { return int(emitter.x); }
// A delta light: one ray, a hard shadow (LightSampler::isDelta).
bool emitterIsDelta(vec4 emitter) { return emitterKind(emitter) <= kEmitterDirection; }

// A unit up vector not parallel to the unit `d` (scenes/Math.h, anyPerpendicularUp).
vec3 emitterUp(vec3 d) { return abs(d.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0); }

// Orthonormal tangents t, b of a unit axis (LightSampler.cpp's tangentFrame): the emitter's u and v for
// axis = w = normalize(direction).
void emitterTangents(vec3 axis, out vec3 t, out vec3 b) {
    t = normalize(cross(emitterUp(axis), axis));
    b = cross(axis, t);
}

// Unit vector at polar angle acos(cosTheta) and azimuth phi around the frame (t, b, axis).
vec3 emitterConeDirection(float cosTheta, float phi, vec3 t, vec3 b, vec3 axis) {
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    return sinTheta * cos(phi) * t + sinTheta * sin(phi) * b + cosTheta * axis;
}

// Shirley and Chiu's concentric map of the unit square onto the unit disk ("A Low Distortion Map Between
// Disk and Square", 1997): area-preserving, and square strata stay compact.
vec2 emitterConcentricDisk(vec2 u) {
    vec2 s = 2.0 * u - 1.0;
    if (s.x == 0.0 && s.y == 0.0) return vec2(0.0);
    const float quarter = 0.78539816339744831; // pi / 4
    if (abs(s.x) > abs(s.y)) {
        float phi = quarter * (s.y / s.x);
        return s.x * vec2(cos(phi), sin(phi));
    }
    float phi = 2.0 * quarter - quarter * (s.x / s.y);
    return s.y * vec2(cos(phi), sin(phi));
}

// Towards `point` on a one-sided planar emitter facing along +w (or on a point light when !oneSided).
EmitterSample emitterTowards(vec3 origin, vec3 point, vec3 w, bool oneSided) {
    EmitterSample s;
    vec3 d = point - origin;
    s.distance = length(d);
    s.direction = vec3(0.0);
    s.valid = false;
    if (!(s.distance > 0.0)) return s;
    s.direction = d / s.distance;
    // Light leaves a rect or disk along +w only: a receiver behind its plane (or on it) gets nothing.
    s.valid = !oneSided || dot(s.direction, w) < 0.0;
    return s;
}

// The sphere of radius r around `centre`: uniform in solid angle over the cap the origin sees, the ray
// ending at the near hit; from inside, every direction, ending where it leaves the sphere.
EmitterSample emitterSphere(vec3 origin, vec3 centre, float r, vec2 u) {
    EmitterSample s;
    vec3 toCentre = centre - origin;
    float d = length(toCentre);
    float phi = 6.2831853071795865 * u.y;
    if (!(d > r)) {
        vec3 dir = emitterConeDirection(1.0 - 2.0 * u.x, phi, vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0),
                                        vec3(0.0, 1.0, 0.0));
        float b = dot(dir, toCentre), c = d * d - r * r;
        s.direction = dir;
        s.distance = b + sqrt(max(0.0, b * b - c));
        s.valid = true;
        return s;
    }
    vec3 axis = toCentre / d;
    vec3 t, bt;
    emitterTangents(axis, t, bt);
    float sinAlpha = r / d;
    float cosAlpha = sqrt(max(0.0, 1.0 - sinAlpha * sinAlpha));
    float cosTheta = 1.0 - u.x * (1.0 - cosAlpha);
    s.direction = emitterConeDirection(cosTheta, phi, t, bt, axis);
    float sin2 = max(0.0, 1.0 - cosTheta * cosTheta);
    s.distance = d * cosTheta - sqrt(max(0.0, r * r - d * d * sin2));
    s.valid = s.distance > 0.0;
    return s;
}

// The sample of the light with emitter constant `emitter`, centre or position `position` and unit
// direction `direction` (from the light into the scene) for `u` in [0,1)^2, seen from `origin`
// (LightSampler::sample). A delta light ignores u.
EmitterSample emitterSample(vec4 emitter, vec3 position, vec3 direction, vec3 origin, vec2 u) {
    int kind = emitterKind(emitter);
    vec3 w = normalize(direction);
    if (kind == kEmitterPoint) return emitterTowards(origin, position, w, false);
    if (kind == kEmitterSphere) return emitterSphere(origin, position, emitter.y, u);
    vec3 eu, ev;
    emitterTangents(w, eu, ev);
    if (kind == kEmitterRect) {
        vec3 point = position + (u.x - 0.5) * emitter.y * eu + (u.y - 0.5) * emitter.z * ev;
        return emitterTowards(origin, point, w, true);
    }
    if (kind == kEmitterDisk) {
        vec2 d = emitter.y * emitterConcentricDisk(u);
        return emitterTowards(origin, position + d.x * eu + d.y * ev, w, true);
    }
    // The sun, and a directional delta light (its cone has cos 1: exactly -w).
    EmitterSample s;
    float cosMax = kind == kEmitterCone ? emitter.w : 1.0;
    float cosTheta = 1.0 - u.x * (1.0 - cosMax);
    s.direction = emitterConeDirection(cosTheta, 6.2831853071795865 * u.y, eu, ev, -w);
    s.distance = emitterInfinity();
    s.valid = true;
    return s;
}

// The PCG hash (see the top of this file).
uint emitterHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The first state of a pixel's stream: the pixel and the frame index, nothing else.
uint emitterSeed(uvec2 pixel, uint frame) {
    return emitterHash(pixel.x ^ emitterHash(pixel.y ^ emitterHash(frame)));
}

// The stream's next uniform in [0, 1), 24 bits.
float emitterUniform(inout uint state) {
    state = emitterHash(state);
    return float(state >> 8u) * (1.0 / 16777216.0);
}

// The jittered point of stratum k of a side x side grid (LightSampler::stratumPoint); draws two uniforms.
vec2 emitterStratum(int k, int side, inout uint state) {
    float inv = 1.0 / float(side);
    float jx = emitterUniform(state);
    float jy = emitterUniform(state);
    // min() keeps the point inside [0,1) when rounding would push (side-1 + ~1)/side to 1.
    const float below1 = 0.99999994039535522; // 1 - 2^-24, the float below 1
    return vec2(min((float(k % side) + jx) * inv, below1), min((float(k / side) + jy) * inv, below1));
}
