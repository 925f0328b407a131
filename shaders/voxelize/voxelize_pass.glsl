// Conservative surface voxelization, accumulating order-independent fixed-point sums: the body
// of both voxelizer passes, included by voxelize.glsl and voxelize_emission.glsl after the
// images each declares.
//
// Work: the voxels a triangle can touch lie, for each column of its projection along the
// dominant normal axis, within a run of at most ~3 voxels (the plane rises by at most
// |n_a| + |n_b| <= 2 |n_d| across one column), so the cost is proportional to the
// triangle's projected area rather than its bounding-box volume (Schwarz and Seidel 2010,
// section 3). Every candidate voxel is then tested exactly with the separating-axis test
// of Akenine-Moller 2001 (13 axes) against the voxel grown by VOX_BOX_GROWTH, so thin,
// sub-voxel and axis-aligned triangles leave no holes despite float rounding.
//
// Modes (define BIG_PASS): the small pass runs one invocation per triangle and defers
// triangles with many columns to a list; the big pass runs one work group per listed
// triangle, its invocations striding over the columns.
//
// Accumulators: OpenGL guarantees only 8 image uniforms per stage, so the 14 fixed-point
// sums are written by two passes over the triangles, two programs whose sources declare only
// the images they bind and then include this body: the geometry pass (voxelize.glsl: albedo,
// normal, weight and, for scenes with doubleSided materials, their weight: 7 or 8 images) and, for scenes with emission, the emission pass
// (voxelize_emission.glsl, EMISSION_PASS: three 64-bit sums, 6 images), which skips every
// triangle whose material emits nothing (its contribution is exactly zero) and reads the
// weights of the geometry pass at resolve, and, with vct.voxel.edges=coverage, the coverage
// pass (voxelize_coverage.glsl, COVERAGE_PASS: the columns' covered areas and the dominant
// axes, 2 images). Integer sums are order-independent, so the split leaves every voxel's
// value unchanged.
#ifdef BIG_PASS
layout(local_size_x = VOX_BIG_GROUP) in;
#else
layout(local_size_x = VOX_TRI_GROUP) in;
#endif

layout(std430, binding = VOX_BINDING_BIGLIST) buffer BigList {
    uvec4 bigHeader;  // x = listed triangles
    uint bigTriangles[];
};

uniform vec3 uGridOrigin;     // world
uniform float uInvVoxelSize;  // 1 / world units
uniform ivec3 uResolution;
uniform uint uTriangleCount;
uniform uint uBigBase;  // big pass: first list entry of this dispatch

struct Tri {
    vec3 p[3];      // voxel coordinates
    vec3 n[3];      // vertex normals (world = voxel orientation; unit)
    vec2 uv[3];
    vec4 color[3];  // vertex colours (GpuVertex::color)
    vec3 faceN;     // cross(p1 - p0, p2 - p0), voxel units
    uint material;
    ivec3 lo, hi;   // clamped voxel bounding box
    int axis;       // dominant axis of faceN
    uint weight;    // integer accumulation weight in [1, VOX_WEIGHT_MAX]
    float lod;      // texture level matching one voxel's footprint
};

