// The reflection probe behind --set fallback_env=1 env_source=probe (host/device shared): one cubemap of
// the lit scene per scene (rgb radiance, a = distance from the centre, 0 for sky), rendered once
// (env_probe_pass.hpp), looked up box-projected by common/environment.glsl.
#ifndef PPR_ENV_PROBE_H
#define PPR_ENV_PROBE_H
#include "shader/shared.h"

PPR_CONST(uint, kEnvProbeFaceSize, 256u)  // texels per cube face side
PPR_CONST(uint, kEnvProbeGroupSize, 8u)   // env_probe_store.comp workgroup side
// The lookup (common/environment.glsl) takes the probe's texel only when what the probe saw there is at
// least this close, as a fraction of the distance, to the point where the reflected ray leaves the box.
PPR_CONST(float, kEnvProbeDistanceTolerance, 0.15f)

PPR_BEGIN
// Where the probe sits and the box its lookups are parallax-corrected against (world space, w unused).
struct EnvProbeData {
    vec4 centre;  // the cube's viewpoint
    vec4 boxMin;  // the scene's bounding box: a reflected ray is followed to where it leaves it
    vec4 boxMax;
};

// One face's resampling from its 90° render into the cube (face in the Vulkan order +X −X +Y −Y +Z −Z).
struct EnvProbeStorePush {
    uint face;
    uint size;  // kEnvProbeFaceSize
};
PPR_END
PPR_SIZE_CHECK(EnvProbeData, 48);
PPR_SIZE_CHECK(EnvProbeStorePush, 8);

#endif
