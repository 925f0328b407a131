// hbao: per direction, march the depth buffer and raise the horizon angle h; each rise adds
// (sin h_i - sin h_{i-1}) W(r_i), W = 1 - r^2/R^2, starting from the tangent angle t plus
// the angle bias (Bavoil and Sainz 2008's incremental form). Angles are elevations above the
// view plane. A = 1 - mean over directions. Directions rotated and steps jittered per pixel.
// Samples are read at their exact marching coordinate (ao_fetchSurfaceAt), as gl_ssao
// reconstructs positions at the sample's own UV.
#include "ao/ao_common.glsl"
#include "ao/hbao_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform HbaoBlock { HbaoUniforms hbao; };
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

// Sine of the tangent angle along screen direction dir: the surface plane (p, n) cut by the
// plane through the eye and the screen line is a 3D line through p, so its elevation is the
// exact horizon of a flat surface; found by intersecting the eye ray one pixel along dir.
float hbao_sinTangent(vec3 p, vec3 n, vec2 pixel, vec2 dir) {
    vec3 ray = ao_viewRayThroughPixel(pixel + dir);
    float nr = dot(n, ray);
    vec3 t;
    if (abs(nr) > 1e-6 * length(ray) && dot(n, p) / nr > 0.0) t = ray * (dot(n, p) / nr) - p;
    else t = vec3(dir, -(n.x * dir.x + n.y * dir.y) / max(n.z, 1e-4));  // grazing: orthographic tangent
    return t.z / max(length(t), 1e-30);
}

float hbao_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    float R2 = aoView.radius.y;
    float radiusPx = aoView.radius.x * ao_pixelsPerUnit(-p.z);
    int directions = hbao.config.x, steps = hbao.config.y;
    float stepPx = radiusPx / float(steps + 1);  // gl_ssao: the last step stays inside R
    if (stepPx < 0.5) return 1.0;                 // R smaller than a pixel: nothing to march
    vec2 noise = ao_pixelNoise(g, 2u);
    vec2 center = vec2(g) + 0.5;

    float occlusion = 0.0;
    for (int i = 0; i < directions; ++i) {
        float phi = 2.0 * AO_PI * (float(i) + noise.x) / float(directions);
        vec2 dir = vec2(cos(phi), sin(phi));
        float tangent = asin(clamp(hbao_sinTangent(p, n, center, dir), -1.0, 1.0));
        float sinHorizon = sin(min(tangent + hbao.angles.x, AO_HALF_PI));
        for (int j = 0; j < steps; ++j) {
            vec2 c = center + dir * ((float(j) + noise.y) * stepPx + 1.0);
            ivec2 q = ivec2(floor(c));
            if (!ao_onScreen(q)) break;
            vec3 s;
            if (q == g || !ao_fetchSurfaceAt(c, s)) continue;
            vec3 v = s - p;
            float r2 = dot(v, v);
            if (r2 > R2) continue;
            float sinH = v.z * inversesqrt(max(r2, 1e-30));
            if (sinH > sinHorizon) {
                occlusion += (sinH - sinHorizon) * (1.0 - r2 / R2);
                sinHorizon = sinH;
            }
        }
    }
    return 1.0 - occlusion / float(directions);
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(hbao_evaluate(ao_gbufferPixel(e)))));
}