Tri vox_loadTriangle(uint t) {
    Tri tri;
    for (int k = 0; k < 3; ++k) {
        GpuVertex v = sceneVertices[sceneIndices[3u * t + uint(k)]];
        tri.p[k] = (v.position.xyz - uGridOrigin) * uInvVoxelSize;
        tri.n[k] = v.normal.xyz;
        tri.uv[k] = v.uv.xy;
        tri.color[k] = v.color;
    }
    tri.material = sceneTriMaterial[t];
    tri.faceN = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
    vec3 bmin = min(tri.p[0], min(tri.p[1], tri.p[2]));
    vec3 bmax = max(tri.p[0], max(tri.p[1], tri.p[2]));
    tri.lo = max(ivec3(floor(bmin - 0.5 * VOX_BOX_GROWTH)), ivec3(0));
    tri.hi = min(ivec3(floor(bmax + 0.5 * VOX_BOX_GROWTH)), uResolution - 1);
    vec3 an = abs(tri.faceN);
    tri.axis = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
    float area = 0.5 * length(tri.faceN);  // in voxel faces
    tri.weight = uint(clamp(round(area * float(VOX_WEIGHT_MAX)), 1.0, float(VOX_WEIGHT_MAX)));
    vec2 duv1 = tri.uv[1] - tri.uv[0], duv2 = tri.uv[2] - tri.uv[0];
    float uvArea = 0.5 * abs(duv1.x * duv2.y - duv1.y * duv2.x);
    // Texels per voxel edge = texture size * sqrt(uv area / voxel-face area).
    float texelsPerVoxel = float(SCENE_TEXTURE_SIZE) * sqrt(uvArea / max(area, 1e-20));
    tri.lod = max(0.0, log2(max(texelsPerVoxel, 1e-8)));
    return tri;
}

// Zero-area triangles (collinear or coincident corners) are no surface: conservative
// voxelization would still fill every voxel along them (a 1-long line made a visible post).
bool vox_insideGrid(Tri tri) { return all(lessThanEqual(tri.lo, tri.hi)) && dot(tri.faceN, tri.faceN) > 0.0; }

int vox_columnCount(Tri tri) {
    int a = (tri.axis + 1) % 3, b = (tri.axis + 2) % 3;
    return (tri.hi[a] - tri.lo[a] + 1) * (tri.hi[b] - tri.lo[b] + 1);
}

// Akenine-Moller's triangle/box overlap: true unless one of the 13 axes separates them.
bool vox_overlaps(Tri tri, vec3 boxCenter) {
    const float h = 0.5 + VOX_BOX_GROWTH;
    vec3 v0 = tri.p[0] - boxCenter, v1 = tri.p[1] - boxCenter, v2 = tri.p[2] - boxCenter;
    // Box face normals.
    if (any(greaterThan(min(v0, min(v1, v2)), vec3(h))) || any(lessThan(max(v0, max(v1, v2)), vec3(-h))))
        return false;
    // Triangle plane: the box's projection radius onto n against the plane's distance.
    vec3 n = tri.faceN;
    if (abs(dot(n, v0)) > h * (abs(n.x) + abs(n.y) + abs(n.z))) return false;
    // Edge x box-axis cross products.
    vec3 e[3] = vec3[3](v1 - v0, v2 - v1, v0 - v2);
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            vec3 axis = k == 0 ? vec3(0.0, -e[i].z, e[i].y) : (k == 1 ? vec3(e[i].z, 0.0, -e[i].x)
                                                                    : vec3(-e[i].y, e[i].x, 0.0));
            float p0 = dot(axis, v0), p1 = dot(axis, v1), p2 = dot(axis, v2);
            float r = h * (abs(axis.x) + abs(axis.y) + abs(axis.z));
            if (min(p0, min(p1, p2)) > r || max(p0, max(p1, p2)) < -r) return false;
        }
    }
    return true;
}

// Barycentrics of the point of the triangle's plane nearest to `q`, clamped into the
// triangle: where the voxel samples the triangle's attributes.
vec3 vox_barycentrics(Tri tri, vec3 q) {
    vec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0], d = q - tri.p[0];
    float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    float d1 = dot(d, e1), d2 = dot(d, e2);
    float det = d11 * d22 - d12 * d12;
    if (!(det > 0.0)) return vec3(1.0 / 3.0);
    float v = (d22 * d1 - d12 * d2) / det, w = (d11 * d2 - d12 * d1) / det;
    vec3 b = max(vec3(1.0 - v - w, v, w), vec3(0.0));
    return b / (b.x + b.y + b.z);
}

