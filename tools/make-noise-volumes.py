#!/usr/bin/env python3
"""Writes three 64^3 float NRRD volumes for comparing level-set discretisations (ITK against
steerseg, docs/benchmarks-itk.md): uniform.nrrd (all 0), white.nrrd (Gaussian noise, std 10,
independent per voxel) and smooth.nrrd (the same noise box-blurred three times along each axis
and rescaled to std 10: correlated over a few voxels). Deterministic (fixed seed).
usage: tools/make-noise-volumes.py OUTPUT_DIR"""
import os
import random
import struct
import sys

N = 64


def write(path, values):
    header = (
        "NRRD0004\ntype: float\ndimension: 3\nspace: left-posterior-superior\n"
        f"sizes: {N} {N} {N}\nspace directions: (1,0,0) (0,1,0) (0,0,1)\n"
        "space origin: (0,0,0)\nendian: little\nencoding: raw\n\n"
    )
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(struct.pack(f"<{len(values)}f", *values))


def blur(values, axis):
    stride = (1, N, N * N)[axis]
    out = [0.0] * len(values)
    for i in range(len(values)):
        c = (i // stride) % N
        lo = i - stride if c > 0 else i + (N - 1) * stride  # periodic
        hi = i + stride if c < N - 1 else i - (N - 1) * stride
        out[i] = (values[lo] + values[i] + values[hi]) / 3.0
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    rng = random.Random(1)
    white = [rng.gauss(0.0, 10.0) for _ in range(N * N * N)]
    write(os.path.join(out, "uniform.nrrd"), [0.0] * (N * N * N))
    write(os.path.join(out, "white.nrrd"), white)
    smooth = white
    for _ in range(3):
        for axis in range(3):
            smooth = blur(smooth, axis)
    mean = sum(smooth) / len(smooth)
    std = (sum((v - mean) ** 2 for v in smooth) / len(smooth)) ** 0.5
    write(os.path.join(out, "smooth.nrrd"), [(v - mean) / std * 10.0 for v in smooth])


if __name__ == "__main__":
    main()
