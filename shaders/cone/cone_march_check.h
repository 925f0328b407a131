// One evaluation of every function of cone_march_shared.h and common/tangent_frame.h on one
// input, over a small analytic volume, shared by the check kernel (cone_march_check.glsl)
// and tests/gpu/cone_march_shared_test.cpp: the test runs cone_checkEvaluate on the CPU and
// in the kernel on the same inputs, so the C++ the CPU tracer runs and the GLSL the passes
// run are shown to be the same computation.
#pragma once
#include "cone/cone_march_shared.h"
#include "common/tangent_frame.h"

VCT_BEGIN_NAMESPACE

VCT_CONST int CONE_CHECK_GROUP = 64;          // invocations per work group, one input each
VCT_CONST int CONE_CHECK_BINDING_INPUTS = 0;  // SSBO of ConeCheckInput[]
VCT_CONST int CONE_CHECK_BINDING_OUTPUTS = 1;  // SSBO of ConeCheckOutput[]

// The volume: the box [0, 32]^3 with levels 0..5 (a 32^3 grid's mips), holding a slab of
// medium across z in [12, 20] whose opacity ramps up over 2 voxels at each face, thins with
// the level as a mip of a thin layer would, and carries a constant colour. Everything is
// continuous in p, so a rounding difference between CPU and GPU stays a rounding difference.
VCT_CONST float CONE_CHECK_SIZE = 32.0f;
VCT_CONST float CONE_CHECK_MAX_LOD = 5.0f;

// Levels finer than the footprint's are refused past x = 24 (rising to 2 at x = 32), as a
// clipmap refuses them near a level's border: the march's second lod() call then matters.
CONE_FN float cone_checkLod(float lod, vec3 x) {
    return min(max(lod, clamp((x.x - 24.0f) * 0.25f, 0.0f, 2.0f)), CONE_CHECK_MAX_LOD);
}

CONE_FN bool cone_checkLeaving(vec3 p, vec3 d, float texel) {
    return cone_leaving(p, d, vec3(CONE_CHECK_SIZE), 1.5f * texel);
}

CONE_FN vec4 cone_checkSample(vec3 p, float lod) {
    float inside = clamp((p.z - 12.0f) * 0.5f, 0.0f, 1.0f) * clamp((20.0f - p.z) * 0.5f, 0.0f, 1.0f);
    float a = 0.6f * inside / (1.0f + 0.25f * lod);
    return vec4(vec3(0.8f, 0.5f, 0.2f) * a, a);
}

// The facing rule against a fixed mean normal of partial coverage (length 0.36).
CONE_FN float cone_checkFacing(vec3 d) {
    return vox_facingWeight(vec3(0.0f, 0.3f, -0.2f), d);
}

// One input; every member is read by cone_checkEvaluate.
struct ConeCheckInput {
    vec4 normal;     // xyz: the frame's unit normal
    vec4 march;      // ConeMarch: tan(aperture / 2), beta, max alpha, plane ratio
    vec4 origin;     // xyz: the march's origin (voxels), w = h0
    vec4 direction;  // xyz: the march's unit direction, w = rise
    vec4 limits;     // x = max distance, y = falloff lambda, z = t of the footprint check
    vec4 partial;    // a cone's result so far: radiance, alpha (compositing, closing)
    vec4 incoming;   // a sample composited onto it: premultiplied radiance, alpha
    vec4 step;       // x = dt, y = texel, z = tMid of that sample
};

struct ConeCheckOutput {
    vec4 frameT, frameB, frameN;  // frame_fromZ(normal), xyz
    vec4 lod;        // x = cone_footprintLod at limits.z, y = the volume's lod() of it at the
                     // origin, z = cone_leaving at the origin, w = at the point limits.x along d
    vec4 composite;  // partial after cone_composite(sample)
    vec4 closed;     // that after cone_close
    vec4 march;      // cone_marchVolume: radiance, alpha
};

CONE_VOLUME_TEMPLATE
CONE_FN ConeCheckOutput cone_checkEvaluate(CONE_VOLUME_PARAM ConeCheckInput c) {
    ConeCheckOutput o;
    mat3 f = frame_fromZ(vec3(c.normal));
    o.frameT = vec4(f[0], 0.0f);
    o.frameB = vec4(f[1], 0.0f);
    o.frameN = vec4(f[2], 0.0f);

    ConeMarch m = {c.march.x, c.march.y, c.march.z, c.march.w, vec3(0.0f), 0.0f, 0.0f};
    vec3 origin = vec3(c.origin);
    vec3 d = vec3(c.direction);
    float lod = cone_footprintLod(m, c.limits.z, c.origin.w, c.direction.w);
    float texel = exp2(lod);
    bool leavingAtOrigin = cone_leaving(origin, d, vec3(CONE_CHECK_SIZE), texel);
    bool leavingAtEnd = cone_leaving(origin + d * c.limits.x, d, vec3(CONE_CHECK_SIZE), texel);
    o.lod = vec4(lod, cone_checkLod(lod, origin), leavingAtOrigin ? 1.0f : 0.0f, leavingAtEnd ? 1.0f : 0.0f);

    ConeResult r;
    r.radiance = vec3(c.partial);
    r.alpha = c.partial.w;
    cone_composite(r, c.incoming, c.step.x, c.step.y, c.step.z, c.limits.y);
    o.composite = vec4(r.radiance, r.alpha);
    cone_close(r, m.maxAlpha);
    o.closed = vec4(r.radiance, r.alpha);

    r = cone_marchVolume(CONE_VOLUME_ARG m, origin, d, c.origin.w, c.direction.w, c.limits.x, c.limits.y);
    o.march = vec4(r.radiance, r.alpha);
    return o;
}

#ifdef __cplusplus
// The volume as cone_marchVolume's template reads it.
struct ConeCheckVolume {
    float lod(float l, vec3 x) const { return cone_checkLod(l, x); }
    bool leaving(vec3 p, vec3 d, float texel) const { return cone_checkLeaving(p, d, texel); }
    vec4 sample(vec3 p, vec3, float l, float, vec2) const { return cone_checkSample(p, l); }
    float facing(vec3, vec3 d, float, vec4) const { return cone_checkFacing(d); }
};
#else
// The volume as cone_marchVolume's prototypes name it.
float cone_volumeLod(float lod, vec3 x) { return cone_checkLod(lod, x); }
bool cone_volumeLeaving(vec3 p, vec3 d, float texel) { return cone_checkLeaving(p, d, texel); }
vec4 cone_volumeSample(vec3 p, vec3 d, float lod, float dt, vec2 cap) { return cone_checkSample(p, lod); }
float cone_volumeFacing(vec3 p, vec3 d, float lod, vec4 s) { return cone_checkFacing(d); }
#endif

VCT_END_NAMESPACE