#ifdef EMISSION_PASS
// Adds `x` >= 0 (< 2^56) to the 64-bit integer (hi, lo): exact, so the sum is independent
// of the order in which triangles arrive.
void vox_add64(int channel, ivec3 v, float x) {
    float hiF = floor(x * (1.0 / 4294967296.0));
    uint hi = uint(hiF);
    uint lo = uint(x - hiF * 4294967296.0);
    uint old = 0u;
    if (channel == 0) old = imageAtomicAdd(accEmissionRLo, v, lo);
    else if (channel == 1) old = imageAtomicAdd(accEmissionGLo, v, lo);
    else old = imageAtomicAdd(accEmissionBLo, v, lo);
    hi += (old + lo < old) ? 1u : 0u;
    if (hi == 0u) return;
    if (channel == 0) imageAtomicAdd(accEmissionRHi, v, hi);
    else if (channel == 1) imageAtomicAdd(accEmissionGHi, v, hi);
    else imageAtomicAdd(accEmissionBHi, v, hi);
}
#endif

// `coverage`: the fixed-point area of the triangle in v's column (COVERAGE_PASS); `sheetZ`: the
// span of its plane over that area along the dominant axis, `across`: the extent bits of that
// area across it (EDGE_SHEETS).
void vox_accumulate(Tri tri, ivec3 v, uint coverage, vec2 sheetZ, uint across) {
    vec3 b = vox_barycentrics(tri, vec3(v) + 0.5);
    vec2 uv = b.x * tri.uv[0] + b.y * tri.uv[1] + b.z * tri.uv[2];
    vec4 color = scene_vertexColor(tri.color[0], tri.color[1], tri.color[2], b);
    vec4 base = scene_baseColor(tri.material, uv, tri.lod) * color;
    if (scene_alphaCut(tri.material, base.a)) return;
    GpuMaterial m = sceneMaterials[tri.material];
    uint w = tri.weight;
#ifdef EMISSION_PASS
    vec3 e = clamp(scene_emission(tri.material, uv, tri.lod), 0.0, VOX_EMISSION_MAX);
    for (int c = 0; c < 3; ++c)
        if (e[c] > 0.0) vox_add64(c, v, e[c] * float(w) * VOX_EMISSION_SCALE);
#elif defined(COVERAGE_PASS)
    imageAtomicAdd(accCoverage, v, coverage);
    imageAtomicOr(accAxes, v, 1u << uint(tri.axis));
#ifdef EDGE_SHEETS
    if (coverage > 0u) {
        uvec2 span = vox_sheetSpanFixed(sheetZ, float(v[tri.axis]));
        imageAtomicMax(accSheetLo, v, span.x);
        imageAtomicMax(accSheetHi, v, span.y);
        imageAtomicOr(accSheetExtent, v, vox_triangleExtentBits(across, sheetZ, float(v[tri.axis]), tri.axis));
    }
#endif
#elif defined(OPACITY_ONLY)
    imageAtomicAdd(accWeight, v, w);
#else
    vec3 n = b.x * tri.n[0] + b.y * tri.n[1] + b.z * tri.n[2];
    float len = length(n);
    float faceLen = length(tri.faceN);
    n = len > 1e-6 ? n / len : (faceLen > 0.0 ? tri.faceN / faceLen : vec3(0.0));
    uvec3 a = uvec3(round(clamp(base.rgb, 0.0, 1.0) * VOX_ALBEDO_SCALE)) * w;
    ivec3 q = ivec3(round(clamp(n, -1.0, 1.0) * VOX_NORMAL_SCALE)) * int(w);
    imageAtomicAdd(accAlbedoR, v, a.r);
    imageAtomicAdd(accAlbedoG, v, a.g);
    imageAtomicAdd(accAlbedoB, v, a.b);
    imageAtomicAdd(accNormalX, v, uint(q.x));
    imageAtomicAdd(accNormalY, v, uint(q.y));
    imageAtomicAdd(accNormalZ, v, uint(q.z));
    imageAtomicAdd(accWeight, v, w);
#ifdef TWO_SIDED
    if ((m.flags & MATERIAL_DOUBLE_SIDED) != 0) imageAtomicAdd(accTwoSided, v, w);
#endif
#endif
}

