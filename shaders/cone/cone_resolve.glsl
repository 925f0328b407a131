// The stages every cone pixel pass runs (cone_ao.glsl, cone_gi.glsl; dense grid or
// clipmap), with vct.trace-scale = s (ConeUniforms::trace.x):
//   trace    one pixel per s x s block (cone_tracedPixel) marches its cones into the traced
//            image at the block's coordinate; with s = 1 that is every pixel, finished, into
//            the output, and nothing else runs;
//   resolve  (s > 1) every surface pixel takes the traced values of its four nearest blocks,
//            weighted bilinearly and by how well each block's pixel shares its surface
//            (cone_resolveAgreement), and lists the pixel for the wide stage when the four
//            share none;
//   wide     (s > 1, when the resolve listed pixels) each listed pixel (a silhouette, a
//            corner) takes the sixteen nearest blocks by agreement alone, and lists itself for
//            the own stage when no block shares its surface (CONE_STAGE_WIDE, cone_shared.h,
//            says why this is a stage);
//   own      (s > 1, when the resolve listed pixels) each listed pixel traces its own cones
//            (CONE_STAGE_OWN, cone_shared.h, says why this is a stage). (Tracing also
//            where the blocks disagree, at a crease's dark band, was tried: on the Cornell
//            box it traced half the pixels at s = 4 and moved the error against the ray
//            tracer by 0.001.)
// The resolve is its own program (CONE_RESOLVE_STAGE defined: no cone march, no volume) and
// runs the resolve and wide stages; the trace program runs the trace and own stages.
// The includer defines, before including this file:
//   vec4 cone_passTrace(ivec2 pix, vec3 p, vec3 n, vec3 ng, out vec2 counts)
//            the pixel's traced value (what the resolve interpolates) and (samples, fetches);
//            not in the resolve program
//   vec4 cone_passFinish(ivec2 pix, vec4 traced)   the output at pix from a traced value
//   vec4 cone_passSky()                            the output of a pixel with no surface
//   vec4 cone_passTraced(ivec2 cell)               the traced image at a block
//   void cone_passStore(ivec2 at, vec4 v)          writes the output (or traced) image
// and the counts buffer cone_counts[] (per pixel (samples, fetches), zeroed by the caller).
// (Loading a work group's blocks once into shared memory, as a GPU would, was tried: it gives
// the same image and made the resolve slower on llvmpipe, whose barrier() is costly.)

// The pixels that trace their own cones, cone_listPixels[0, cone_ownCount), and those the
// wide stage resolves, cone_listPixels[width x height + i] for i < cone_wideCount, each as
// y x width + x (the caller zeroes both counts and sizes the array for two lists of every
// pixel: 8 bytes a pixel, so a 4K image's lists stay within GL's 128 MiB storage block).
layout(std430, binding = CONE_BINDING_OWN_LIST) buffer ConeOwnList {
    uint cone_ownCount;
    uint cone_wideCount;
    uint cone_ownPad[CONE_OWN_LIST_HEADER - 2];
    uint cone_listPixels[];
};

// The first entry of the wide stage's list in cone_listPixels.
uint cone_wideListStart() { return uint(u.image.x) * uint(u.image.y); }

uint cone_listIndex(ivec2 q) { return uint(q.y) * uint(u.image.x) + uint(q.x); }
ivec2 cone_listPixel(uint i) { return ivec2(i % uint(u.image.x), i / uint(u.image.x)); }

// The list entry of this invocation in a stage over a list (the own and wide stages).
uint cone_listEntry() {
    return uint(u.trace.z) + gl_WorkGroupID.x * uint(CONE_LOCAL_SIZE * CONE_LOCAL_SIZE) + gl_LocalInvocationIndex;
}

// The pixel that traces block `cell`: the block's centre, clamped to the image.
ivec2 cone_tracedPixel(ivec2 cell, int s) { return min(cell * s + ivec2(s / 2), u.image.xy - 1); }

#ifdef CONE_RESOLVE_STAGE

// A block as the resolve reads it: its traced pixel's surface (surface false for a sky
// block) and its traced value.
struct ConeResolveBlock {
    bool surface;
    vec3 p, n, ng;
    vec4 traced;
};

ConeResolveBlock cone_loadBlock(ivec2 cell, int s) {
    ConeResolveBlock b;
    b.surface = cone_surface(cone_tracedPixel(cell, s), b.p, b.n, b.ng);
    b.traced = cone_passTraced(cell);
    return b;
}

// How well block b's traced pixel shares the surface of the point p (normal n): the
// shading normals' agreement times the tangent-plane agreement (CONE_RESOLVE_*, cone_shared.h);
// 0 for a sky block.
float cone_resolveAgreement(ConeResolveBlock b, vec3 p, vec3 n) {
    if (!b.surface) return 0.0;
    float wn = pow(max(dot(n, b.n), 0.0), CONE_RESOLVE_NORMAL_POWER);
    vec3 offset = p - b.p;
    float separation = length(offset);
    float slope = separation > 0.0 ? abs(dot(b.ng, offset)) / separation : 0.0;
    return wn * max(0.0, 1.0 - slope / CONE_RESOLVE_PLANE_SLOPE);
}

