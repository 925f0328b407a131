// Direct irradiance from KHR_lights_punctual lights with shadow-map visibility. Needs
// common/scene.glsl. Units follow the extension: directional colour in lux, point and
// spot colour in candela (E = I cos / d^2); spot falloff as the glTF spec recommends.
layout(binding = 10) uniform sampler2DArrayShadow shadowMaps;    // directional + spot
layout(binding = 11) uniform samplerCubeArray shadowCubes;       // point: distance to light
uniform int lightCount;

// Visibility of light `l` from world point p with geometric normal ng (1 lit, 0 shadowed).
float light_visibility(GpuLight l, vec3 p, vec3 ng) {
    float layer = l.spot.z;
    if (layer < 0.0) return 1.0;
    vec3 biased = p + ng * l.spot.w;
    int type = int(l.color.w);
    if (type == LIGHT_POINT) {
        vec3 d = biased - l.position.xyz;
        float stored = texture(shadowCubes, vec4(d, layer)).r;
        return length(d) <= stored * 1.0005 + 1e-7 * length(d) ? 1.0 : 0.0;
    }
    vec4 clip = l.shadowClipFromWorld * vec4(biased, 1.0);
    if (clip.w <= 0.0) return 0.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return type == LIGHT_SPOT ? 0.0 : 1.0;
    // 2x2 PCF through the comparison sampler (hardware bilinear of the comparisons).
    return texture(shadowMaps, vec4(uv, layer, ndc.z * 0.5 + 0.5));
}

// Irradiance (W/m^2 per channel, before albedo/pi) arriving at p on a surface with
// shading normal n and geometric normal ng, from every light.
vec3 light_irradiance(vec3 p, vec3 n, vec3 ng) {
    vec3 e = vec3(0.0);
    for (int i = 0; i < lightCount; ++i) {
        GpuLight l = sceneLights[i];
        int type = int(l.color.w);
        vec3 wi;
        float scale = 1.0;
        if (type == LIGHT_DIRECTIONAL) {
            wi = -l.direction.xyz;
        } else {
            vec3 d = l.position.xyz - p;
            float dist2 = max(dot(d, d), 1e-30);
            wi = d * inversesqrt(dist2);
            scale = 1.0 / dist2;
            if (type == LIGHT_SPOT) {
                float cd = dot(-wi, l.direction.xyz);
                float t = clamp((cd - l.spot.x) / max(l.spot.y - l.spot.x, 1e-4), 0.0, 1.0);
                scale *= t * t;
            }
        }
        float cosTheta = dot(n, wi);
        if (cosTheta <= 0.0 || dot(ng, wi) <= 0.0) continue;
        e += l.color.rgb * (scale * cosTheta) * light_visibility(l, p, ng);
    }
    return e;
}