// Tests and accumulates the voxel run of one column of the dominant-axis projection.
void vox_column(Tri tri, int column) {
    int d = tri.axis, a = (d + 1) % 3, b = (d + 2) % 3;
    int width = tri.hi[a] - tri.lo[a] + 1;
    int i = tri.lo[a] + column % width, j = tri.lo[b] + column / width;
    int kLo = tri.lo[d], kHi = tri.hi[d];
    vec3 n = tri.faceN;
    if (abs(n[d]) > 0.0) {
        // Plane height over the column's (grown) corners.
        float c = dot(n, tri.p[0]);
        float g = VOX_BOX_GROWTH;
        float zMin = 3.4e38, zMax = -3.4e38;
        for (int k = 0; k < 4; ++k) {
            float pa = float(i) + ((k & 1) != 0 ? 1.0 + g : -g);
            float pb = float(j) + ((k & 2) != 0 ? 1.0 + g : -g);
            float z = (c - n[a] * pa - n[b] * pb) / n[d];
            zMin = min(zMin, z);
            zMax = max(zMax, z);
        }
        // One extra voxel each side absorbs the rounding of the division above; the exact
        // test below decides.
        kLo = max(kLo, int(floor(zMin)) - 1);
        kHi = min(kHi, int(floor(zMax)) + 1);
    }
    uint coverage = 0u;
    vec2 sheetZ = vec2(0.0);
    uint across = 0u;
#ifdef COVERAGE_PASS
#ifdef EDGE_SHEETS
    vec4 plane = vec4(n[a], n[b], n[d], dot(n, tri.p[0]));
#else
    vec4 plane = vec4(0.0);
#endif
    VoxColumnCut cut = vox_columnCut(vec2(tri.p[0][a], tri.p[0][b]), vec2(tri.p[1][a], tri.p[1][b]),
                                     vec2(tri.p[2][a], tri.p[2][b]), vec2(float(i), float(j)), plane);
    coverage = vox_coverageFixed(cut.area);
    sheetZ = vec2(cut.zMin, cut.zMax);
#ifdef EDGE_SHEETS
    across = vox_extentBits(cut.boxLo.x, cut.boxHi.x, a) | vox_extentBits(cut.boxLo.y, cut.boxHi.y, b);
#endif
#endif
    for (int k = kLo; k <= kHi; ++k) {
        ivec3 v;
        v[a] = i;
        v[b] = j;
        v[d] = k;
        if (vox_overlaps(tri, vec3(v) + 0.5)) vox_accumulate(tri, v, coverage, sheetZ, across);
    }
}

void main() {
#ifdef BIG_PASS
    uint t = bigTriangles[uBigBase + gl_WorkGroupID.x];
    Tri tri = vox_loadTriangle(t);
    int columns = vox_columnCount(tri);
    for (int c = int(gl_LocalInvocationIndex); c < columns; c += VOX_BIG_GROUP) vox_column(tri, c);
#else
    uint t = gl_GlobalInvocationID.x;
    if (t >= uTriangleCount) return;
#ifdef EMISSION_PASS
    // A material without an emissive factor adds exactly zero to every emission sum.
    if (all(equal(sceneMaterials[sceneTriMaterial[t]].emissive.rgb, vec3(0.0)))) return;
#endif
    Tri tri = vox_loadTriangle(t);
    if (!vox_insideGrid(tri)) return;
    int columns = vox_columnCount(tri);
    if (columns > VOX_SMALL_COLUMNS) {
        uint slot = atomicAdd(bigHeader.x, 1u);
        bigTriangles[slot] = t;
        return;
    }
    for (int c = 0; c < columns; ++c) vox_column(tri, c);
#endif
}
