// What every cone pass shares (dense grid: cone_march.glsl; clipmap: clipmap_march.glsl):
// the uniform block, the G-buffer, the tangent frame, front-to-back compositing of one sample,
// and the gather of the cone set around a normal. The includer defines cone_march (declared
// below) for its volume. Include this first: the shader loader expands each file once.
#include "cone/cone_shared.h"

layout(std140, binding = CONE_UBO_BINDING) uniform ConeBlock { ConeUniforms u; };

// G-buffer units of render/gbuffer.h (GBufferUnit).
layout(binding = 0) uniform sampler2D gbufPosition;
layout(binding = 1) uniform sampler2D gbufNormal;
layout(binding = 2) uniform sampler2D gbufGeomNormal;
layout(binding = 3) uniform sampler2D gbufAlbedo;

// Tangent frame around unit n without a branch on the pole (Duff et al. 2017).
mat3 cone_frame(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    vec3 t = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    vec3 bt = vec3(b, s + n.y * n.y * a, -n.y);
    return mat3(t, bt, n);
}

struct ConeResult {
    vec3 radiance;   // premultiplied radiance gathered front to back
    float alpha;     // accumulated opacity; 1 = the cone saw no sky
};

// Composites one sample s (premultiplied radiance, alpha) over a step dt through texels of
// edge `texel`, at distance tMid: opacity corrected for the step length, alpha' = 1 - (1 -
// alpha)^(dt / texel), and (AO) the falloff weight 1 / (1 + lambda t).
void cone_composite(inout ConeResult r, vec4 s, float dt, float texel, float tMid, float falloff) {
    float a = clamp(s.a, 0.0, 1.0);
    float k = dt / texel;
    float aStep = 1.0 - exp2(k * log2(max(1.0 - a, 1e-7)));
    // Premultiplied radiance scales with the corrected opacity (its ratio to alpha is the
    // radiance itself); a transparent sample with radiance would be emission of a medium.
    vec3 c = a > 1e-6 ? s.rgb * (aStep / a) : s.rgb * k;
    float w = falloff > 0.0 ? 1.0 / (1.0 + falloff * tMid) : 1.0;
    r.radiance += (1.0 - r.alpha) * c;
    r.alpha += (1.0 - r.alpha) * aStep * w;
}

// The footprint's level of detail at distance t: diameter 2 t tan(aperture / 2), at least one
// voxel; with the plane limit, whole levels of at most h / ratio voxels at height h above the
// tangent plane (a fractional level would blend in the next, coarser one).
float cone_footprintLod(float t, float h0, float rise) {
    float lod = log2(max(1.0, 2.0 * t * u.march.x));
    float planeRatio = u.limits.w;
    if (planeRatio > 0.0) lod = min(lod, floor(log2(max(1.0, (h0 + t * rise) / planeRatio))));
    return lod;
}

// True once the footprint at p (volume coordinates, box [0, size]; one texel of trilinear
// reach past half a texel: `reach`) is outside the volume and moving away along d: the zero
// border means only sky remains.
bool cone_leaving(vec3 p, vec3 d, vec3 size, float reach) {
    bvec3 below = lessThan(p, vec3(-reach));
    bvec3 above = greaterThan(p, size + reach);
    return any(bvec3(below.x && d.x <= 0.0, below.y && d.y <= 0.0, below.z && d.z <= 0.0)) ||
           any(bvec3(above.x && d.x >= 0.0, above.y && d.y >= 0.0, above.z && d.z >= 0.0));
}

// A saturated cone counts as closed: renormalize what it saw rather than letting the last
// 1 - maxAlpha see the sky (that would leak sky light into closed rooms).
void cone_close(inout ConeResult r, float maxAlpha) {
    if (r.alpha >= maxAlpha) {
        r.radiance /= r.alpha;
        r.alpha = 1.0;
    }
}

// Marches from `origin` (voxel units) along unit `d`. `h0` is the origin's height above the
// shading point's tangent plane and `rise` = dot(d, geometric normal), both for the plane
// limit; `maxDist` (voxels) limits the distance (R for AO); `falloff` is lambda (AO only).
ConeResult cone_march(vec3 origin, vec3 d, float h0, float rise, float maxDist, float falloff);

// Reads the G-buffer texel; false for sky or unusable normals.
bool cone_surface(ivec2 pix, out vec3 pWorld, out vec3 n, out vec3 ng) {
    vec4 pos = texelFetch(gbufPosition, pix, 0);
    n = texelFetch(gbufNormal, pix, 0).xyz;
    ng = texelFetch(gbufGeomNormal, pix, 0).xyz;
    pWorld = pos.xyz;
    if (!(pos.w > 0.0)) return false;
    if (any(isnan(pos.xyz)) || any(isinf(pos.xyz))) return false;
    float ln = dot(n, n), lg = dot(ng, ng);
    if (!(lg > 1e-12) || isnan(lg) || isinf(lg)) return false;
    ng *= inversesqrt(lg);
    n = (ln > 1e-12 && !isnan(ln) && !isinf(ln)) ? n * inversesqrt(ln) : ng;
    return true;
}

// The cone set around shading normal n: sum_c w_c * (cone result) integrates the cosine lobe.
// Cones whose axis is below the geometric plane are closed (BRIEF section 1: directions below
// the geometric normal count as occluded).
struct ConeGather {
    vec3 radiance;    // sum_c w_c * (radiance_c + (1 - alpha_c) * sky)
    float occlusion;  // sum_c w_c * alpha_c
};

// The gather from voxel-space point p (the surface point, or a voxel centre for bounces);
// the cones start `offset` voxels along ng, and `h0` is that start's height above the
// tangent plane for the plane limit.
ConeGather cone_gatherVoxel(vec3 p, vec3 n, vec3 ng, float offset, float h0, float maxDist, float falloff,
                            float sky) {
    mat3 frame = cone_frame(n);
    vec3 origin = p + ng * offset;
    ConeGather g;
    g.radiance = vec3(0.0);
    g.occlusion = 0.0;
    for (int c = 0; c < u.config.x; ++c) {
        vec4 cone = u.cones[c];
        vec3 d = normalize(frame * cone.xyz);
        float rise = dot(d, ng);
        if (rise <= 0.0) {
            g.occlusion += cone.w;
            continue;
        }
        ConeResult r = cone_march(origin, d, h0, rise, maxDist, falloff);
        g.radiance += cone.w * (r.radiance + (1.0 - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
    }
    return g;
}

