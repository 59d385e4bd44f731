// GPU-side scene records (host/device shared). Uploaded once per scene load.
#ifndef PPR_SCENE_DATA_H
#define PPR_SCENE_DATA_H
#include "shader/shared.h"

PPR_BEGIN
struct DrawData {
    mat4 world;
    mat4 normalMatrix;  // inverse-transpose of world (upper 3x3 used)
    uint material;
    uint reflectorId;   // load-time binding (index + 1, 0 = none); the frame's is common/surface_binding.hpp
    uint firstIndex;    // the mesh's triangles in the scene index buffer (ray-query hits fetch their vertices)
    int vertexOffset;   // added to each index, as vkCmdDrawIndexed does
    uint flags;         // kDrawVertexColors
    uint motionSlot;    // moving draws: 1..kMaxMovingDraws, its MotionData entry; 0 = still
    uint pad1;
    uint pad2;
};

struct MaterialData {
    vec4 baseColor;
    float metallic;
    float roughness;
    float normalScale;
    uint flags;         // kMaterialReflective | kMaterialTransparent | kMaterialMasked
    uint baseColorTex;  // kNoTexture when absent
    uint normalTex;
    uint metalRoughTex;
    float alphaCutoff;  // kMaterialMasked: cut out where base colour alpha is below it
    // KHR_texture_transform as the two rows of a 2x3 matrix: uv' = (dot(row0, (uv, 1)), dot(row1, (uv, 1))).
    vec4 uvRow0;  // xyz used; identity (1, 0, 0)
    vec4 uvRow1;  // identity (0, 1, 0)
    vec3 emissive;     // emitted radiance, added to the lit colour (zero: not emissive)
    uint emissiveTex;  // kNoTexture when absent; multiplies `emissive`
};

// scene::Vertex as shaders that read the vertex buffer as storage see it (the ray-traced reference's
// hits); gpu_scene.cpp checks the two agree member by member.
struct VertexData {
    vec3 position;
    vec3 normal;
    vec4 tangent;  // xyz + handedness sign in w
    vec2 uv;
    uvec2 color;  // RGBA16 unorm: unpackUnorm2x16 of x = (r, g), of y = (b, a)
};

// Push constants of the mesh passes (shadow, gbuffer).
struct DrawPush {
    uint drawIndex;
    uint looseCount;  // gbuffer: loose reflectors tested per pixel (gbuffer/gbuffer.h)
    uint pad1;
    uint pad2;
};
PPR_END
PPR_SIZE_CHECK(DrawData, 160);
PPR_SIZE_CHECK(VertexData, 56);
PPR_SIZE_CHECK(MaterialData, 96);
PPR_SIZE_CHECK(DrawPush, 16);

PPR_CONST(uint, kNoTexture, 0xFFFFFFFFu)

PPR_BEGIN
// A material's texture coordinates (the identity leaves uv bit for bit as it was).
PPR_INLINE vec2 materialUv(MaterialData m, vec2 uv) {
    return vec2(dot(vec3(m.uvRow0), vec3(uv, 1.0f)), dot(vec3(m.uvRow1), vec3(uv, 1.0f)));
}
// A difference of texture coordinates (a footprint's derivative) under the same transform.
PPR_INLINE vec2 materialUvDelta(MaterialData m, vec2 d) { return vec2(dot(vec2(m.uvRow0), d), dot(vec2(m.uvRow1), d)); }
PPR_END
// Only meshes with COLOR_0 multiply by it: an interpolated constant white need not be exactly 1.0, and
// scenes without vertex colours stay bit-identical.
PPR_CONST(uint, kDrawVertexColors, 1u)
PPR_BEGIN
// A vertex's COLOR_0 (VertexData::color).
PPR_INLINE vec4 vertexColor(uvec2 packed) { return vec4(unpackUnorm2x16(packed.x), unpackUnorm2x16(packed.y)); }
PPR_END
// Per-object motion for TAA. The G-buffer writes a draw's motionSlot / 255 into the material
// target's alpha (RGBA8); TAA carries that pixel's world position through the slot's matrix before
// projecting it with last frame's view-projection. Slot 0, every still draw, is the identity.
PPR_CONST(uint, kMaxMovingDraws, 255u)
PPR_BEGIN
struct MotionData {
    mat4 toPrevious;  // world position now → where that point of the draw was last frame
};
PPR_END
PPR_SIZE_CHECK(MotionData, 64);
PPR_CONST(uint, kMaterialReflective, 1u)
PPR_CONST(uint, kMaterialTransparent, 2u)  // glTF alphaMode BLEND: the glass forward pass draws it
PPR_CONST(uint, kMaterialMasked, 4u)       // glTF alphaMode MASK: G-buffer and shadow map cut it out

#endif
