#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_nonuniform_qualifier : require
#include "common/bindings.glsl"
#include "gpu/scene_data.h"

// Cuts alpha-masked surfaces out of the shadow map with the G-buffer's rule (gbuffer.frag).
layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(set = 0, binding = 2, scalar) readonly buffer Materials { MaterialData materials[]; };
layout(set = 1, binding = 0) uniform sampler2D textures[];
layout(push_constant, scalar) uniform Push { DrawPush pc; };  // one draw per push: its texture index is uniform

layout(location = 0) in vec2 vUv;
layout(location = 2) in float vAlpha;

void main() {
    DrawData d = draws[pc.drawIndex];
    MaterialData m = materials[d.material];
    float alpha = m.baseColor.a;
    if ((d.flags & kDrawVertexColors) != 0u) alpha *= vAlpha;
    if (m.baseColorTex != kNoTexture) alpha *= texture(textures[m.baseColorTex], materialUv(m, vUv)).a;
    if (alpha < m.alphaCutoff) discard;
}
