// ssao-crytek and ssao-hemisphere: count kernel points that lie behind the depth buffer.
// Kernel offsets (unit-radius, view-independent) come from the SSBO, rotated per pixel by a
// 4x4 noise tile; a point counts as occluded when the surface seen through it is nearer
// than the point by more than the bias, with LearnOpenGL's range check
// smoothstep(0, 1, R / |d_p - d_scene|) fading occluders far in front of p.
#include "ao/ao_common.glsl"
#include "ao/ssao_shared.h"

layout(local_size_x = AO_LOCAL_SIZE_X, local_size_y = AO_LOCAL_SIZE_Y) in;
layout(std140, binding = AO_BINDING_TECHNIQUE) uniform SsaoBlock { SsaoUniforms ssao; };
layout(std430, binding = AO_BINDING_KERNEL) readonly buffer SsaoKernel { vec4 ssaoKernel[]; };
layout(r32f, binding = AO_IMAGE_OUTPUT) uniform writeonly image2D aoOut;

// Orthonormal frame around n from the tile's random vector (Gram-Schmidt, as LearnOpenGL).
mat3 ssao_tangentFrame(vec3 n, vec3 randomVec) {
    vec3 t = randomVec - n * dot(randomVec, n);
    if (dot(t, t) < 1e-8) t = abs(n.x) < 0.9 ? vec3(1, 0, 0) - n * n.x : vec3(0, 1, 0) - n * n.y;
    t = normalize(t);
    return mat3(t, cross(n, t), n);
}

float ssao_evaluate(ivec2 g) {
    vec3 p;
    if (!ao_fetchViewPosition(g, p)) return 1.0;
    vec3 n = ao_fetchViewNormal(g, p);
    float R = aoView.radius.x;
    float dP = -p.z;
    vec3 randomVec = ssao.noise[(g.x % SSAO_NOISE_TILE) + SSAO_NOISE_TILE * (g.y % SSAO_NOISE_TILE)].xyz;
    bool hemisphere = ssao.config.x == SSAO_KERNEL_HEMISPHERE;
    mat3 frame = ssao_tangentFrame(n, randomVec);

    float occlusion = 0.0;
    int counted = 0;
    for (int i = 0; i < ssao.config.y; ++i) {
        vec3 k = ssaoKernel[i].xyz;
        vec3 offset = hemisphere ? frame * k : reflect(k, randomVec);
        vec3 s = p + R * offset;
        if (s.z >= 0.0) continue;  // behind the eye: not on screen
        ivec2 q = ivec2(floor(ao_pixelFromView(s)));
        if (!ao_onScreen(q)) continue;  // off screen: skipped, neither open nor occluded
        ++counted;
        // A hemisphere point that projects into p's own pixel is compared with the depth along
        // the pixel centre's ray, not its own: on a slanted plane it reads occluded whenever it
        // lies farther than p, so A -> ~0.9 instead of 1 as R -> 0 (stability suite, R = 1e-4).
        // The depth buffer knows nothing finer than p's pixel; the point is above p's tangent
        // plane, so it is open. (Crytek's sphere keeps its documented ~0.5 on flat ground.)
        if (hemisphere && q == g) continue;
        vec3 scene;
        if (!ao_fetchViewPosition(q, scene)) continue;  // sky behind the point: open
        float dSample = -s.z, dScene = -scene.z;
        float range = ssao.config.z != 0 ? smoothstep(0.0, 1.0, R / max(abs(dP - dScene), 1e-30)) : 1.0;
        occlusion += (dScene <= dSample - ssao.bias.x ? 1.0 : 0.0) * range;
    }
    return counted > 0 ? 1.0 - occlusion / float(counted) : 1.0;
}

void main() {
    ivec2 e = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(e, ao_evalSize()))) return;
    imageStore(aoOut, e, vec4(ao_sanitize(ssao_evaluate(ao_gbufferPixel(e)))));
}
