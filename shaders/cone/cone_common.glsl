// What every cone pass shares (dense grid: cone_march.glsl; clipmap: clipmap_march.glsl):
// the uniform block, the G-buffer, and the gather of the cone set around a normal. The march
// itself is cone_march_shared.h's; the includer defines its volume (cone_volumeLod,
// cone_volumeLeaving, cone_volumeSample, cone_volumeFacing). Include this first: the shader
// loader expands each file once.
#include "cone/cone_shared.h"
#ifndef CONE_RESOLVE_STAGE  // the resolve program (cone_resolve.glsl) marches no cones
#include "cone/cone_march_shared.h"
#include "common/tangent_frame.h"
#endif

layout(std140, binding = CONE_UBO_BINDING) uniform ConeBlock { ConeUniforms u; };

// G-buffer units of render/gbuffer.h (GBufferUnit).
layout(binding = 0) uniform sampler2D gbufPosition;
layout(binding = 1) uniform sampler2D gbufNormal;
layout(binding = 2) uniform sampler2D gbufGeomNormal;
layout(binding = 3) uniform sampler2D gbufAlbedo;

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

#ifndef CONE_RESOLVE_STAGE
// The march settings of the uniform block.
ConeMarch cone_uniformMarch() {
    return ConeMarch(u.march.x, u.march.y, u.march.w, u.limits.w, u.gridResolution.xyz,
                     u.lanes.w != 0 ? cone_endRatio(u.march.y) : 0.0, u.caps.x);
}

// The cone set around shading normal n: sum_c w_c * (cone result) integrates the cosine lobe.
// Cones whose axis is below the geometric plane are closed (as in the AO definition, directions below
// the geometric normal count as occluded), every lane of them; a lane below it of a cone
// above it is open (cone_laneState).
struct ConeGather {
    vec3 radiance;    // sum_c w_c * (radiance_c + (1 - alpha_c) * sky)
    float occlusion;  // sum_c w_c * alpha_c
    float samples;    // volume samples of all its cones
};

// Texture fetches this invocation's volume made (the volume's sample and facing functions
// count them): with the samples, the cone pass's cost in units a GPU can be reasoned in.
float cone_fetches = 0.0;

// The turn of the cone set about the normal (vct.jitter), set by a pixel pass before its
// gather; 0 keeps the set as it is (bounces never turn it).
float cone_rotation = 0.0;

// Sets cone_rotation for pixel `pix` when the pass jitters its cones.
void cone_jitterPixel(ivec2 pix) {
    if (u.image.z != 0) cone_rotation = cone_jitterAngle(uint(pix.x), uint(pix.y), uint(u.image.w));
}

// A gather split over dispatches (CONE_LOOP_BUDGET, cone_shared.h): each dispatch marches a
// slice of the cone set (u.cones holds it) and leaves its running sums in cone_carried[slot]
// for the next, which adds its own cones to them: the sums one dispatch would have made, in
// its order, to the bit. `slot` is the pixel (pixel passes) or the list entry (bounces).
struct ConeCarried {
    vec4 light;   // (radiance, occlusion) summed so far
    vec4 counts;  // (samples, fetches, 0, 0) so far
};
layout(std430, binding = CONE_BINDING_CARRY) buffer ConeCarry { ConeCarried cone_carried[]; };

// The sums a gather starts from: zero, or what the previous dispatch carried (its fetches
// into cone_fetches).
ConeGather cone_gatherStart(uint slot) {
    ConeGather g;
    g.radiance = vec3(0.0);
    g.occlusion = 0.0;
    g.samples = 0.0;
    if ((u.trace.w & CONE_SPLIT_RESUME) != 0) {
        ConeCarried c = cone_carried[slot];
        g.radiance = c.light.xyz;
        g.occlusion = c.light.w;
        g.samples = c.counts.x;
        cone_fetches = c.counts.y;
    }
    return g;
}

// Leaves the gather's sums for the next dispatch when one follows.
void cone_gatherCarry(uint slot, ConeGather g) {
    if ((u.trace.w & CONE_SPLIT_CARRY) != 0)
        cone_carried[slot] = ConeCarried(vec4(g.radiance, g.occlusion), vec4(g.samples, cone_fetches, 0.0, 0.0));
}

// The gather from voxel-space point p (the surface point, or a voxel centre for bounces) of
// this dispatch's cones, added to `g` (cone_gatherStart); the cones start `offset` voxels
// along ng, and `h0` is that start's height above the tangent plane for the plane limit.
ConeGather cone_gatherVoxel(ConeGather g, vec3 p, vec3 n, vec3 ng, float offset, float h0, float maxDist,
                            float falloff, float sky) {
    mat3 frame = frame_fromZ(n);
    if (cone_rotation != 0.0) {
        float c = cos(cone_rotation), s = sin(cone_rotation);
        frame = frame * mat3(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);  // about the frame's z = n
    }
    ConeMarch m = cone_uniformMarch();
    vec3 origin = p + ng * offset;
    for (int c = 0; c < u.config.x; ++c) {
        vec4 cone = u.cones[c];
        vec3 d = normalize(frame * cone.xyz);
        float rise = dot(d, ng);
        float axisRise = u.lanes.x > 1 ? dot(frame * u.coneAxes[cone_laneCone(u.lanes.y + c, u.lanes.x)].xyz, ng) : rise;
        int state = cone_laneState(rise, axisRise);
        if (state == CONE_LANE_CLOSED) {
            g.occlusion += cone.w;
            continue;
        }
        if (state == CONE_LANE_OPEN) {
            if ((u.lanes.z & CONE_LANES_MIRROR) == 0) {
                g.radiance += cone.w * sky;
                continue;
            }
            d = cone_mirrored(d, ng);  // vct.below-plane=mirror
        }
        // vct.aim: towards the point the lane's ray from p reaches at maxDist.
        // It marches to that point (cone_aimedReach), not maxDist past its start.
        bool aim = (u.lanes.z & CONE_LANES_AIM) != 0;
        vec3 marched = aim ? cone_aimedDirection(d, ng, offset, maxDist) : d;
        float reach = aim ? cone_aimedReach(d, ng, offset, maxDist) : maxDist;
        ConeResult r = cone_marchVolume(m, origin, marched, h0, dot(marched, ng), reach, falloff);
        g.radiance += cone.w * (r.radiance + (1.0 - r.alpha) * sky);
        g.occlusion += cone.w * r.alpha;
        g.samples += r.samples;
    }
    return g;
}
#endif
