// The part every SSR technique shares: bindings, which pixels to shade, the reflected ray and the
// result. A technique includes this and defines
//     bool ssrTrace(SsrRay ray, out vec2 hitPixel);
// returning the pixel (centre coordinates) whose lit colour the ray reflects, or false for a miss.
// Binding 9 takes the path lengths (kSsrWriteDistance), 10 and 11 are the environment's
// (common/environment.glsl); define SSR_USES_HIZ before including to bind the depth hierarchy (12).
#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "gpu/scene_data.h"
#include "ppr_common/tiles.h"
#include "ssr_common/ssr.h"

layout(local_size_x = kPprTileSize, local_size_y = kPprTileSize) in;
layout(set = 0, binding = 1) uniform sampler2D depthTex;    // reverse-Z: near / view distance, 0 = sky
layout(set = 0, binding = 2) uniform sampler2D normalTex;
layout(set = 0, binding = 3) uniform sampler2D materialTex;
layout(set = 0, binding = 4) uniform usampler2D reflectorTex;
layout(set = 0, binding = 5) uniform sampler2D sceneColor;  // lit scene, bilinear
layout(set = 0, binding = 6, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 7, scalar) readonly buffer TileLists { uint tileLists[]; };
layout(set = 0, binding = 8, rgba16f) uniform image2D outReflection;
layout(set = 0, binding = 9, rg32f) uniform writeonly image2D outDistance;  // kSsrWriteDistance: common/reflection.h
#ifdef SSR_USES_HIZ
layout(set = 0, binding = 12, r32f) uniform readonly image2D hizAtlas;
#endif
layout(push_constant, scalar) uniform Push { SsrPush pc; };
#define ENV_BINDING 10  // the probe's data and cube (10, 11)
#include "common/environment.glsl"
#include "gbuffer/motion_slot.glsl"

bool environmentUsesProbe() { return (pc.flags & kSsrEnvironmentProbe) != 0u; }

// The reflected ray. View space looks down −Z; `k` is 1/w = 1/view distance, affine along the
// screen-space segment, so the distance at a fraction t of it is 1 / mix(k0, k1, t).
struct SsrRay {
    vec3 viewOrigin, viewEnd;  // view space; the end clipped at the near plane (not at the screen)
    vec2 p0, p1;               // pixels; p1 clipped to the screen
    float k0, k1;              // 1/distance at p0 and p1
    vec3 worldOrigin;          // the reflecting surface point (world space; the environment's box projection)
    vec3 worldDir;             // the reflected direction (world space)
};

bool ssrTrace(SsrRay ray, out vec2 hitPixel);

float ssrNear() { return frame.cameraPos.w; }

// View distance of the surface with depth-buffer sample d (infinite for sky).
float ssrSurfaceDistanceOf(float d) { return d > 0.0 ? ssrNear() / d : 1e30; }

// View distance of the surface seen at an integer pixel (infinite for sky).
float ssrSurfaceDistance(ivec2 pix) { return ssrSurfaceDistanceOf(texelFetch(depthTex, pix, 0).r); }

float ssrThicknessAt(float surfaceDistance) { return ssrThickness(surfaceDistance, pc.thickness, pc.thicknessScale); }

// Is the ray at distance rayDistance hitting the surface at pixel `pix` (behind it, within thickness)?
bool ssrHitsSurface(ivec2 pix, float rayDistance) {
    float s = ssrSurfaceDistance(pix);
    return rayDistance >= s && rayDistance <= s + ssrThicknessAt(s);
}

bool ssrOnScreen(vec2 p) { return all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, frame.screenSize)); }

// Projects a view-space point: pixel coordinates and k = 1/w.
vec2 ssrProject(vec3 v, out float k) {
    vec4 h = frame.proj * vec4(v, 1.0);
    k = 1.0 / h.w;
    return (h.xy * k * 0.5 + 0.5) * frame.screenSize;
}

// Largest t in [0, 1] keeping p0 + t (p1 − p0) inside the screen (p0 is inside).
float ssrScreenExit(vec2 p0, vec2 p1) {
    vec2 d = p1 - p0;
    vec2 lo = vec2(0.5), hi = frame.screenSize - 0.5;
    float t = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] > 1e-6) t = min(t, (hi[axis] - p0[axis]) / d[axis]);
        else if (d[axis] < -1e-6) t = min(t, (lo[axis] - p0[axis]) / d[axis]);
    }
    return clamp(t, 0.0, 1.0);
}

