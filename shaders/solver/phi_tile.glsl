// A brick's phi plus a one-voxel apron in shared memory, so that each voxel's 3x3x3 stencil
// costs no page-table look-ups (include after common/brick_pool.glsl and solver/phi_stencil.glsl).
const int APRON = BRICK_SIZE + 2;
shared float tile[APRON * APRON * APRON];

// Fills the tile of the brick starting at voxel `origin`, stored in `slot`; call barrier() before
// reading. The brick's own voxels inside the volume come straight from its slot, where phiAt
// would find them through the page table; the apron, and voxels past the volume's end (which
// repeat the border voxel), through phiAt.
void loadTile(ivec3 origin, uint slot) {
    for (uint a = gl_LocalInvocationIndex; a < uint(APRON * APRON * APRON); a += uint(LOCAL_SIZE)) {
        int i = int(a);
        ivec3 l = ivec3(i % APRON, (i / APRON) % APRON, i / (APRON * APRON)) - 1;
        bool own = all(greaterThanEqual(l, ivec3(0))) && all(lessThan(l, ivec3(BRICK_SIZE))) &&
                   all(lessThan(origin + l, volumeDims));
        tile[a] = own ? phiPool[slot * BRICK_VOXELS +
                                uint(l.x + BRICK_SIZE * (l.y + BRICK_SIZE * l.z))]
                      : phiAt(origin + l);
    }
}

// phi at local voxel l (-1 .. BRICK_SIZE on each axis).
float tileAt(ivec3 l) { return tile[(l.x + 1) + APRON * ((l.y + 1) + APRON * (l.z + 1))]; }

// The centre and its face neighbours (enough for the band and front tests); edges left at 0.
PhiStencil tileFaces(ivec3 l) {
    PhiStencil s = PhiStencil(tileAt(l), tileAt(l + ivec3(-1, 0, 0)), tileAt(l + ivec3(1, 0, 0)),
                              tileAt(l + ivec3(0, -1, 0)), tileAt(l + ivec3(0, 1, 0)),
                              tileAt(l + ivec3(0, 0, -1)), tileAt(l + ivec3(0, 0, 1)), 0.0, 0.0,
                              0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    return s;
}
