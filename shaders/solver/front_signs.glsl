// The front of a brick from the sign rows update_phi and allocate_bricks keep
// (solver/speed_cache.glsl), a row of voxels at a time: a voxel is on the front where its bit
// differs from a face neighbour's, the same test as onFront (phi_stencil.glsl) on the values
// the rows were taken from. A face neighbour past the volume's end is the voxel itself, as
// phiAt repeats the border voxel. Include after solver/speed_cache.glsl.

// The brick's face neighbours in FACE_NEIGHBOURS order: a slot, or BRICK_INSIDE / BRICK_OUTSIDE
// (also past the grid, where no voxel is read). Filled by findFaceSlots.
shared uint faceSlot[6];

// From one invocation, before a barrier(): the neighbours of `brick`; whether every slot among
// them and `slot` keeps its sign rows.
bool findFaceSlots(uint slot, ivec3 brick) {
    bool kept = signsKept(slot);
    for (int f = 0; f < 6; ++f) {
        ivec3 b = brick + FACE_NEIGHBOURS[f];
        uint s = brickInGrid(b) ? pageTable[brickIndex(b)] : BRICK_OUTSIDE;
        faceSlot[f] = s;
        if (s != BRICK_INSIDE && s != BRICK_OUTSIDE && !signsKept(s)) {
            kept = false;
        }
    }
    return kept;
}

// Row (y, z), 0 .. BRICK_SIZE - 1, of slot s or of a constant brick.
uint signRowOf(uint s, int y, int z) {
    if (s == BRICK_INSIDE) {
        return ROW_BITS;
    }
    if (s == BRICK_OUTSIDE) {
        return 0u;
    }
    return signRow(s, uint(y + BRICK_SIZE * z));
}

// Row (y, z) of the brick in `slot`, y and z in -1 .. BRICK_SIZE (not both outside): the face
// neighbour's row where one is.
uint signRowAround(uint slot, int y, int z) {
    const int L = BRICK_SIZE - 1;
    if (y < 0 || y > L) {
        return signRowOf(faceSlot[y < 0 ? 2 : 3], y < 0 ? L : 0, z);
    }
    if (z < 0 || z > L) {
        return signRowOf(faceSlot[z < 0 ? 4 : 5], y, z < 0 ? L : 0);
    }
    return signRowOf(slot, y, z);
}

// The bits of row (y, z) of the brick at voxel `origin` in `slot` whose voxels are on the front;
// the row lies in the volume, and bits past the volume's end are clear.
uint frontRow(uint slot, ivec3 origin, int y, int z) {
    const int L = BRICK_SIZE - 1;
    ivec3 g = origin + ivec3(0, y, z);
    int width = min(BRICK_SIZE, volumeDims.x - origin.x);
    uint c = signRowAround(slot, y, z);
    uint before = origin.x == 0 ? c : signRowOf(faceSlot[0], y, z) >> uint(L);
    uint xm = (c << 1) | (before & 1u);
    uint xp = c >> 1;
    if (origin.x + BRICK_SIZE < volumeDims.x) {
        xp |= (signRowOf(faceSlot[1], y, z) & 1u) << uint(L);
    } else {
        uint last = 1u << uint(width - 1);
        xp = (xp & ~last) | (c & last);
    }
    uint ym = g.y == 0 ? c : signRowAround(slot, y - 1, z);
    uint yp = g.y + 1 >= volumeDims.y ? c : signRowAround(slot, y + 1, z);
    uint zm = g.z == 0 ? c : signRowAround(slot, y, z - 1);
    uint zp = g.z + 1 >= volumeDims.z ? c : signRowAround(slot, y, z + 1);
    uint differs = (c ^ xm) | (c ^ xp) | (c ^ ym) | (c ^ yp) | (c ^ zm) | (c ^ zp);
    return differs & ((1u << uint(width)) - 1u);
}
