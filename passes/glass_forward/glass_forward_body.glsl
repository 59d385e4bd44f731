// Glass forward pass fragment shader, compiled twice: glass_forward.frag (transmission only) and
// glass_forward_reflect.frag (GLASS_REFLECTION: plus the panel's reflection from the atlas).
//
// Output 0 is added to the opaque colour, output 1 filters it (dual-source blending):
//     result = F·reflectance·reflection + (1 − F·reflectance)·tint·opaque
// with F the Schlick Fresnel term of glass (F0 = 0.04) and tint = mix(1, base colour, base alpha).
#include "common/bindings.glsl"
#include "common/brdf.glsl"
#include "common/reflection.h"
#include "common/reflector_data.h"
#include "gbuffer/gbuffer.h"
#include "glass_forward/glass_forward.h"
#extension GL_EXT_nonuniform_qualifier : require
#include "gpu/scene_data.h"

layout(set = 0, binding = 1, scalar) readonly buffer Draws { DrawData draws[]; };
layout(set = 0, binding = 2, scalar) readonly buffer Materials { MaterialData materials[]; };
layout(set = 0, binding = 3, scalar) readonly buffer Reflectors { ReflectorData reflectors[]; };
layout(set = 0, binding = 4, scalar) readonly buffer DrawReflectors { uint drawReflectors[]; };  // common/surface_binding.hpp
layout(set = 0, binding = 5, scalar) readonly buffer LooseGlass { uint looseGlass[]; };
#ifdef GLASS_REFLECTION
layout(set = 0, binding = 6, scalar) readonly buffer Regions { GlassRegionData regions[]; };
layout(set = 0, binding = 7) uniform sampler2D reflectionAtlas;  // rgba16f, common/reflection.h alpha codes
#endif
layout(set = 1, binding = 0) uniform sampler2D textures[];
layout(push_constant, scalar) uniform Push { GlassForwardPush pc; };

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec4 vTangent;
layout(location = 2) in vec2 vUv;
layout(location = 4) in vec4 vColor;

layout(location = 0, index = 0) out vec4 outAdd;
layout(location = 0, index = 1) out vec4 outFilter;

void main() {
    DrawData d = draws[pc.drawIndex];
    MaterialData m = materials[d.material];
    vec4 base = m.baseColor * (m.baseColorTex == kNoTexture ? vec4(1.0) : texture(textures[m.baseColorTex], materialUv(m, vUv)));
    if ((d.flags & kDrawVertexColors) != 0u) base *= vColor;
    vec3 world = worldFromDepth(gl_FragCoord.xy * frame.invScreenSize, gl_FragCoord.z);
    vec3 v = normalize(frame.cameraPos.xyz - world);
    vec3 n = normalize(vNormal);
    uint reflectorId = drawReflectors[pc.drawIndex];
    if (reflectorId == 0u) {
        // A draw holding many panes: the glass reflector whose rectangle this point lies on, the one
        // facing the viewer first (a pane fitted on both faces has one reflector per face); one seen
        // from behind still sets the reflectance, as it does for a draw bound to it.
        float tolerance = kLooseSurfaceTolerance + kLooseSurfaceTolerancePerMetre * distance(world, frame.cameraPos.xyz);
        uint behind = 0u;
        for (uint k = 0u; k < pc.looseGlassCount && reflectorId == 0u; ++k) {
            ReflectorData r = reflectors[looseGlass[k]];
            if (abs(dot(world - r.center, r.normal)) > tolerance || !reflectorContains(r, world)) continue;
            if (dot(r.normal, v) > 0.0) reflectorId = looseGlass[k] + 1u;
            else if (behind == 0u) behind = looseGlass[k] + 1u;
        }
        if (reflectorId == 0u) reflectorId = behind;
    }
    float reflectance = reflectorId != 0u ? reflectors[reflectorId - 1u].reflectance : 1.0;
    float weight = fresnelSchlick(abs(dot(n, v)), vec3(0.04)).x * reflectance;
    vec3 reflection = vec3(0.0);
#ifdef GLASS_REFLECTION
    // Only the reflecting side has a reflection (PPR sees no reflector from behind).
    if (reflectorId != 0u && dot(reflectors[reflectorId - 1u].normal, v) > 0.0) {
        GlassRegionData r = regions[reflectorId - 1u];
        if (r.valid != 0u) {
            vec2 t = glassAtlasFromScreen(r, gl_FragCoord.xy);
            vec4 texel = textureLod(reflectionAtlas, t / vec2(textureSize(reflectionAtlas, 0)), 0.0);
            if (texel.a > 0.0) reflection = texel.rgb;
        }
    }
#endif
    vec3 tint = mix(vec3(1.0), base.rgb, base.a);
    // An emissive pane (glTF emissive on a BLEND material) adds its light over whatever it filters.
    vec3 emitted = m.emissive * (m.emissiveTex == kNoTexture ? vec3(1.0) : texture(textures[m.emissiveTex], materialUv(m, vUv)).rgb);
    outAdd = vec4(weight * reflection + emitted, 0.0);
    outFilter = vec4((1.0 - weight) * tint, 1.0);
}
