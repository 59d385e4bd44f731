#version 460
#extension GL_GOOGLE_include_directive : require
#include "common/bindings.glsl"
#include "common/reflection.h"
#include "glass_forward/glass_forward.h"
#include "glass_reflect/glass_reflect.h"
#include "ppr_common/encoding.h"

// PPR's reflection pass for glass panels: resolves every texel of the atlas regions (the same decode,
// hole filling, filtered sample and anti-bleeding as on screen, ppr_common/ppr_resolve.glsl) into
// the glass reflection atlas (rgba16f, common/reflection.h alpha codes) the glass forward pass reads.
// A texel only ever reads its own region: the neighbours hole filling looks at stop at the region's edge.
layout(local_size_x = kGlassReflectGroupSize, local_size_y = kGlassReflectGroupSize) in;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D atlas;
layout(set = 0, binding = 2) uniform sampler2D sceneLinear;  // the lit scene, bilinear
layout(set = 0, binding = 3) uniform sampler2D scenePoint;   // and point sampled
layout(set = 0, binding = 4, scalar) readonly buffer Regions { GlassRegionData regions[]; };  // per reflector
layout(set = 0, binding = 5, scalar) readonly buffer RegionList { uint regionReflectors[]; };  // reflectors with a region
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D outReflection;
layout(push_constant, scalar) uniform Push { GlassReflectPush pc; };

ivec2 regionLo, regionHi;  // the region of the texel being resolved

uint fetchValue(ivec2 t) {
    if (any(lessThan(t, regionLo)) || any(greaterThanEqual(t, regionHi))) return kPprClearValue;
    return imageLoad(atlas, t).r;
}

#include "ppr_common/ppr_resolve.glsl"

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(outReflection)))) return;
    vec4 result = vec4(0.0, 0.0, 0.0, kReflectionNone);
    for (uint k = 0u; k < pc.regionCount; ++k) {
        GlassRegionData r = regions[regionReflectors[k]];
        regionLo = ivec2(r.atlasOrigin);
        regionHi = regionLo + ivec2(r.atlasSize);
        if (any(lessThan(texel, regionLo)) || any(greaterThanEqual(texel, regionHi))) continue;
        // The screen position this texel stands for (its centre), and the pixels it covers.
        vec2 screen = r.screenOrigin + (vec2(texel - regionLo) + 0.5) / r.scale;
        PprResolved resolved = pprResolve(texel, screen, 1.0 / r.scale, pc.flags);
        if (resolved.valid) result = vec4(resolved.color, resolved.readTexel == texel ? kReflectionHit : kReflectionFilled);
        break;
    }
    imageStore(outReflection, texel, result);
}
