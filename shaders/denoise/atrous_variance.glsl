// The a-trous filter's first pass: each pixel's value (divided by its albedo when the filter
// works on irradiance) and the variance of its luminance, estimated from the 7x7 pixels of the
// same surface around it (SVGF's spatial estimate: the geometry weights of the iterations,
// no kernel). Sky pixels pass through with variance 0.
#include "denoise/atrous_common.glsl"

vec3 atrous_value(ivec2 q, vec3 albedo) {
    vec3 v = texelFetch(atrousIn, q, 0).rgb;
#if ATROUS_CHANNELS == 1
    return vec3(v.r, 0.0, 0.0);
#else
    // A channel of albedo 0 reflects nothing, so its radiance is 0 and it stays 0.
    if (atrous.config.y != 0)
        v = vec3(albedo.r > 0.0 ? v.r / albedo.r : 0.0, albedo.g > 0.0 ? v.g / albedo.g : 0.0,
                 albedo.b > 0.0 ? v.b / albedo.b : 0.0);
    return v;
#endif
}

void main() {
    ivec2 pix = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(atrousIn, 0);
    if (any(greaterThanEqual(pix, size))) return;
    AtrousSurface c = atrous_surface(pix);
    vec3 value = atrous_value(pix, c.albedo);
    float variance = 0.0;
    if (c.depth > 0.0) {
        float sum = 0.0, sumSq = 0.0, weightSum = 0.0;
        for (int dy = -ATROUS_VARIANCE_RADIUS; dy <= ATROUS_VARIANCE_RADIUS; ++dy)
            for (int dx = -ATROUS_VARIANCE_RADIUS; dx <= ATROUS_VARIANCE_RADIUS; ++dx) {
                ivec2 q = pix + ivec2(dx, dy);
                if (!atrous_inside(q, size)) continue;
                AtrousSurface t = atrous_surface(q);
                if (!(t.depth > 0.0)) continue;
                float w = (dx == 0 && dy == 0) ? 1.0 : atrous_geometryWeight(c, t);
                float l = atrous_luminance(atrous_value(q, t.albedo));
                sum += w * l;
                sumSq += w * l * l;
                weightSum += w;
            }
        float mean = sum / weightSum;
        variance = max(sumSq / weightSum - mean * mean, 0.0);
    }
    imageStore(atrousOut, pix, vec4(value, variance));
}
