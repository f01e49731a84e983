// A brick's shell: its voxels with a coordinate at 0 or BRICK_SIZE - 1, the only ones the 3x3x3
// stencils of other bricks read. update_phi writes a brick's new interior in place and its new
// shell aside (shellNext), so that no group reads a neighbour's half-updated shell;
// settle_bricks then copies the shells in. Host mirror: GpuBrickPool::shellBytes().
const int SHELL_RING = 4 * BRICK_SIZE - 4; // shell voxels of one inner z slice
const uint SHELL_VOXELS = uint(2 * BRICK_SIZE * BRICK_SIZE + (BRICK_SIZE - 2) * SHELL_RING);

layout(std430, binding = SHELL_NEXT_BINDING) buffer ShellNext { float shellNext[]; };

bool onShell(ivec3 l) {
    return any(equal(l, ivec3(0))) || any(equal(l, ivec3(BRICK_SIZE - 1)));
}

// Position of shell voxel l among its brick's SHELL_VOXELS: the z = 0 face, the z = last face,
// then each inner slice's ring (row y = 0, row y = last, then x = 0 / x = last of the rows
// between).
uint shellIndex(ivec3 l) {
    const int B = BRICK_SIZE;
    if (l.z == 0) {
        return uint(l.x + B * l.y);
    }
    if (l.z == B - 1) {
        return uint(B * B + l.x + B * l.y);
    }
    int ring = 2 * B * B + (l.z - 1) * SHELL_RING;
    if (l.y == 0) {
        return uint(ring + l.x);
    }
    if (l.y == B - 1) {
        return uint(ring + B + l.x);
    }
    return uint(ring + 2 * B + 2 * (l.y - 1) + (l.x == B - 1 ? 1 : 0));
}

// The shell voxel at position i (< SHELL_VOXELS): the inverse of shellIndex.
ivec3 shellVoxel(uint i) {
    const int B = BRICK_SIZE;
    int n = int(i);
    if (n < 2 * B * B) {
        return ivec3(n % B, (n / B) % B, n < B * B ? 0 : B - 1);
    }
    n -= 2 * B * B;
    int z = 1 + n / SHELL_RING;
    int r = n % SHELL_RING;
    if (r < 2 * B) {
        return ivec3(r % B, r < B ? 0 : B - 1, z);
    }
    r -= 2 * B;
    return ivec3((r % 2) * (B - 1), 1 + r / 2, z);
}
