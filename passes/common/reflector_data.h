// Reflector rectangles as the GPU sees them (host/device shared). Uploaded once per reflector change,
// in scene order (so the G-buffer's reflector id − 1 indexes it), plus the projection order: indices
// sorted by orientation group (engine/scene/reflector_groups.hpp).
#ifndef PPR_REFLECTOR_DATA_H
#define PPR_REFLECTOR_DATA_H
#include "shader/shared.h"

PPR_BEGIN
struct ReflectorData {
    vec3 center;
    float halfExtentU;      // metres along tangent
    vec3 normal;            // unit; the reflecting side
    float halfExtentV;      // metres along bitangent
    vec3 tangent;
    float reflectance;      // 0..1, scales the Fresnel term in the composite
    vec3 bitangent;         // cross(normal, tangent)
    uint orientationGroup;  // reflectors facing the same way share it
    uint planeGroup;        // coplanar reflectors share it
    uint kind;              // kReflectorOpaque | kReflectorGlass
    uint cullPlane;         // index of its plane among the cull planes (kPprNoCullPlane beyond them):
                            // per-tile culling mirrors a tile once per plane (ppr_common/tile_culling.h)
    uint pad1;
};
PPR_END
PPR_SIZE_CHECK(ReflectorData, 80);

PPR_BEGIN
// Does p (on or near the reflector's plane) project inside its rectangle?
PPR_INLINE bool reflectorContains(ReflectorData r, vec3 p) {
    vec3 l = p - r.center;
    return abs(dot(l, r.tangent)) <= r.halfExtentU && abs(dot(l, r.bitangent)) <= r.halfExtentV;
}
PPR_END

PPR_CONST(uint, kReflectorOpaque, 0u)
PPR_CONST(uint, kReflectorGlass, 1u)

#endif
