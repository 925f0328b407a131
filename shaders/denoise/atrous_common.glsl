// Bindings and helpers of the a-trous passes (denoise/atrous_shared.h). ATROUS_CHANNELS is 1
// (AO in .r) or 3 (RGB radiance); the working images are RGBA32F: the value in rgb (or r),
// its variance in a.
#include "denoise/atrous_shared.h"

layout(local_size_x = ATROUS_LOCAL_SIZE, local_size_y = ATROUS_LOCAL_SIZE) in;
layout(std140, binding = ATROUS_BINDING_UNIFORMS) uniform AtrousBlock { AtrousUniforms atrous; };
layout(binding = ATROUS_UNIT_POSITION) uniform sampler2D atrousPosition;
layout(binding = ATROUS_UNIT_NORMAL) uniform sampler2D atrousNormal;
layout(binding = ATROUS_UNIT_ALBEDO) uniform sampler2D atrousAlbedo;
layout(binding = ATROUS_UNIT_INPUT) uniform sampler2D atrousIn;
layout(rgba32f, binding = ATROUS_IMAGE_OUTPUT) uniform writeonly image2D atrousOut;

struct AtrousSurface {
    vec3 position;
    float depth;  // linear view depth; <= 0 on sky
    vec3 normal;
    vec3 albedo;
};

AtrousSurface atrous_surface(ivec2 q) {
    vec4 p = texelFetch(atrousPosition, q, 0);
    return AtrousSurface(p.xyz, p.w, texelFetch(atrousNormal, q, 0).xyz, texelFetch(atrousAlbedo, q, 0).rgb);
}

bool atrous_inside(ivec2 q, ivec2 size) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size)); }

float atrous_geometryWeight(AtrousSurface c, AtrousSurface t) {
    return atrous_edgeWeight(c.position, c.normal, c.albedo, c.depth, t.position, t.normal, t.albedo, atrous.sigmas);
}

float atrous_luminance(vec3 v) {
#if ATROUS_CHANNELS == 1
    return v.r;
#else
    return dot(v, vec3(0.2126, 0.7152, 0.0722));
#endif
}