// Pixel q (point p, normal n) of region c0 from the sixteen blocks around the region, by
// agreement alone; listed for the own stage when no block shares its surface (an object
// narrower than a block).
void cone_resolveWide(ivec2 q, int s, ivec2 blocks, ivec2 c0, vec3 p, vec3 n) {
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int j = -1; j <= 2; ++j)
        for (int i = -1; i <= 2; ++i) {
            ivec2 c = c0 + ivec2(i, j);
            if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, blocks))) continue;
            ConeResolveBlock b = cone_loadBlock(c, s);
            float w = cone_resolveAgreement(b, p, n);
            sum += w * b.traced;
            weight += w;
        }
    if (weight < CONE_RESOLVE_MIN_WEIGHT) {
        cone_listPixels[atomicAdd(cone_ownCount, 1u)] = cone_listIndex(q);
        return;
    }
    cone_passStore(q, cone_passFinish(q, sum / weight));
}

// The region of pixel q: the c0 whose pixels run from block c0's traced pixel up to, not
// including, block c0 + 1's (main's regions).
ivec2 cone_regionOf(ivec2 q, int s) { return ivec2(floor(vec2(q - ivec2(s / 2)) / float(s))); }

// The wide stage: one listed pixel per invocation.
void cone_wideStage() {
    uint entry = cone_listEntry();
    if (entry >= cone_wideCount) return;
    ivec2 q = cone_listPixel(cone_listPixels[cone_wideListStart() + entry]);
    vec3 p, n, ng;
    if (!cone_surface(q, p, n, ng)) return;  // listed pixels are surface pixels
    int s = max(u.trace.x, 1);
    cone_resolveWide(q, s, (u.image.xy + s - 1) / s, cone_regionOf(q, s), p, n);
}

// Pixel q of region c0 (main), whose four nearest blocks (c0 + (i, j), clamped to the
// image's `blocks`) are near[i + 2 j].
void cone_resolve(ivec2 q, int s, ivec2 blocks, ivec2 c0, ConeResolveBlock near[4]) {
    vec3 p, n, ng;
    if (!cone_surface(q, p, n, ng)) {
        cone_passStore(q, cone_passSky());
        return;
    }
    // Block coordinates of q (block c's traced pixel sits at c exactly): c0 + f, f in [0, 1).
    vec2 f = (vec2(q) - float(s / 2)) / float(s) - vec2(c0);
    vec4 sum = vec4(0.0);
    float weight = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ConeResolveBlock b = near[i + 2 * j];
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) * cone_resolveAgreement(b, p, n);
            sum += w * b.traced;
            weight += w;
        }
    if (weight < CONE_RESOLVE_MIN_WEIGHT) {
        // A silhouette or a corner: the sixteen nearest blocks, in the wide stage.
        cone_listPixels[cone_wideListStart() + atomicAdd(cone_wideCount, 1u)] = cone_listIndex(q);
        return;
    }
    cone_passStore(q, cone_passFinish(q, sum / weight));
}

// One invocation per region of the s x s pixels that share their four nearest blocks (the
// pixels from block c0's traced pixel up to, not including, block c0 + 1's; c0 from -1 for
// the image's first pixels): it reads the four blocks once for its s^2 pixels, where one
// invocation per pixel read them s^2 times (llvmpipe, AO 512^2 at s = 4: resolve 21-24 ->
// 12 ms on the Cornell box, 30 -> 26 ms on Sponza, whose silhouettes take the sixteen-block
// path per pixel; reading those sixteen once per region too was slower, 16 ms and 28 ms: the
// sixteen blocks do not fit in the registers).
void main() {
    if (u.trace.y == CONE_STAGE_WIDE) {
        cone_wideStage();
        return;
    }
    int s = max(u.trace.x, 1);
    ivec2 blocks = (u.image.xy + s - 1) / s;
    ivec2 c0 = ivec2(gl_GlobalInvocationID.xy) - 1;
    if (any(greaterThanEqual(c0, blocks))) return;
    ConeResolveBlock near[4];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) near[i + 2 * j] = cone_loadBlock(clamp(c0 + ivec2(i, j), ivec2(0), blocks - 1), s);
    ivec2 first = c0 * s + ivec2(s / 2);
    for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x) {
            ivec2 q = first + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || q.x >= u.image.x || q.y >= u.image.y) continue;
            cone_resolve(q, s, blocks, c0, near);
        }
}

#else

void cone_ownTrace() {
    uint entry = cone_listEntry();
    if (entry >= cone_ownCount) return;
    ivec2 q = cone_listPixel(cone_listPixels[entry]);
    vec3 p, n, ng;
    if (!cone_surface(q, p, n, ng)) return;  // listed pixels are surface pixels
    vec2 counts;
    vec4 traced = cone_passTrace(q, p, n, ng, counts);
    cone_counts[q.y * u.image.x + q.x] = counts;
    cone_passStore(q, cone_passFinish(q, traced));
}

void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    int s = max(u.trace.x, 1);
    if (u.trace.y == CONE_STAGE_OWN) {
        cone_ownTrace();
        return;
    }
    ivec2 blocks = (u.image.xy + s - 1) / s;
    if (cell.x >= blocks.x || cell.y >= blocks.y) return;
    ivec2 pix = cone_tracedPixel(cell, s);
    vec3 p, n, ng;
    vec4 v = cone_passSky();
    vec2 counts = vec2(0.0);
    if (cone_surface(pix, p, n, ng)) {
        v = cone_passTrace(pix, p, n, ng, counts);
        if (s == 1) v = cone_passFinish(pix, v);
    }
    cone_counts[pix.y * u.image.x + pix.x] = counts;
    cone_passStore(cell, v);
}

#endif  // CONE_RESOLVE_STAGE
