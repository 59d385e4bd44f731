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
// One workgroup per block of kGlassReflectGroupSize² texels of one region grown by a texel on every
// side (the regions' blocks numbered region after region, regionBlockStarts). That ring lies in the
// gutter between regions (scene/glass_atlas.hpp kGlassAtlasGutter) and gets "no reflection": it is
// what the glass pass's bilinear taps at a region's edge read besides the region, so the image needs
// no clear (the texels beyond the rings are read by nothing but debug=atlas, which clears it first).
layout(local_size_x = kGlassReflectGroupSize, local_size_y = kGlassReflectGroupSize) in;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D atlas;
layout(set = 0, binding = 2) uniform sampler2D sceneLinear;  // the lit scene, bilinear
layout(set = 0, binding = 3) uniform sampler2D scenePoint;   // and point sampled
layout(set = 0, binding = 4, scalar) readonly buffer Regions { GlassRegionData regions[]; };  // per reflector
layout(set = 0, binding = 5, scalar) readonly buffer RegionList { uint regionReflectors[]; };  // reflectors with a region
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D outReflection;
layout(set = 0, binding = 7, scalar) readonly buffer BlockStarts { uint regionBlockStarts[]; };  // per listed region, then the total
layout(push_constant, scalar) uniform Push { GlassReflectPush pc; };

ivec2 regionLo, regionHi;  // the region of the texel being resolved

uint fetchValue(ivec2 t) {
    if (any(lessThan(t, regionLo)) || any(greaterThanEqual(t, regionHi))) return kPprClearValue;
    return imageLoad(atlas, t).r;
}

#include "ppr_common/ppr_resolve.glsl"

void main() {
    // This workgroup's region (the same for all its invocations) and block in it.
    uint group = gl_WorkGroupID.x, k = 0u;
    while (k + 1u < pc.regionCount && regionBlockStarts[k + 1u] <= group) ++k;
    GlassRegionData r = regions[regionReflectors[k]];
    regionLo = ivec2(r.atlasOrigin);
    regionHi = regionLo + ivec2(r.atlasSize);
    uint block = group - regionBlockStarts[k];
    uint blocksPerRow = (uint(r.atlasSize.x) + 2u + kGlassReflectGroupSize - 1u) / kGlassReflectGroupSize;
    ivec2 texel = regionLo - 1 + ivec2(block % blocksPerRow, block / blocksPerRow) * int(kGlassReflectGroupSize) + ivec2(gl_LocalInvocationID.xy);
    // Past the ring (the last blocks reach beyond it), or off the atlas (a region on its edge).
    if (any(greaterThan(texel, regionHi)) || any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, imageSize(outReflection)))) return;
    if (any(lessThan(texel, regionLo)) || any(equal(texel, regionHi))) {  // the ring
        imageStore(outReflection, texel, vec4(0.0, 0.0, 0.0, kReflectionNone));
        return;
    }
    // The screen position this texel stands for (its centre), and the pixels it covers.
    vec2 screen = r.screenOrigin + (vec2(texel - regionLo) + 0.5) / r.scale;
    PprResolved resolved = pprResolve(texel, screen, 1.0 / r.scale, pc.flags);
    imageStore(outReflection, texel, resolved.valid ? vec4(resolved.color, resolved.readTexel == texel ? kReflectionHit : kReflectionFilled)
                                                    : vec4(0.0, 0.0, 0.0, kReflectionNone));
}
