// Which pixels of its workgroup's 16×16 tile an invocation resolves (taa.h kTaaTileSize, kTaaThreads):
// a column of kTaaRowsPerInvocation pixels, one above the other. With 256 invocations that is one pixel
// each, laid out as a 16×16 group would be.
layout(local_size_x_id = 0) in;
layout(constant_id = 0) const uint kThreads = kTaaThreads;  // TaaPass always specialises it
const uint kTaaRowsPerInvocation = kTaaTileSize * kTaaTileSize / kThreads;

ivec2 tileOrigin() { return ivec2(gl_WorkGroupID.xy) * int(kTaaTileSize); }

// The invocation's row-th pixel, relative to its tile's origin.
ivec2 pixelInTile(uint row) {
    return ivec2(gl_LocalInvocationIndex % kTaaTileSize, gl_LocalInvocationIndex / kTaaTileSize * kTaaRowsPerInvocation + row);
}
