#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora: a few tiny valid and near-valid files per format.

Run from anywhere: python3 tests/fuzz/make_corpus.py. Deterministic, so the committed files only
change when this script does.
"""
import gzip
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def out(fmt, name, data):
    d = os.path.join(HERE, "corpus", fmt)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def gz(data):
    return gzip.compress(data, mtime=0)


VOX = bytes(range(8))  # 2x2x2 uint8


def nifti1(dtype=2, bitpix=8, dims=(2, 2, 2), data=VOX, endian="<", sform=1, qform=1,
           slope=0.0, inter=0.0, vox_offset=352.0, magic=b"n+1\0", ndim=3, extra_dims=(1, 1, 1, 1)):
    h = bytearray(348)
    e = endian
    struct.pack_into(e + "i", h, 0, 348)
    struct.pack_into(e + "8h", h, 40, ndim, *dims, *extra_dims)
    struct.pack_into(e + "hh", h, 70, dtype, bitpix)
    struct.pack_into(e + "8f", h, 76, 1.0, 0.9, 1.1, 2.5, 1, 1, 1, 1)
    struct.pack_into(e + "3f", h, 108, vox_offset, slope, inter)
    struct.pack_into(e + "hh", h, 252, qform, sform)
    struct.pack_into(e + "6f", h, 256, 0.1, 0.2, 0.3, -10.0, 20.0, 5.0)
    struct.pack_into(e + "12f", h, 280, -0.9, 0, 0, 10, 0, 1.1, 0, -20, 0, 0, 2.5, 5)
    h[344:348] = magic
    return bytes(h) + b"\0" * 4 + data


def nifti2(dtype=16, bitpix=32, dims=(2, 2, 1), data=struct.pack("<4f", 0, 1.5, -2, 3)):
    h = bytearray(540)
    struct.pack_into("<i", h, 0, 540)
    h[4:12] = b"n+2\0\r\n\x1a\n"
    struct.pack_into("<hh", h, 12, dtype, bitpix)
    struct.pack_into("<8q", h, 16, 3, *dims, 1, 1, 1, 1)
    struct.pack_into("<8d", h, 104, 1, 1, 1, 1, 1, 1, 1, 1)
    struct.pack_into("<q", h, 168, 544)
    struct.pack_into("<2i", h, 344, 0, 2)
    struct.pack_into("<12d", h, 400, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0)
    return bytes(h) + b"\0" * 4 + data


def nifti():
    out("nifti", "uint8.nii", nifti1())
    out("nifti", "uint8.nii.gz", gz(nifti1()))
    out("nifti", "int16_big.nii", nifti1(4, 16, data=struct.pack(">8h", *range(-4, 4)), endian=">"))
    out("nifti", "qform_only_slope.nii", nifti1(sform=0, slope=2.0))
    out("nifti", "float64.nii", nifti1(64, 64, dims=(2, 1, 1), data=struct.pack("<2d", 1.5, -2.5)))
    out("nifti", "4d.nii", nifti1(ndim=4, extra_dims=(2, 1, 1, 1), data=VOX * 2))
    out("nifti", "nifti2_float.nii", nifti2())
    out("nifti", "truncated.nii", nifti1()[:352 + 3])
    out("nifti", "pair_header.nii", nifti1(magic=b"ni1\0"))
    # Hostile rescales: not finite, or past float32 (stored 7 * 1e38).
    out("nifti", "scl_slope_nan.nii", nifti1(slope=float("nan")))
    out("nifti", "scl_inter_inf.nii", nifti1(slope=1.0, inter=float("inf")))
    out("nifti", "scl_slope_overflow.nii", nifti1(slope=1e38))
    # Decompression bomb: 4 Mi voxels declared, a few dozen bytes of gzip behind them.
    out("nifti", "bomb_claim.nii.gz", gz(nifti1(dims=(256, 256, 63))))


def nrrd():
    base = ("NRRD0004\n# seed\ntype: {t}\ndimension: 3\nspace: {s}\nsizes: 2 2 2\n"
            "space directions: (1,0,0) (0,1.5,0) (0,0,2)\nspace origin: (-1,2,3)\n")
    out("nrrd", "raw.nrrd", (base.format(t="uchar", s="left-posterior-superior")
                             + "encoding: raw\n\n").encode() + VOX)
    out("nrrd", "gzip_short.nrrd", (base.format(t="short", s="right-anterior-superior")
                                    + "endian: big\nencoding: gzip\n\n").encode()
        + gz(struct.pack(">8h", *range(8))))
    out("nrrd", "ascii_float.nrrd", base.format(t="float", s="LAS")
        + "encoding: ascii\n\n0 1.5 2 3\n4 5 6 -7\n")
    out("nrrd", "2d_spacings.nrrd", b"NRRD0001\ntype: uint16\ndimension: 2\nsizes: 2 2\n"
        b"spacings: 0.5 nan\nendian: little\nencoding: raw\nbyte skip: 2\n\nXX" + struct.pack("<4H", 1, 2, 3, 4))
    out("nrrd", "detached.nhdr", base.format(t="uint8", s="LPS")
        + "encoding: raw\ndata file: missing.raw\nline skip: 1\n")
    out("nrrd", "no_sizes.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nencoding: raw\n\n")
    # Decompression bomb and an ascii claim: far more voxels declared than the data can hold.
    out("nrrd", "gzip_bomb_claim.nrrd", b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 256 256 63\n"
        b"encoding: gzip\n\n" + gz(VOX))
    out("nrrd", "ascii_claim.nrrd", "NRRD0004\ntype: float\ndimension: 3\nsizes: 256 256 63\n"
        "encoding: ascii\n\n1 2 3 4\n")


def metaimage():
    head = ("ObjectType = Image\nNDims = 3\nBinaryData = True\nTransformMatrix = 0 1 0 -1 0 0 0 0 1\n"
            "Offset = 1 2 3\nElementSpacing = 0.5 0.5 2\nDimSize = 2 2 2\n")
    out("metaimage", "raw.mha", (head + "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n").encode() + VOX)
    data = struct.pack("<8f", *[float(v) for v in range(8)])
    out("metaimage", "zlib_float.mha", (head + "ElementType = MET_FLOAT\nCompressedData = True\n"
                                        "ElementDataFile = LOCAL\n").encode() + zlib.compress(data))
    out("metaimage", "big_short.mha", (head + "ElementType = MET_SHORT\nBinaryDataByteOrderMSB = True\n"
                                       "ElementDataFile = LOCAL\n").encode() + struct.pack(">8h", *range(8)))
    out("metaimage", "ascii_2d.mha", "NDims = 2\nDimSize = 2 2\nElementType = MET_DOUBLE\nBinaryData = False\n"
        "ElementDataFile = LOCAL\n1 2 3 4\n")
    out("metaimage", "zlib_bomb_claim.mha", "NDims = 3\nDimSize = 256 256 63\nElementType = MET_UCHAR\n"
        "CompressedData = True\nElementDataFile = LOCAL\n".encode() + zlib.compress(VOX))
    out("metaimage", "detached.mhd", head + "ElementType = MET_UCHAR\nHeaderSize = -1\nElementDataFile = d.raw\n")


def mgh(mtype=0, dims=(2, 2, 2), data=VOX, good=1):
    h = bytearray(284)
    struct.pack_into(">7i", h, 0, 1, *dims, 1, mtype, 0)
    struct.pack_into(">h", h, 28, good)
    struct.pack_into(">3f", h, 30, 1.0, 1.5, 2.0)
    struct.pack_into(">9f", h, 42, -1, 0, 0, 0, 0, -1, 0, 1, 0)
    struct.pack_into(">3f", h, 78, 5.0, -3.0, 12.0)
    return bytes(h) + data


def mgz():
    out("mgz", "uchar.mgh", mgh())
    out("mgz", "float.mgz", gz(mgh(3, data=struct.pack(">8f", *[v / 2 for v in range(8)]))))
    out("mgz", "short_noras.mgz", gz(mgh(4, data=struct.pack(">8h", *range(8)), good=0)))
    out("mgz", "int_truncated.mgz", gz(mgh(1, data=struct.pack(">4i", 1, 2, 3, 4))))
    out("mgz", "bomb_claim.mgz", gz(mgh(dims=(256, 256, 63))))
    out("mgz", "frames.mgh", mgh()[:16] + struct.pack(">i", 3) + mgh()[20:] + VOX * 2)


def config():
    # The shipped defaults (every key, presets, both binding forms) and near-valid variants.
    with open(os.path.join(HERE, "..", "..", "config", "steerseg.toml"), encoding="utf-8") as f:
        out("config", "shipped.toml", f.read())
    out("config", "layer.toml", 'display.rotation = 90\n[frame]\nmin_iterations = 8\n'
        '[bindings.keys]\n"ctrl+shift+z" = { action = "redo", steps = 2 }\nz = "none"\n'
        '[[preset]]\nname = "CT bone"\nT = 1000\n')
    out("config", "bad_values.toml", '[display]\nrotation = 45\nwidth = "wide"\nmode = "1920x@"\n'
        '[export]\nformats = ["nrrd", "nrrd", 3]\n[ui]\ntouch_target_mm = nan\n')
    out("config", "syntax.toml", '[display\nrotation = = 1\n"a\\nb" = 1\n')
    out("config", "not_utf8.toml", b'[audit]\npath = "caf\xe9"\n')


def script():
    # The example sessions, and a few lines of every kind of step and of error.
    scenarios = os.path.join(HERE, "..", "scenarios")
    for name in sorted(os.listdir(scenarios)):
        if name.endswith(".session"):
            with open(os.path.join(scenarios, name), "rb") as f:
                out("script", name, f.read())
    out("script", "device.session",
        "at 0.5 touch down 0 640 400\nafter 0.05 touch move 0 650 410\ntouch up 0 650 410\n"
        "tap 10 20\nkey ctrl+shift+z\nkey_down space\nkey_up space\nwheel 1 2 -3\n")
    out("script", "actions.session",
        "load \"$DATA/a b.nii\"\nprobe 1 2 3 4\npreset \"CT bone\"\nset eps 3\nnudge selected 2\n"
        "select alpha\ncycle -1\nseed 1 2 3\nerase 1 2 3 2\nerase_mode on\nwindow 40 400\n"
        "run\nwait iterations 5 timeout 9\npause\nrotate 1 2\nzoom 2\npage axial -1\n"
        "slice coronal 3\nshow sagittal axial\nundo\nredo\nrestart\nproceed\nback\nfinish\n"
        "resume\ndismiss\nexport\nexport $OUT/m.nii.gz\nframe ${OUT}/f.png\nautosave resume\n"
        "autosave discard\nquit\n")
    out("script", "checks.session",
        "wait loaded\nwait converged timeout 3\nwait state review\nwait seconds 2\n"
        "expect state done\nexpect volume_ml >= 1.5\nexpect converged\n"
        "expect message contains \"a # b\"\nexpect exported contains x\n"
        "dice $EXPORTED $DATA/r.nii.gz label 3 >= 0.8\n")
    out("script", "errors.session",
        "jump\nat -1 run\nat 5 run\nat 4 run\nseed 1 2 nan\nset eps 1e400\nload \"open\n"
        "key hyper\nload $HOME\nexpect x ~ 1\nat 2\n")


def snapshot(runs, voxels, dims, state="evolving", version=1):
    """An autosave (app/kiosk/autosave_snapshot.cpp): header, JSON metadata, uint32 runs."""
    meta = ('{"dims":[%d,%d,%d],"erasures":1,"evolved_time":2.5,"iterations":40,'
            '"params":{"T":200.0,"alpha":0.7,"eps":60.0,"preset":"","radius":3.0},'
            '"saved_at":"2026-11-23T13:01:40.000Z","saved_at_ms":1795438900000,'
            '"scan":{"bytes":885,"mtime_ns":1,"path":"/s.nrrd"},"seeds":1,"sequence":3,'
            '"state":"%s"}' % (dims + (state,))).encode()
    payload = meta + struct.pack("<%dI" % len(runs), *runs)
    return (b"STEERSAV" + struct.pack("<IIQQI", version, len(meta), len(runs), voxels,
                                      zlib.crc32(payload)) + payload)


def autosave():
    out("autosave", "ball.ssav", snapshot([10, 4, 10], 24, (2, 3, 4)))
    out("autosave", "empty.ssav", snapshot([], 0, (2, 3, 4), state="inspect"))
    out("autosave", "version2.ssav", snapshot([24], 24, (2, 3, 4), version=2))
    good = snapshot([3, 5, 16], 24, (4, 3, 2), state="review")
    out("autosave", "truncated.ssav", good[:-3])
    out("autosave", "badcrc.ssav", good[:40] + b"X" + good[41:])


if __name__ == "__main__":
    nifti()
    nrrd()
    metaimage()
    mgz()
    config()
    script()
    autosave()
