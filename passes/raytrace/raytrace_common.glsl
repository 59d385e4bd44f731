// The ray-traced reference, shared by the screen pass (raytrace_reflect.comp) and the glass-atlas
// pass (raytrace_glass.comp): trace one mirror ray through the scene's TLAS with a ray query, shade the
// hit exactly as the lighting pass shades a G-buffer pixel (lighting/shade.glsl, shadow map included),
// and classify it with the planar reference's rules (common/reflection.h):
//   miss (sky)                                 → skyRadiance(dir), kReflectionOffscreen
//   hit on a surface bound to a reflector      → kReflectionSecondary (planar: "a second bounce")
//   hit visible in the main view               → kReflectionHit (the pixels compare scores)
//   hit off screen or occluded in the main view → kReflectionOffscreen
// The includer includes common/bindings.glsl first; bindings 0..10 of set 0 and set 1 are declared
// here, the includer's own bindings start at 11.
#extension GL_EXT_ray_query : require
#extension GL_EXT_nonuniform_qualifier : require
#include "common/brdf.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "common/normal_mapping.glsl"
#include "gbuffer/gbuffer.h"
#include "gpu/scene_data.h"
#include "planar/planar.h"  // the tolerance of "visible in the main view", as the planar reference judges it
#include "raytrace/raytrace.h"

layout(set = 0, binding = 1) uniform sampler2D depthTex;  // the main view's depth
layout(set = 0, binding = 2) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = 3, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 4, scalar) readonly buffer DrawReflectors { uint drawReflectors[]; };  // per draw: reflector id
layout(set = 0, binding = 5, scalar) readonly buffer Loose { uint looseReflectors[]; };
layout(set = 0, binding = 6, scalar) readonly buffer Vertices { VertexData vertices[]; };
layout(set = 0, binding = 7, scalar) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = 8, scalar) readonly buffer Draws { DrawData draws[]; };
layout(set = 0, binding = 9, scalar) readonly buffer Materials { MaterialData materials[]; };
layout(set = 0, binding = 10) uniform accelerationStructureEXT tlas;
layout(set = 1, binding = 0) uniform sampler2D textures[];
layout(push_constant, scalar) uniform Push { RaytracePush pc; };

#include "lighting/shade.glsl"

// Unit direction of the eye ray through a screen position (pixels).
vec3 eyeRayDir(vec2 screenPos) { return normalize(worldFromDepth(screenPos * frame.invScreenSize, 1.0) - frame.cameraPos.xyz); }

// Where the eye ray along d meets reflector r's plane (false when it does not, from the reflecting side).
bool onPlane(ReflectorData r, vec3 d, out vec3 p) {
    float denom = dot(d, r.normal);
    if (denom >= 0.0) return false;
    p = frame.cameraPos.xyz + d * (dot(r.center - frame.cameraPos.xyz, r.normal) / denom);
    return true;
}

// The parameter at which a ray leaving reflector r's plane rises kRaytraceClipOffset above it: the
// planar reference's mirrored view clips everything closer to the plane. `dir` must leave the plane.
float clipT(ReflectorData r, vec3 origin, vec3 dir) {
    return max((kRaytraceClipOffset - dot(origin - r.center, r.normal)) / dot(dir, r.normal), 0.0);
}

#include "planar/main_view.glsl"

// The reflector id (index + 1, 0 = none) of a hit surface, as a G-buffer rendered from the mirrored eye
// would write it: the draw's binding, else a loose reflector whose rectangle holds the point
// (`eyeDistance`: from the mirrored eye, which is the path length from the real eye).
uint hitReflectorId(uint draw, vec3 p, float eyeDistance) {
    uint id = drawReflectors[draw];
    float tolerance = kLooseSurfaceTolerance + kLooseSurfaceTolerancePerMetre * eyeDistance;
    for (uint k = 0u; k < pc.looseCount && id == 0u; ++k) {
        ReflectorData r = reflectors[looseReflectors[k]];
        if (abs(dot(p - r.center, r.normal)) <= tolerance && reflectorContains(r, p)) id = looseReflectors[k] + 1u;
    }
    return id;
}

