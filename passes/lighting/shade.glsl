// The lighting pass's shading of one opaque surface point, shared with every pass that must light a
// point exactly as the lighting pass would (the ray-traced reference shades its hits with it). The
// includer includes common/bindings.glsl (frame constants) and common/brdf.glsl and binds
// `shadowMap` (sampler2DShadow, shadowCompare sampler).
//
// Sun: GGX specular + Lambert diffuse, shadowed by the shadow map (3x3 PCF); hemisphere ambient.

// The sun's visibility at a world point with normal n (0 = in shadow).
float shadowFactor(vec3 world, vec3 n) {
    // Offset along the normal so grazing surfaces do not self-shadow.
    vec4 p = frame.lightViewProj * vec4(world + n * 0.02, 1.0);
    vec3 s = p.xyz / p.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || s.z <= 0.0) return 1.0;
    float texel = frame.lightDir.w;
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) sum += texture(shadowMap, vec3(uv + vec2(x, y) * texel, s.z));
    return sum / 9.0;
}

// Outgoing radiance towards v (unit, from the point towards the viewer) of a point at `world` with
// shading normal n (unit) and the G-buffer's material; `shadow` returns the sun's visibility.
vec3 shadeSurface(vec3 world, vec3 n, vec3 v, vec3 albedo, float roughness, float metallic, out float shadow) {
    vec3 l = -frame.lightDir.xyz;
    vec3 h = normalize(v + l);
    float nl = max(dot(n, l), 0.0), nv = max(dot(n, v), 1e-4), nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    vec3 f0 = mix(vec3(0.04), albedo, metallic);
    float a = max(roughness * roughness, 2e-3);
    vec3 F = fresnelSchlick(vh, f0);
    vec3 specular = distributionGGX(nh, a) * visibilitySmithGGX(nv, nl, a) * F;
    vec3 diffuse = (1.0 - F) * (1.0 - metallic) * albedo / PI;
    shadow = nl > 0.0 ? shadowFactor(world, n) : 0.0;
    vec3 direct = (diffuse + specular) * frame.lightColor.rgb * nl * shadow;
    // Hemisphere ambient: diffuse from the sky/ground gradient, a rough specular term from the sky.
    vec3 ambientDiffuse = mix(frame.groundColor.rgb, frame.skyColor.rgb, n.y * 0.5 + 0.5) * albedo * (1.0 - metallic);
    vec3 ambientSpecular = skyRadiance(reflect(-v, n)) * fresnelSchlick(nv, f0) * (1.0 - roughness) * 0.5;
    return direct + (ambientDiffuse + ambientSpecular) * frame.skyColor.w;
}
