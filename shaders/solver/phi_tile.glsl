// A brick's phi plus a one-voxel apron in shared memory, so that each voxel's 3x3x3 stencil
// costs no page-table look-ups (include after common/brick_pool.glsl).
const int APRON = BRICK_SIZE + 2;
shared float tile[APRON * APRON * APRON];

// Fills the tile of the brick starting at voxel `origin`; call barrier() before reading.
void loadTile(ivec3 origin) {
    for (uint a = gl_LocalInvocationIndex; a < uint(APRON * APRON * APRON); a += uint(LOCAL_SIZE)) {
        int i = int(a);
        ivec3 l = ivec3(i % APRON, (i / APRON) % APRON, i / (APRON * APRON)) - 1;
        tile[a] = phiAt(origin + l);
    }
}

// phi at local voxel l (-1 .. BRICK_SIZE on each axis).
float tileAt(ivec3 l) { return tile[(l.x + 1) + APRON * ((l.y + 1) + APRON * (l.z + 1))]; }

bool tileInNarrowBand(ivec3 l) {
    return inNarrowBand(tileAt(l), tileAt(l + ivec3(-1, 0, 0)), tileAt(l + ivec3(1, 0, 0)),
                        tileAt(l + ivec3(0, -1, 0)), tileAt(l + ivec3(0, 1, 0)),
                        tileAt(l + ivec3(0, 0, -1)), tileAt(l + ivec3(0, 0, 1)));
}

bool tileOnFront(ivec3 l) {
    return onFront(tileAt(l), tileAt(l + ivec3(-1, 0, 0)), tileAt(l + ivec3(1, 0, 0)),
                   tileAt(l + ivec3(0, -1, 0)), tileAt(l + ivec3(0, 1, 0)),
                   tileAt(l + ivec3(0, 0, -1)), tileAt(l + ivec3(0, 0, 1)));
}
