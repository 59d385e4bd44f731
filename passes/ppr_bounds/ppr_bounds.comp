#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflector_data.h"
#include "ppr_bounds/ppr_bounds.h"
#include "ppr_common/tile_culling.h"

// Once per frame and reflector, before the projection pass: the reflector's screen rectangle and
// whether the camera may see its reflecting side, so that every tile's culling reads them instead
// of clipping and projecting each rectangle again.
layout(local_size_x = kPprBoundsGroupSize) in;
layout(set = 0, binding = 1, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 2, scalar) writeonly buffer Bounds { PprReflectorBounds bounds[]; };
layout(push_constant, scalar) uniform Push { PprBoundsPush pc; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pc.reflectorCount) return;
    bounds[i] = pprReflectorBounds(reflectors[i], frame.viewProj, frame.cameraPos.xyz, frame.screenSize);
}
