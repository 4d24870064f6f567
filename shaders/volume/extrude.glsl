// The chapter's extrusion (Listing 9-3), shared by volume/extrude.vert and volume/silhouette.geom: p sent
// to infinity away from the object-space light uLightObject, or by uRange under FINITE (section 9.6.1).
vec4 extrude(vec3 p) {
    vec3 away = p * uLightObject.w - uLightObject.xyz; // from the light through p (Listing 9-3)
#ifdef FINITE
    return vec4(p + normalize(away) * uRange, 1.0);
#else
    return vec4(away, 0.0);
#endif
}
