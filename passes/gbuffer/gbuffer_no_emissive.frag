#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer without its emissive target (no opaque material emits): four colour targets.
#include "gbuffer/gbuffer_body.glsl"
