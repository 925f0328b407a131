// One iteration of the edge-avoiding a-trous filter (denoise/atrous_shared.h) over the working
// image (rgb value, a variance): 5x5 taps 2^i pixels apart, weighted by the B3 spline, the
// G-buffer's resemblance to the centre and the luminance term, divided by the sum of the
// weights used (taps off screen or on sky are left out, so borders and silhouettes neither
// darken nor brighten). The variance is filtered with the squared weights. Sky pixels pass
// through unchanged; the last iteration multiplies by the albedo when the filter works on
// irradiance, and writes alpha 1 on surfaces, 0 on sky, as the other GI passes.
#include "denoise/atrous_common.glsl"

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(atrousIn, 0);
    if (any(greaterThanEqual(pix, size))) return;
    AtrousSurface c = atrous_surface(pix);
    vec4 centre = texelFetch(atrousIn, pix, 0);
    vec4 result = centre;
    if (c.depth > 0.0) {
        float luminance = atrous_luminance(centre.rgb);
        float deviation = sqrt(max(centre.a, 0.0));
        vec3 sum = vec3(0.0);
        float weightSum = 0.0, varianceSum = 0.0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                ivec2 q = pix + ivec2(dx, dy) * atrous.config.x;
                if (!atrous_inside(q, size)) continue;
                AtrousSurface t = atrous_surface(q);
                if (!(t.depth > 0.0)) continue;
                vec4 tap = texelFetch(atrousIn, q, 0);
                float w = atrous_kernel(abs(dx)) * atrous_kernel(abs(dy));
                if (dx != 0 || dy != 0)
                    w *= atrous_geometryWeight(c, t) *
                         atrous_luminanceWeight(luminance, atrous_luminance(tap.rgb), deviation, atrous.sigmas.w);
                sum += w * tap.rgb;
                varianceSum += w * w * tap.a;
                weightSum += w;
            }
        // weightSum >= the centre's own weight, 0.140625
        result = vec4(sum / weightSum, varianceSum / (weightSum * weightSum));
    }
    if (atrous.config.z != 0) {
        if (atrous.config.y != 0) result.rgb *= c.albedo;
        result.a = c.depth > 0.0 ? 1.0 : 0.0;
    }
    imageStore(atrousOut, pix, result);
}