// Values as the G-buffer stores them (albedo RGBA8 sRGB, material RGBA8 unorm, normal RGBA16F), so
// that a hit is lit from the same inputs as the lighting pass reads for that surface.
float srgbEncode(float c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }
float srgbDecode(float c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }
float unorm8(float x) { return round(clamp(x, 0.0, 1.0) * 255.0) / 255.0; }
vec3 storedAlbedo(vec3 c) {
    return vec3(srgbDecode(unorm8(srgbEncode(c.r))), srgbDecode(unorm8(srgbEncode(c.g))), srgbDecode(unorm8(srgbEncode(c.b))));
}
vec3 storedNormal(vec3 n) { return vec3(unpackHalf2x16(packHalf2x16(n.xy)), unpackHalf2x16(packHalf2x16(vec2(n.z, 0.0))).x); }
// An unsigned float with `mantissaBits` (B10G11R11: 6, 6, 5), rounded to nearest.
float smallFloat(float x, float mantissaBits) {
    if (!(x > 0.0)) return 0.0;
    float step = exp2(max(floor(log2(x)), -14.0) - mantissaBits);
    return min(round(x / step) * step, 65024.0);
}
vec3 storedEmissive(vec3 e) { return vec3(smallFloat(e.r, 6.0), smallFloat(e.g, 6.0), smallFloat(e.b, 5.0)); }

// A draw's triangle in world space (as the G-buffer's vertex shader transforms it).
struct HitTriangle {
    VertexData v0, v1, v2;
    vec3 p0, p1, p2;
};
HitTriangle hitTriangle(uint draw, uint prim) {
    DrawData d = draws[draw];
    uint base = d.firstIndex + 3u * prim;
    HitTriangle h;
    h.v0 = vertices[int(indices[base]) + d.vertexOffset];
    h.v1 = vertices[int(indices[base + 1u]) + d.vertexOffset];
    h.v2 = vertices[int(indices[base + 2u]) + d.vertexOffset];
    h.p0 = (d.world * vec4(h.v0.position, 1.0)).xyz;
    h.p1 = (d.world * vec4(h.v1.position, 1.0)).xyz;
    h.p2 = (d.world * vec4(h.v2.position, 1.0)).xyz;
    return h;
}

// Where the ray meets a triangle's plane: the parameter, and the barycentrics (b0, b1, b2) there,
// outside [0, 1] beyond its edges (as a rasterizer's helper pixels extrapolate). False when the ray
// runs parallel to it.
bool rayOnTriangle(HitTriangle h, vec3 origin, vec3 dir, out float t, out vec3 b) {
    vec3 e1 = h.p1 - h.p0, e2 = h.p2 - h.p0, ng = cross(e1, e2);
    float denom = dot(dir, ng);
    t = 0.0;
    b = vec3(1.0, 0.0, 0.0);
    if (abs(denom) < 1e-12 * dot(ng, ng)) return false;
    t = dot(h.p0 - origin, ng) / denom;
    vec3 w = origin + dir * t - h.p0;
    float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(w, e1), d21 = dot(w, e2);
    float den = d00 * d11 - d01 * d01;
    if (den <= 0.0) return false;
    b.y = (d11 * d20 - d01 * d21) / den;
    b.z = (d00 * d21 - d01 * d20) / den;
    b.x = 1.0 - b.y - b.z;
    return true;
}

// Texture coordinates of the rays of a 2x2 pixel quad, reflected off a reflector, on a hit triangle's
// plane, and their differences: what a rasterizer's fragment quad computes as derivatives. `coarse`
// are the quad's (top-left to its right and lower neighbours, one pair for all four pixels), `fine`
// the pixel's own row and column pair.
struct Footprint {
    vec2 coarseX, coarseY, fineX, fineY;
};

