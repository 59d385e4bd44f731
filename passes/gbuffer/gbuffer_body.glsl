// The G-buffer's fragment shader (layout in gbuffer.h), compiled twice: gbuffer.frag with the emissive
// target (PPR_GBUFFER_EMISSIVE) and gbuffer_no_emissive.frag without it, for a scene whose opaque materials
// emit nothing (GBufferPass).
#include "common/bindings.glsl"
#extension GL_EXT_nonuniform_qualifier : require
#include "gpu/scene_data.h"
#include "common/reflector_data.h"
#include "gbuffer/gbuffer.h"
#include "common/normal_mapping.glsl"

layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(set = 0, binding = 2, scalar) readonly buffer Materials { MaterialData materials[]; };
layout(set = 0, binding = 3, scalar) readonly buffer DrawReflectors { uint drawReflectors[]; };  // per draw, id
layout(set = 0, binding = 4, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 5, scalar) readonly buffer Loose { uint looseReflectors[]; };
layout(push_constant, scalar) uniform Push { DrawPush pc; };
layout(set = 1, binding = 0) uniform sampler2D textures[];

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec4 vTangent;
layout(location = 2) in vec2 vUv;
layout(location = 4) in vec4 vColor;

layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outMaterial;
layout(location = 3) out uint outReflector;
#ifdef PPR_GBUFFER_EMISSIVE
layout(location = 4) out vec4 outEmissive;
#endif

// Each draw is its own vkCmdDrawIndexed with its index pushed, so the material and its texture
// indices are uniform across a draw: no nonuniformEXT, and no varying for the index (the shader
// compiler then reads them once; on lavapipe the pass costs 0.85-0.91 of what it did).
vec4 sampleOr(uint tex, vec2 uv, vec4 fallback) {
    return tex == kNoTexture ? fallback : texture(textures[tex], uv);
}

void main() {
    DrawData d = draws[pc.drawIndex];
    MaterialData m = materials[d.material];
    vec2 uv = materialUv(m, vUv);
    vec4 base = m.baseColor * sampleOr(m.baseColorTex, uv, vec4(1.0));
    if ((d.flags & kDrawVertexColors) != 0u) base *= vColor;
    if ((m.flags & kMaterialMasked) != 0u && base.a < m.alphaCutoff) discard;  // glTF alpha MASK
    vec4 mr = sampleOr(m.metalRoughTex, uv, vec4(1.0));

    // Two-sided: flip the geometric frame for back faces so thin panels light correctly. A mirrored
    // view (planar reference) reverses winding, so there the back-facing side is the front.
    bool front = gl_FrontFacing != (frame.mirrored != 0u);
    vec3 n = normalize(front ? vNormal : -vNormal);
    vec3 t, b;
    if (m.normalTex != kNoTexture && normalMapFrame(n, vTangent, t, b))
        n = mappedNormal(n, t, b, texture(textures[m.normalTex], uv).xyz, m.normalScale);
    outNormal = vec4(n, 1.0);
    outAlbedo = vec4(base.rgb, 1.0);
    outMaterial = vec4(clamp(m.roughness * mr.g, 0.02, 1.0), clamp(m.metallic * mr.b, 0.0, 1.0),
                       (m.flags & kMaterialReflective) != 0u ? 1.0 : 0.0, float(d.motionSlot) / float(kMaxMovingDraws));
    uint id = drawReflectors[pc.drawIndex];
    if (id == 0u && pc.looseCount > 0u) {
        // A reflector no mesh belongs to covers whatever surface lies on its rectangle.
        vec3 p = worldFromDepth(gl_FragCoord.xy * frame.invScreenSize, gl_FragCoord.z);
        float tolerance = kLooseSurfaceTolerance + kLooseSurfaceTolerancePerMetre * distance(p, frame.cameraPos.xyz);
        for (uint k = 0u; k < pc.looseCount && id == 0u; ++k) {
            ReflectorData r = reflectors[looseReflectors[k]];
            if (abs(dot(p - r.center, r.normal)) <= tolerance && reflectorContains(r, p)) id = looseReflectors[k] + 1u;
        }
    }
    outReflector = id;
#ifdef PPR_GBUFFER_EMISSIVE
    outEmissive = vec4(m.emissive * sampleOr(m.emissiveTex, uv, vec4(1.0)).rgb, 0.0);
#endif
}
