// The tangent-space normal map's rule, shared by the G-buffer (gbuffer/gbuffer_body.glsl) and the
// ray-traced reference (raytrace/raytrace_common.glsl) so that both bend a normal the same way.
// Each caller keeps its own texel fetch: the rasterizer's derivatives there, the ray's footprint here.

// The frame around normal n (already flipped to the side that faces the viewer): the tangent made
// orthogonal to n, the bitangent signed by the tangent's w. False where the tangent is degenerate
// (parallel to n or zero), and the caller then keeps n and need not fetch the map at all.
bool normalMapFrame(vec3 n, vec4 tangent, out vec3 t, out vec3 b) {
    t = tangent.xyz - n * dot(n, tangent.xyz);
    if (!(dot(t, t) > 1e-12)) {  // written so that a NaN tangent counts as degenerate too
        b = vec3(0.0);
        return false;
    }
    t = normalize(t);
    b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    return true;
}

// n bent by the map's texel (in [0, 1], as stored) in the frame t, b, n. glTF's normalTexture.scale
// scales x and y; z is kept above zero so a bent normal never turns to the surface's back.
vec3 mappedNormal(vec3 n, vec3 t, vec3 b, vec3 texel, float scale) {
    vec3 tn = texel * 2.0 - 1.0;
    tn.xy *= scale;
    return normalize(t * tn.x + b * tn.y + n * max(tn.z, 1e-3));
}