bool ssrSetupRay(ivec2 pix, float depth, uint reflectorId, out SsrRay ray) {
    vec3 world = worldOfPixel(pix, depth);
    vec3 mapped = normalize(texelFetch(normalTex, pix, 0).xyz);
    vec3 n = mapped;
    // Reflector pixels: the reflector's plane, as PPR and planar see it; with normal maps on, the
    // mapped normal where it leaves the plane.
    if (reflectorId != 0u) {
        n = reflectors[reflectorId - 1u].normal;
        if ((pc.flags & kSsrMappedNormals) != 0u && dot(mapped, n) < kFlatNormalCos) n = mapped;
    }
    vec3 v = normalize(world - frame.cameraPos.xyz);
    if (dot(v, n) >= 0.0) return false;  // the reflecting side faces away from the camera
    vec3 r = reflect(v, n);
    ray.worldOrigin = world;
    ray.worldDir = r;
    float distance = length(world - frame.cameraPos.xyz);
    // Lift the origin off the surface so the first samples do not find the surface itself.
    vec3 origin = world + n * (1e-3 * distance);
    ray.viewOrigin = (frame.view * vec4(origin, 1.0)).xyz;
    vec3 viewDir = mat3(frame.view) * r;
    float rayLength = pc.maxDistance;
    float nearZ = -ssrNear() * 1.001;
    if (ray.viewOrigin.z + viewDir.z * rayLength > nearZ) rayLength = (nearZ - ray.viewOrigin.z) / viewDir.z;
    if (!(rayLength > 0.0)) return false;
    ray.viewEnd = ray.viewOrigin + viewDir * rayLength;
    ray.p0 = ssrProject(ray.viewOrigin, ray.k0);
    vec2 p1 = ssrProject(ray.viewEnd, ray.k1);
    float t = ssrScreenExit(ray.p0, p1);
    ray.p1 = mix(ray.p0, p1, t);
    ray.k1 = mix(ray.k0, ray.k1, t);
    return true;
}

ivec2 ssrPixel() {
    if ((pc.flags & kSsrIndirect) == 0u) return ivec2(gl_GlobalInvocationID.xy);
    uvec2 tile = pprUnpackTile(tileLists[pc.listClass * pc.tileCount + gl_WorkGroupID.x]);
    return ivec2(tile * kPprTileSize + gl_LocalInvocationID.xy);
}

void main() {
    ivec2 pix = ssrPixel();
    if (any(greaterThanEqual(pix, ivec2(frame.screenSize)))) return;
    uint id = texelFetch(reflectorTex, pix, 0).r;
    bool reflective = texelFetch(materialTex, pix, 0).b > 0.5;  // gbuffer.h: material b = reflective flag
    uint pixelClass = id != 0u ? kTileClassPlanar : (reflective ? kTileClassOther : kTileClassCount);
    bool shade = pixelClass != kTileClassCount && (pc.pixelClasses & (1u << pixelClass)) != 0u;
    if (shade && pixelClass == kTileClassPlanar && (pc.flags & kSsrHolesOnly) != 0u) {
        float kind = imageLoad(outReflection, pix).a;
        if (kind != kReflectionNone && kind != kReflectionEnvironment) return;  // PPR's own reflection stays
        // Only where the mapped normal leaves the plane: on a flat mirror a hole is a point nothing on
        // screen shows, which the same ray marched would not find either.
        vec3 mapped = normalize(texelFetch(normalTex, pix, 0).xyz);
        if ((pc.flags & kSsrMappedNormals) == 0u || dot(mapped, reflectors[id - 1u].normal) >= kFlatNormalCos) return;
    }
    bool writeDistance = (pc.flags & kSsrWriteDistance) != 0u;
    if (!shade) {
        if ((pc.flags & kSsrWriteAll) != 0u) {
            imageStore(outReflection, pix, vec4(0.0));
            if (writeDistance) imageStore(outDistance, pix, vec4(0.0));
        }
        return;
    }
    vec4 result = vec4(0.0);
    vec2 path = vec2(0.0);  // reflected-path image (common/reflection.h): eye → surface → reflected point, 0 = none
    float depth = texelFetch(depthTex, pix, 0).r;
    SsrRay ray;
    vec2 hit;
    bool env = (pc.flags & kSsrEnvironment) != 0u;
    if (depth > 0.0 && ssrSetupRay(pix, depth, id, ray)) {
        if (ssrTrace(ray, hit)) {
            vec3 c = textureLod(sceneColor, hit * frame.invScreenSize, 0.0).rgb;
            result = vec4(env ? environmentBlend(c, hit, ray.worldOrigin, ray.worldDir) : c, kReflectionHit);
            // The reflected point is the surface seen at the hit pixel, moving with that pixel's draw.
            vec3 reflected = worldFromDepth(hit * frame.invScreenSize, texelFetch(depthTex, ivec2(hit), 0).r);
            path = vec2(distance(frame.cameraPos.xyz, ray.worldOrigin) + distance(ray.worldOrigin, reflected),
                        pathTag(motionSlotOf(texelFetch(materialTex, ivec2(hit), 0)), 0u));
        } else if (env) {
            result = vec4(environmentRadiance(ray.worldOrigin, ray.worldDir), kReflectionEnvironment);
        }
    }
    imageStore(outReflection, pix, result);
    if (writeDistance) imageStore(outDistance, pix, vec4(path, 0.0, 0.0));
}
