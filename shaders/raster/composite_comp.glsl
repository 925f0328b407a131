// beauty = emission + direct + ambient, where ambient is either the GI pass's indirect
// radiance or sky * albedo * AO. AO multiplies the ambient term only, never direct light
// (direct light is already shadowed). Sky pixels show the sky radiance.
#include "raster/raster_shared.h"
layout(local_size_x = RASTER_GROUP_SIZE, local_size_y = RASTER_GROUP_SIZE) in;
layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 3) uniform sampler2D gAlbedo;
layout(binding = 4) uniform sampler2D gEmission;
layout(binding = 6) uniform sampler2D directTex;    // rgb direct (zero texture when no lights)
layout(binding = 7) uniform sampler2D aoTex;        // r = AO
layout(binding = 9) uniform sampler2D indirectTex;  // rgb indirect radiance (GI)
uniform int useGi;
uniform int useDirect;
uniform int useAo;
uniform float sky;
layout(rgba32f, binding = 0) uniform writeonly image2D outBeauty;
layout(rgba32f, binding = 1) uniform writeonly image2D outIndirect;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(outBeauty)))) return;
    vec4 pos = texelFetch(gPosition, px, 0);
    if (pos.w <= 0.0) {
        imageStore(outBeauty, px, vec4(vec3(sky), 1.0));
        imageStore(outIndirect, px, vec4(0.0));
        return;
    }
    vec3 albedo = texelFetch(gAlbedo, px, 0).rgb;
    vec3 indirect;
    if (useGi != 0) {
        indirect = texelFetch(indirectTex, px, 0).rgb;
    } else {
        float ao = useAo != 0 ? texelFetch(aoTex, px, 0).r : 1.0;
        indirect = sky * albedo * ao;
    }
    vec3 direct = useDirect != 0 ? texelFetch(directTex, px, 0).rgb : vec3(0.0);
    vec3 beauty = texelFetch(gEmission, px, 0).rgb + direct + indirect;
    imageStore(outBeauty, px, vec4(beauty, 1.0));
    imageStore(outIndirect, px, vec4(indirect, 1.0));
}
