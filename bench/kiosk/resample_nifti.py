#!/usr/bin/python3
"""Resample a NIfTI-1 scan to another grid size (trilinear), for the kiosk's benchmark on a
512x512x120-class scan when ../shared/data holds none: the real scan's content, that grid's
voxel count and spacing (tools/bench-kiosk.sh --large). Writes float32 NIfTI-1 (gzip); keeps
the qform's orientation and origin, scales the spacing so the scan covers the same millimetres.

    resample_nifti.py IN.nii[.gz] OUT.nii.gz NX NY NZ [--label]

--label: IN is a mask; the interpolated value is cut at 0.5 (1 inside, 0 outside), so a scan
and its label resampled alike stay on one grid (the steering benchmark's finer-resampled cases:
docs/steering-log.md, "512x512x120").

Needs numpy (Debian's python3-numpy); reads float32, int16, uint16, uint8 and int32 data and
applies scl_slope and scl_inter.
"""
import gzip
import struct
import sys

import numpy as np

DTYPES = {2: np.uint8, 4: np.int16, 8: np.int32, 16: np.float32, 512: np.uint16}


def fail(message):
    sys.exit(f"resample_nifti: {message}")


def read(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rb") as f:
        data = f.read()
    if len(data) < 352:
        fail(f"{path}: shorter than a NIfTI-1 header")
    header = bytearray(data[:348])
    endian = "<" if struct.unpack("<i", header[0:4])[0] == 348 else ">"
    if struct.unpack(endian + "i", header[0:4])[0] != 348 or header[344:347] not in (b"n+1", b"ni1"):
        fail(f"{path}: not a single-file NIfTI-1 scan")
    dim = struct.unpack(endian + "8h", header[40:56])
    datatype = struct.unpack(endian + "h", header[70:72])[0]
    vox_offset = int(struct.unpack(endian + "f", header[108:112])[0])
    slope, inter = struct.unpack(endian + "2f", header[112:120])
    if dim[0] < 3 or any(d < 1 for d in dim[1:4]) or datatype not in DTYPES:
        fail(f"{path}: a 3D scan of float32, int16, uint16, uint8 or int32 voxels is needed")
    nx, ny, nz = dim[1:4]
    count = nx * ny * nz
    dtype = np.dtype(DTYPES[datatype]).newbyteorder(endian)
    if len(data) < vox_offset + count * dtype.itemsize:
        fail(f"{path}: truncated: {nx}x{ny}x{nz} voxels do not fit")
    voxels = np.frombuffer(data, dtype=dtype, count=count, offset=vox_offset).astype(np.float32)
    if slope not in (0.0, 1.0) or inter != 0.0:
        voxels = voxels * (slope or 1.0) + inter
    # NIfTI stores x fastest: as an array [z][y][x].
    return header, endian, voxels.reshape(nz, ny, nx)


def resample_axis(a, axis, n):
    """Linear interpolation along one axis to n samples, the end voxels' centres kept."""
    m = a.shape[axis]
    pos = np.linspace(0.0, m - 1.0, n) if n > 1 else np.zeros(1)
    lo = np.clip(np.floor(pos).astype(np.int64), 0, m - 1)
    hi = np.minimum(lo + 1, m - 1)
    w = (pos - lo).astype(np.float32)
    shape = [1] * a.ndim
    shape[axis] = n
    w = w.reshape(shape)
    return np.take(a, lo, axis=axis) * (1.0 - w) + np.take(a, hi, axis=axis) * w


def main():
    args = sys.argv[1:]
    label = "--label" in args
    if label:
        args.remove("--label")
    if len(args) != 5:
        fail("usage: resample_nifti.py IN.nii[.gz] OUT.nii.gz NX NY NZ [--label]")
    src, dst = args[0], args[1]
    try:
        size = [int(v) for v in args[2:5]]
    except ValueError:
        fail("NX NY NZ must be whole numbers")
    if any(not 1 <= v <= 4096 for v in size):
        fail("each of NX NY NZ must be 1 to 4096")
    header, endian, vol = read(src)
    nz, ny, nx = vol.shape
    out = resample_axis(vol, 2, size[0])
    out = resample_axis(out, 1, size[1])
    out = resample_axis(out, 0, size[2]).astype(np.float32)
    if label:
        out = (out >= 0.5).astype(np.float32)
    pixdim = list(struct.unpack(endian + "8f", header[76:108]))
    for axis, (old, new) in enumerate(zip((nx, ny, nz), size)):
        # The same extent between the end voxels' centres.
        pixdim[axis + 1] = pixdim[axis + 1] * (old - 1) / (new - 1) if new > 1 else pixdim[axis + 1]
    dim = list(struct.unpack(endian + "8h", header[40:56]))
    dim[0], dim[1:4], dim[4:8] = 3, size, [1, 1, 1, 1]
    header[40:56] = struct.pack(endian + "8h", *dim)
    header[70:74] = struct.pack(endian + "2h", 16, 32)
    header[76:108] = struct.pack(endian + "8f", *pixdim)
    header[108:120] = struct.pack(endian + "3f", 352.0, 1.0, 0.0)
    # The sform's rows hold the old spacing: leave only the qform, which takes the new pixdim.
    header[254:256] = struct.pack(endian + "h", 0)
    header[344:348] = b"n+1\0"
    with gzip.open(dst, "wb", compresslevel=1) as f:
        f.write(bytes(header) + b"\0\0\0\0" + out.astype(np.dtype(np.float32).newbyteorder(endian)).tobytes())
    print(f"resample_nifti: {src} {nx}x{ny}x{nz} -> {dst} {size[0]}x{size[1]}x{size[2]}, "
          f"spacing {pixdim[1]:.3f} x {pixdim[2]:.3f} x {pixdim[3]:.3f} mm")


if __name__ == "__main__":
    main()
