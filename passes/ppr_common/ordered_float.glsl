// Floats as order-preserving uints, so that integer atomicMin/atomicMax (and subgroupMin/Max) reduce
// world-space bounds exactly: the projection pass and the reach pass build the same tile boxes.
#ifndef PPR_ORDERED_FLOAT_GLSL
#define PPR_ORDERED_FLOAT_GLSL

uint orderedFromFloat(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
uvec3 orderedFromFloat(vec3 v) { return uvec3(orderedFromFloat(v.x), orderedFromFloat(v.y), orderedFromFloat(v.z)); }
float floatFromOrdered(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u); }
vec3 floatFromOrdered(uvec3 u) { return vec3(floatFromOrdered(u.x), floatFromOrdered(u.y), floatFromOrdered(u.z)); }

#endif
