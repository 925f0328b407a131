// Direct lighting at every G-buffer pixel: Lambertian albedo/pi times the lights'
// irradiance with shadow-map visibility. Emission and ambient are added by composite.
#include "raster/raster_shared.h"
#include "common/scene.glsl"
#include "common/lights.glsl"
layout(local_size_x = RASTER_GROUP_SIZE, local_size_y = RASTER_GROUP_SIZE) in;
layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 2) uniform sampler2D gGeomNormal;
layout(binding = 3) uniform sampler2D gAlbedo;
layout(rgba32f, binding = 0) uniform writeonly image2D outDirect;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(outDirect)))) return;
    vec4 pos = texelFetch(gPosition, px, 0);
    if (pos.w <= 0.0) { imageStore(outDirect, px, vec4(0.0)); return; }
    vec3 n = texelFetch(gNormal, px, 0).xyz;
    vec3 ng = texelFetch(gGeomNormal, px, 0).xyz;
    vec3 albedo = texelFetch(gAlbedo, px, 0).rgb;
    vec3 direct = albedo * (1.0 / 3.14159265358979) * light_irradiance(pos.xyz, n, ng);
    imageStore(outDirect, px, vec4(direct, 1.0));
}
