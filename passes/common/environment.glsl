// The environment behind screen-space reflections (--set fallback_env): what a reflected ray that
// leaves the screen or finds nothing shows, and how a hit near the screen border fades into it, so
// the edge of the screen is not a visible seam. The environment is the sky the lighting pass draws
// (common/brdf.glsl skyRadiance) or, with env_source=probe, the scene's reflection probe
// (env_probe/env_probe.h): a cubemap of the lit scene looked up box-projected where it shows what lies
// on the scene's box, the exact sky along the ray elsewhere (docs/normalmaps.md).
// Needs common/bindings.glsl, common/brdf.glsl and common/reflection.h. The includer defines
// ENV_BINDING first (the probe's data binds there, its cube at ENV_BINDING + 1: passes/common/
// environment.hpp) and, anywhere, `bool environmentUsesProbe()` from its flags.
#include "env_probe/env_probe.h"

layout(set = 0, binding = ENV_BINDING, scalar) uniform EnvProbeBlock { EnvProbeData envProbe; };
layout(set = 0, binding = ENV_BINDING + 1) uniform samplerCube envProbeCube;

bool environmentUsesProbe();

// The probe's view of a ray reflected at `origin` along unit `dir`: rgb, a = 1 where it stands for
// the ray's hit, 0 where it does not (sky). Box projection (parallax correction): the cube is looked up
// from its centre towards the point where the ray leaves the scene's box, which is right for what lies
// on the box (walls at the scene's edge). Checked against the probe's distance there (cube alpha): a
// surface much nearer the probe than that point (a pillar in the courtyard) hides from the probe what
// the ray really passes, so it is not taken.
vec4 environmentProbeHit(vec3 origin, vec3 dir) {
    vec3 d = mix(dir, vec3(1e-6), lessThan(abs(dir), vec3(1e-6)));  // an axis the ray runs along never exits first
    vec3 exits = max((envProbe.boxMin.xyz - origin) / d, (envProbe.boxMax.xyz - origin) / d);
    vec3 q = origin + dir * max(min(min(exits.x, exits.y), exits.z), 0.0) - envProbe.centre.xyz;
    vec4 seen = textureLod(envProbeCube, q, 0.0);
    bool onTheBox = seen.a > 0.0 && seen.a >= (1.0 - kEnvProbeDistanceTolerance) * length(q);
    return onTheBox ? vec4(seen.rgb, 1.0) : vec4(0.0);
}

// What a ray reflected at `origin` (world) along `reflectedDir` sees when the screen cannot tell.
vec3 environmentRadiance(vec3 origin, vec3 reflectedDir) {
    vec3 dir = normalize(reflectedDir);
    if (!environmentUsesProbe()) return skyRadiance(dir);
    vec4 probe = environmentProbeHit(origin, dir);
    return mix(skyRadiance(dir), probe.rgb, probe.a);
}

// 1 well inside the screen, falling to 0 at its border (pixel coordinates of the sample).
float environmentEdgeWeight(vec2 pixel) {
    vec2 d = min(pixel, frame.screenSize - pixel);
    float band = kEnvironmentEdgeFade * min(frame.screenSize.x, frame.screenSize.y);
    return smoothstep(0.0, band, min(d.x, d.y));
}

// A screen-space hit at `pixel` seen along the ray from `origin`, faded into the environment at the border.
vec3 environmentBlend(vec3 hitColor, vec2 pixel, vec3 origin, vec3 reflectedDir) {
    return mix(environmentRadiance(origin, reflectedDir), hitColor, environmentEdgeWeight(pixel));
}
