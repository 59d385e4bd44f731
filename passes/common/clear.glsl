// The body of clear_float.comp and clear_uint.comp (common/clear_pass.hpp): fills one image with one
// value. On GPUs whose transfer clears run through the raster back-end this is many times cheaper.
// The image is written without a format qualifier (shaderStorageImageWriteWithoutFormat), so one
// pipeline serves every format of its kind; CLEAR_IMAGE is image2D or uimage2D.
#extension GL_EXT_scalar_block_layout : require
#include "common/clear.h"

layout(local_size_x = kClearGroupSize, local_size_y = kClearGroupSize) in;
layout(set = 0, binding = 0) uniform writeonly CLEAR_IMAGE target;
layout(push_constant, scalar) uniform Push { ClearPush pc; };

void main() {
    const uvec2 pix = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pix, pc.extent))) return;
    imageStore(target, ivec2(pix), CLEAR_VALUE(pc.value));
}
