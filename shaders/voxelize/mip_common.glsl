// Child ranges of a mip voxel: 2v and 2v + 1, plus 2v + 2 at the last voxel of an axis whose
// source size is odd (so nothing is dropped from non-power-of-two grids).
void mip_childRange(ivec3 v, ivec3 srcSize, ivec3 dstSize, out ivec3 lo, out ivec3 hi) {
    lo = min(2 * v, srcSize - 1);
    hi = min(2 * v + 1, srcSize - 1);
    for (int a = 0; a < 3; ++a)
        if (v[a] == dstSize[a] - 1) hi[a] = srcSize[a] - 1;
}