// The planar reference rasterizes the hit surface from the mirrored eye at the same pixel grid; the
// rays of the pixel's quad, reflected off the reflector about the same normal, are exactly the mirrored
// camera's rays for a flat mirror, so these derivatives are the rasterizer's (extrapolated over the
// triangle's plane beyond its edges, as helper pixels are).
Footprint rayFootprint(HitTriangle h, ReflectorData plane, vec3 n, ivec2 pix) {
    Footprint f = Footprint(vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    ivec2 q = pix & ~1;
    vec2 uv[4];  // top-left, top-right, bottom-left, bottom-right
    for (int k = 0; k < 4; ++k) {
        vec3 d = eyeRayDir(vec2(q + ivec2(k & 1, k >> 1)) + 0.5), o, b;
        float t;
        if (!onPlane(plane, d, o) || !rayOnTriangle(h, o, reflect(d, n), t, b)) return f;
        uv[k] = h.v0.uv * b.x + h.v1.uv * b.y + h.v2.uv * b.z;
    }
    f.coarseX = uv[1] - uv[0];
    f.coarseY = uv[2] - uv[0];
    f.fineX = (pix.y & 1) == 0 ? uv[1] - uv[0] : uv[3] - uv[2];
    f.fineY = (pix.x & 1) == 0 ? uv[2] - uv[0] : uv[3] - uv[1];
    return f;
}

ivec2 wrapRepeat(ivec2 t, ivec2 size) { return t - size * ivec2(floor(vec2(t) / vec2(size))); }  // (GLSL's % is undefined below 0)

// Bilinear filtering of one mip level, repeat addressing.
vec4 bilinear(uint tex, vec2 uv, int level, ivec2 size) {
    vec2 p = uv * vec2(size) - 0.5;
    ivec2 i = ivec2(floor(p));
    vec2 f = p - vec2(i);
    vec4 a = texelFetch(textures[nonuniformEXT(tex)], wrapRepeat(i, size), level);
    vec4 b = texelFetch(textures[nonuniformEXT(tex)], wrapRepeat(i + ivec2(1, 0), size), level);
    vec4 c = texelFetch(textures[nonuniformEXT(tex)], wrapRepeat(i + ivec2(0, 1), size), level);
    vec4 d = texelFetch(textures[nonuniformEXT(tex)], wrapRepeat(i + ivec2(1, 1), size), level);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

// The material sampler (linear, mipmapped, repeat, maxAnisotropy 8) as lavapipe (Mesa 25) filters a
// fragment shader's implicit-derivative sample: the mip level from the quad's footprint along its
// minor axis (unless the major one is more than 8 times longer: then the major one over 8), truncated,
// not blended; then N = ceil(longer fine derivative in that level's texels) ≤ 16 bilinear probes of
// that level, evenly spread (centred) over the pixel's fine derivative along the longer screen axis,
// averaged. Matched against the G-buffer's albedo on primary rays: 52-56 dB without the 1 % worst
// (silhouette) pixels. Written out because sampling through the anisotropic sampler from this compute
// shader would take its derivatives from neighbouring invocations (whatever unrelated rays hit) and
// ignore textureGrad's (docs/raytraced.md).
const float kMaxAnisotropy = 8.0;  // shader::Samplers::linearRepeatAniso
const int kMaxProbes = 16;
vec4 sampleFootprint(uint tex, vec2 uv, Footprint f) {
    ivec2 size0 = textureSize(textures[nonuniformEXT(tex)], 0);
    int levels = textureQueryLevels(textures[nonuniformEXT(tex)]);
    vec2 gx = f.coarseX * vec2(size0), gy = f.coarseY * vec2(size0);
    float px2 = dot(gx, gx), py2 = dot(gy, gy);
    float pmax2 = max(px2, py2), pmin2 = min(px2, py2);
    if (pmax2 > pmin2 * kMaxAnisotropy * kMaxAnisotropy) pmin2 = pmax2 / (kMaxAnisotropy * kMaxAnisotropy);
    int level = pmin2 > 1.0 ? min(int(0.5 * log2(pmin2)), levels - 1) : 0;
    ivec2 size = max(size0 >> level, ivec2(1));  // (lavapipe's textureSize ignores a level here)
    float rhoX = max(abs(f.fineX.x), abs(f.fineX.y)) * float(size.x);
    float rhoY = max(abs(f.fineY.x), abs(f.fineY.y)) * float(size.y);
    int n = clamp(int(ceil(max(rhoX, rhoY))), 1, kMaxProbes);
    vec2 axis = rhoX > rhoY ? f.fineX : f.fineY;
    vec4 sum = vec4(0.0);
    float rcpN = 1.0 / float(n);
    for (int k = 0; k < n; ++k) sum += bilinear(tex, uv + ((float(k) + 0.5) * rcpN - 0.5) * axis, level, size);
    return sum * rcpN;
}

vec4 sampleMaterial(uint tex, vec2 uv, Footprint f, vec4 fallback) { return tex == kNoTexture ? fallback : sampleFootprint(tex, uv, f); }

// What the ray sees when it finds nothing: the sky, as the lighting pass draws it along dir.
vec4 skyReflection(vec3 dir) { return vec4(skyRadiance(dir), kReflectionOffscreen); }

// The reflection of a hit: primitive `prim` of `draw` at barycentrics b, at parameter t along the
// ray from `origin` (on reflector `plane`, whose screen pixel is `pix`; `n` is the normal
// the ray was reflected about, `eyeDistance` the distance from the eye to `origin`): rgb = radiance,
// a = kind (see the top of this file).
vec4 shadeHit(ReflectorData plane, vec3 n, ivec2 pix, vec3 origin, vec3 dir, float eyeDistance, uint draw, uint prim, float t, vec3 b) {
    DrawData d = draws[draw];
    MaterialData m = materials[d.material];
    HitTriangle h = hitTriangle(draw, prim);
    mat3 normalMatrix = mat3(d.normalMatrix), world3 = mat3(d.world);
    vec3 vNormal = normalMatrix * h.v0.normal * b.x + normalMatrix * h.v1.normal * b.y + normalMatrix * h.v2.normal * b.z;
    vec4 vTangent = vec4(world3 * h.v0.tangent.xyz, h.v0.tangent.w) * b.x + vec4(world3 * h.v1.tangent.xyz, h.v1.tangent.w) * b.y +
                    vec4(world3 * h.v2.tangent.xyz, h.v2.tangent.w) * b.z;
    vec2 uv = h.v0.uv * b.x + h.v1.uv * b.y + h.v2.uv * b.z;
    vec3 hit = origin + dir * t;

    // Material, sampled with the rasterizer's footprint (rayFootprint).
    Footprint footprint = rayFootprint(h, plane, n, pix);
    uv = materialUv(m, uv);
    footprint = Footprint(materialUvDelta(m, footprint.coarseX), materialUvDelta(m, footprint.coarseY), materialUvDelta(m, footprint.fineX),
                          materialUvDelta(m, footprint.fineY));
    vec4 baseColor = m.baseColor * sampleMaterial(m.baseColorTex, uv, footprint, vec4(1.0));
    if ((d.flags & kDrawVertexColors) != 0u)
        baseColor *= vertexColor(h.v0.color) * b.x + vertexColor(h.v1.color) * b.y + vertexColor(h.v2.color) * b.z;
    vec4 mr = sampleMaterial(m.metalRoughTex, uv, footprint, vec4(1.0));

    // The G-buffer's rules: two-sided (the side facing the viewer, by winding, as the rasterizer
    // decides front faces), then the normal map in the interpolated tangent frame.
    bool front = dot(cross(h.p1 - h.p0, h.p2 - h.p0), dir) < 0.0;
    vec3 sn = normalize(front ? vNormal : -vNormal);
    vec3 tg, bt;
    if (m.normalTex != kNoTexture && normalMapFrame(sn, vTangent, tg, bt))
        sn = mappedNormal(sn, tg, bt, sampleMaterial(m.normalTex, uv, footprint, vec4(0.5, 0.5, 1.0, 1.0)).xyz, m.normalScale);
    vec3 albedo = storedAlbedo(baseColor.rgb);
    float roughness = unorm8(clamp(m.roughness * mr.g, 0.02, 1.0)), metallic = unorm8(clamp(m.metallic * mr.b, 0.0, 1.0));
    vec3 shadingNormal = normalize(storedNormal(sn));

    // Lit as the lighting pass lights it, seen from the mirrored eye: the view vector is −dir.
    float shadow;
    vec3 color = shadeSurface(hit, shadingNormal, -dir, albedo, roughness, metallic, shadow) +
                 storedEmissive(m.emissive * sampleMaterial(m.emissiveTex, uv, footprint, vec4(1.0)).rgb);
    float kind = kReflectionOffscreen;
    if (hitReflectorId(draw, hit, eyeDistance + t) != 0u) kind = kReflectionSecondary;
    else if (visibleInMainView(depthTex, hit, sn)) kind = kReflectionHit;
    return vec4(color, kind);
}

// Whether a candidate hit on an alpha-masked surface (the only non-opaque geometry) is kept: its base
// colour alpha at the hit, read from the finest mip level, against the material's cutoff.
bool passesAlphaMask(uint draw, uint prim, vec2 bary) {
    DrawData d = draws[draw];
    MaterialData m = materials[d.material];
    HitTriangle h = hitTriangle(draw, prim);
    float b0 = 1.0 - bary.x - bary.y;
    vec2 uv = materialUv(m, h.v0.uv * b0 + h.v1.uv * bary.x + h.v2.uv * bary.y);
    float alpha = m.baseColor.a;
    if ((d.flags & kDrawVertexColors) != 0u)
        alpha *= vertexColor(h.v0.color).a * b0 + vertexColor(h.v1.color).a * bary.x + vertexColor(h.v2.color).a * bary.y;
    if (m.baseColorTex != kNoTexture) alpha *= textureLod(textures[nonuniformEXT(m.baseColorTex)], uv, 0.0).a;
    return alpha >= m.alphaCutoff;
}

// The distance from `origin` to the last shaded reflection's hit (reflectionOf, which traceReflection and
// rasterCoverageReflection end in), 0 when it hit nothing (the sky), and the hit draw's motion slot (0:
// still, or nothing hit).
float traceHitT = 0.0;
uint traceHitSlot = 0u;

// The nearest hit along `dir` from `origin` (the planar reference's clip respected, alpha masks
// tested): false for none (the sky).
struct RayHit {
    uint draw, prim;
    float t;
    vec3 b;  // barycentrics (b0, b1, b2)
};
bool traceNearest(ReflectorData plane, vec3 origin, vec3 dir, out RayHit hit) {
    rayQueryEXT query;
    rayQueryInitializeEXT(query, tlas, gl_RayFlagsNoneEXT, 0xFFu, origin, clipT(plane, origin, dir), dir, 1e7);
    while (rayQueryProceedEXT(query)) {
        if (rayQueryGetIntersectionTypeEXT(query, false) == gl_RayQueryCandidateIntersectionTriangleEXT &&
            passesAlphaMask(uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false)),
                            uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false)), rayQueryGetIntersectionBarycentricsEXT(query, false)))
            rayQueryConfirmIntersectionEXT(query);
    }
    hit = RayHit(0u, 0u, 0.0, vec3(1.0, 0.0, 0.0));
    if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionTriangleEXT) return false;
    vec2 bary = rayQueryGetIntersectionBarycentricsEXT(query, true);
    hit = RayHit(uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, true)), uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, true)),
                 rayQueryGetIntersectionTEXT(query, true), vec3(1.0 - bary.x - bary.y, bary.x, bary.y));
    return true;
}

// The reflection of `hit` (or the sky along `dir` when `found` is false), shaded (see shadeHit); sets
// traceHitT and traceHitSlot.
vec4 reflectionOf(bool found, RayHit hit, ReflectorData plane, vec3 n, ivec2 pix, vec3 origin, vec3 dir, float eyeDistance) {
    traceHitT = found ? hit.t : 0.0;
    traceHitSlot = found ? draws[hit.draw].motionSlot : 0u;
    if (!found) return skyReflection(dir);
    return shadeHit(plane, n, pix, origin, dir, eyeDistance, hit.draw, hit.prim, hit.t, hit.b);
}

// The reflection seen along `dir` from `origin`: the nearest hit, shaded.
vec4 traceReflection(ReflectorData plane, vec3 n, ivec2 pix, vec3 origin, vec3 dir, float eyeDistance) {
    RayHit hit;
    bool found = traceNearest(plane, origin, dir, hit);
    return reflectionOf(found, hit, plane, n, pix, origin, dir, eyeDistance);
}
