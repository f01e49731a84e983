// A brick's phi plus a one-voxel apron in shared memory, so that each voxel's 3x3x3 stencil
// costs no page-table look-ups (include after common/brick_pool.glsl and solver/phi_stencil.glsl).
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

// The centre and its face neighbours (enough for the band and front tests); edges left at 0.
PhiStencil tileFaces(ivec3 l) {
    PhiStencil s = PhiStencil(tileAt(l), tileAt(l + ivec3(-1, 0, 0)), tileAt(l + ivec3(1, 0, 0)),
                              tileAt(l + ivec3(0, -1, 0)), tileAt(l + ivec3(0, 1, 0)),
                              tileAt(l + ivec3(0, 0, -1)), tileAt(l + ivec3(0, 0, 1)), 0.0, 0.0,
                              0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    return s;
}

// The whole stencil of one step (faces and the 12 edge neighbours).
PhiStencil tileStencil(ivec3 l) {
    PhiStencil s = tileFaces(l);
    s.xpyp = tileAt(l + ivec3(1, 1, 0));
    s.xpym = tileAt(l + ivec3(1, -1, 0));
    s.xmyp = tileAt(l + ivec3(-1, 1, 0));
    s.xmym = tileAt(l + ivec3(-1, -1, 0));
    s.xpzp = tileAt(l + ivec3(1, 0, 1));
    s.xpzm = tileAt(l + ivec3(1, 0, -1));
    s.xmzp = tileAt(l + ivec3(-1, 0, 1));
    s.xmzm = tileAt(l + ivec3(-1, 0, -1));
    s.ypzp = tileAt(l + ivec3(0, 1, 1));
    s.ypzm = tileAt(l + ivec3(0, 1, -1));
    s.ymzp = tileAt(l + ivec3(0, -1, 1));
    s.ymzm = tileAt(l + ivec3(0, -1, -1));
    return s;
}
