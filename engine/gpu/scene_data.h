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
    uint pad0;
    uint pad1;
};

struct MaterialData {
    vec4 baseColor;
    float metallic;
    float roughness;
    float normalScale;
    uint flags;         // kMaterialReflective | kMaterialTransparent
    uint baseColorTex;  // kNoTexture when absent
    uint normalTex;
    uint metalRoughTex;
    uint pad0;
};

// Push constants of the mesh passes (shadow, gbuffer).
struct DrawPush {
    uint drawIndex;
    uint looseCount;  // gbuffer: loose reflectors tested per pixel (gbuffer/gbuffer.h)
    uint pad1;
    uint pad2;
};
PPR_END
PPR_SIZE_CHECK(DrawData, 144);
PPR_SIZE_CHECK(MaterialData, 48);
PPR_SIZE_CHECK(DrawPush, 16);

PPR_CONST(uint, kNoTexture, 0xFFFFFFFFu)
PPR_CONST(uint, kMaterialReflective, 1u)
PPR_CONST(uint, kMaterialTransparent, 2u)  // glTF alphaMode BLEND: the glass forward pass draws it

#endif
