// G-buffer access and projection helpers shared by every screen-space AO pass. View space
// is GL's: camera at the origin looking down -z, so view z grows toward the camera and the
// linear depth of a point is -z.
#include "ao/ao_shared.h"

layout(std140, binding = AO_BINDING_VIEW) uniform AoViewBlock { AoViewUniforms aoView; };
layout(binding = AO_UNIT_POSITION) uniform sampler2D aoGPosition;
layout(binding = AO_UNIT_NORMAL) uniform sampler2D aoGNormal;

const float AO_PI = 3.14159265358979;
const float AO_HALF_PI = 1.57079632679490;

ivec2 ao_fullSize() { return aoView.size.zw; }
ivec2 ao_evalSize() { return aoView.size.xy; }

bool ao_onScreen(ivec2 g) { return all(greaterThanEqual(g, ivec2(0))) && all(lessThan(g, ao_fullSize())); }

// The G-buffer pixel an evaluation pixel stands for (the lower-left one of its block at half res).
ivec2 ao_gbufferPixel(ivec2 e) { return min(e * int(aoView.noise.y), ao_fullSize() - 1); }

bool ao_isSky(vec4 worldPosition) { return !(worldPosition.w > 0.0); }

vec3 ao_viewFromWorldPoint(vec3 w) { return (aoView.viewFromWorld * vec4(w, 1.0)).xyz; }

// View-space position at G-buffer pixel g; returns false for sky.
bool ao_fetchViewPosition(ivec2 g, out vec3 p) {
    vec4 w = texelFetch(aoGPosition, g, 0);
    p = ao_viewFromWorldPoint(w.xyz);
    return !ao_isSky(w) && p.z < 0.0;
}

// Unit view-space shading normal; falls back to facing the eye when the G-buffer's is unusable.
vec3 ao_fetchViewNormal(ivec2 g, vec3 p) {
    vec3 n = mat3(aoView.viewFromWorld) * texelFetch(aoGNormal, g, 0).xyz;
    float len = length(n);
    return len > 1e-20 && !isnan(len) && !isinf(len) ? n / len : normalize(-p);
}

vec3 ao_viewRayThroughPixel(vec2 c);

// The surface seen at continuous pixel coordinate c: the nearest pixel's point, slid along
// that pixel's tangent plane to the eye ray through c. Exact on planes, so marching methods
// need no bias against the up-to-half-pixel snapping error; falls back to the pixel centre
// where the plane is grazing (a depth change over 10 %).
bool ao_fetchSurfaceAt(vec2 c, out vec3 s) {
    ivec2 q = ivec2(floor(c));
    if (!ao_fetchViewPosition(q, s)) return false;
    vec3 n = ao_fetchViewNormal(q, s);
    vec3 ray = ao_viewRayThroughPixel(c);
    float depth = dot(n, s) / dot(n, ray);  // ray.z = -1, so this is the linear depth
    if (depth > 0.0 && abs(depth + s.z) < 0.1 * (-s.z)) s = ray * depth;
    return true;
}

vec2 ao_pixelFromView(vec3 p) { return aoView.pixelFromView.xy * p.xy / (-p.z) + aoView.pixelFromView.zw; }

// Direction (not normalized, z = -1) of the eye ray through continuous pixel coordinate c.
vec3 ao_viewRayThroughPixel(vec2 c) { return vec3((c - aoView.pixelFromView.zw) / aoView.pixelFromView.xy, -1.0); }

// Pixels spanned by a world length at linear depth d (focal length along y).
float ao_pixelsPerUnit(float d) { return aoView.pixelFromView.y / d; }

// PCG3D (Jarzynski and Olano 2020): a per-pixel hash seeded by the run's seed, so noise is
// deterministic for a given seed and decorrelated between salts.
uvec3 ao_pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    return v;
}
vec2 ao_pixelNoise(ivec2 g, uint salt) {
    uvec3 h = ao_pcg3d(uvec3(uvec2(g), aoView.noise.x ^ (salt * 0x9E3779B9u)));
    return vec2(h.xy >> 8u) * (1.0 / 16777216.0);  // 24-bit uniforms in [0, 1)
}

// Every pass writes through here: AO in [0, maxValue] (1 for a chain's last pass), never NaN.
float ao_sanitize(float a, float maxValue) { return isnan(a) || isinf(a) ? 1.0 : clamp(a, 0.0, maxValue); }
float ao_sanitize(float a) { return ao_sanitize(a, 1.0); }

// One slice of the horizon search of GTAO (Jimenez et al. 2016, Algorithm 1, lines 5-15),
// shared by gtao, vbao and ssil: the slice at angle phi in the image plane, its step vector
// scaled to the screen radius, and the shading normal projected into the slice's plane
// (its length weights the slice; angleN is its signed angle from the view vector).
struct AoSlice {
    vec2 omega;             // pixels per unit step along the slice
    float projectedLength;
    float cosN;
    float angleN;
};

AoSlice ao_slice(float phi, float screenRadius, vec3 n, vec3 viewVec) {
    AoSlice sl;
    sl.omega = vec2(cos(phi), sin(phi)) * screenRadius;
    vec3 direction = vec3(cos(phi), sin(phi), 0.0);                        // line 8
    vec3 orthoDirection = direction - dot(direction, viewVec) * viewVec;   // line 9
    vec3 axis = normalize(cross(orthoDirection, viewVec));                 // line 10
    vec3 projectedNormal = n - axis * dot(n, axis);                        // line 11
    float signN = sign(dot(orthoDirection, projectedNormal));              // line 13
    sl.projectedLength = length(projectedNormal);
    sl.cosN = clamp(dot(projectedNormal, viewVec) / max(sl.projectedLength, 1e-30), 0.0, 1.0);  // 14
    sl.angleN = signN * acos(sl.cosN);                                     // line 15
    return sl;
}
