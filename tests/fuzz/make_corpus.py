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
        "autosave discard\nspeed classify\noutside 1 2 3 4\noutside 1 2 3\noutside_mode on\n"
        "clear_examples\nspeed edge\nquit\n")
    out("script", "checks.session",
        "wait loaded\nwait converged timeout 3\nwait state review\nwait seconds 2\n"
        "expect state done\nexpect volume_ml >= 1.5\nexpect converged\n"
        "expect message contains \"a # b\"\nexpect exported contains x\n"
        "wait speed classify timeout 4\nexpect speed edge\nexpect outside_examples == 1\n"
        "dice $EXPORTED $DATA/r.nii.gz label 3 >= 0.8\n")
    out("script", "errors.session",
        "jump\nat -1 run\nat 5 run\nat 4 run\nseed 1 2 nan\nset eps 1e400\nload \"open\n"
        "key hyper\nload $HOME\nexpect x ~ 1\nat 2\n")


SURFACE_DIAL = bytes.fromhex(
    "05 01 09 0E A1 01 85 01 05 0D 09 21 A1 02 15 00 25 01 75 01 95 01 A1 00 05 09 09 01 81 02"
    " 05 0D 09 33 81 02 95 06 81 03 A1 02 05 01 09 37 16 01 80 26 FF 7F 75 10 95 01 81 06 35 00"
    " 46 10 0E 15 00 26 10 0E 09 48 B1 02 45 00 C0 55 0E 65 11 46 00 00 26 00 00 09 30 81 42 09"
    " 31 46 00 00 26 00 00 81 42 05 0D 09 48 15 3A 25 3A 75 08 55 0F 35 3A 45 3A 81 03 55 00 65"
    " 00 35 00 45 00 05 0E 09 01 A1 02 15 00 26 FF 00 09 24 B1 42 09 24 91 42 15 01 25 07 09 20"
    " B1 42 09 21 91 42 25 0A 09 28 B1 42 75 10 26 D0 07 09 25 B1 42 09 25 91 42 85 02 75 20 17"
    " 37 00 01 00 27 37 00 01 00 09 22 B1 02 09 11 A1 02 05 0A 95 03 09 03 09 04 09 05 75 08 15"
    " 00 25 FF B1 02 C0 05 0E 09 10 A1 02 05 0A 95 01 15 03 25 03 36 03 10 46 03 10 09 03 B1 02"
    " 15 04 25 04 36 04 10 46 04 10 09 04 B1 02 15 05 25 05 36 04 10 46 04 10 09 05 B1 02 35 00"
    " 45 00 C0 C0 C0 C0 C0")
HANDMADE_RADIAL = bytes.fromhex(
    "05 01 09 0E A1 01 85 03 05 09 19 01 29 03 15 00 25 01 75 01 95 03 81 02 A4 05 01 09 37 15"
    " F0 25 0F 75 05 95 01 81 06 B4 75 05 95 01 81 03 85 04 05 01 09 38 16 00 F8 26 FF 07 75 0C"
    " 95 01 81 06 75 04 81 03 C0")


def hid_input(radial, descriptor, reports):
    """fuzz_hid's input: decoder choice, descriptor length (LE16), descriptor, then reports
    each after its length byte (None: an unplug)."""
    data = bytes([1 if radial else 0]) + struct.pack("<H", len(descriptor)) + descriptor
    for r in reports:
        data += b"\xff" if r is None else bytes([len(r)]) + r
    return data


def hid():
    shuttle = [bytes([0, j, 0, b & 255, b >> 8]) for j, b in
               ((253, 0), (254, 0), (255, 0x10), (0, 0x10), (1, 0), (0, 0x4001))]
    shuttle += [bytes([3, 0, 0, 0, 0]), bytes([0xF9, 0, 0, 0, 0]), bytes([0, 0, 0, 0, 0])]
    out("hid", "shuttle.bin", hid_input(False, b"", shuttle + [None, bytes([0, 7, 0, 0, 0])]))
    out("hid", "shuttle_garbage.bin",
        hid_input(False, b"", [b"\x01\x02", bytes(6), bytes([0x40, 0, 0, 0, 0]),
                               bytes([0, 0, 0, 0, 0x80])]))
    dial = [bytes([1, b, v & 255, (v >> 8) & 255, 0, 0, 0, 0, 0])
            for b, v in ((0, 3), (1, 0), (1, 0xFFFE), (0, 0))]
    out("hid", "surface_dial.bin", hid_input(True, SURFACE_DIAL, dial + [None, bytes(3)]))
    out("hid", "handmade_radial.bin",
        hid_input(True, HANDMADE_RADIAL, [b"\x03\xf9\x00", b"\x04\x00\x08", b"\x03\x10\x00",
                                          b"\x05\x00\x00"]))
    out("hid", "wheel_only.bin",
        hid_input(True, bytes.fromhex("05 01 09 0E A1 01 09 38 15 81 25 7F 75 08 95 01 81 06 C0"),
                  [b"\xfe", b"\x02"]))


def evdev():
    # (type index: 0 SYN, 1 KEY, 2 REL, 3 MSC; code: 0x80 = BTN_0; value as int8; ms since last)
    def ev(*events):
        return b"".join(bytes([t, c, v & 255, dt]) for t, c, v, dt in events)
    out("evdev", "turns_and_press.bin",
        ev((2, 7, 1, 0), (2, 7, 2, 0), (0, 0, 0, 0), (1, 0x80, 1, 100), (0, 0, 0, 0),
           (2, 7, -1, 50), (0, 0, 0, 0), (1, 0x80, 2, 30), (1, 0x80, 0, 200), (0, 0, 0, 0)))
    out("evdev", "dropped.bin",
        ev((2, 7, 5, 0), (0, 3, 0, 0), (1, 0x80, 1, 0), (0, 0, 0, 1), (2, 7, 1, 10),
           (0, 0, 0, 0), (3, 1, 127, 5)))
    out("evdev", "bounce_unplug.bin",
        ev((1, 0x80, 1, 0), (1, 0x80, 0, 2), (1, 0x80, 1, 2), (1, 0x80, 0, 2), (0, 0, 0, 30),
           (1, 0x80, 1, 200), (0, 0, 0, 0)) + bytes([0xFF, 0, 0, 10]))


def recording():
    data = os.path.join(HERE, "..", "data", "input")
    for name in sorted(os.listdir(data)):
        if name.endswith(".rec"):
            with open(os.path.join(data, name), "rb") as f:
                out("recording", name, f.read())
    out("recording", "every_kind.rec",
        "# steerseg input recording 1\n0.000000 dial hid-descriptor " + SURFACE_DIAL.hex() +
        "\n0.010000 dial hid 010003000000000000\n0.020000 powermate evdev 2 7 -1\n"
        "0.030000 pedal gpio 1\n0.040000 pedal unplug\n0.050000 pedal plug\n")

def snapshot(runs, voxels, dims, state="evolving", version=1):
    """An autosave (app/autosave/autosave_snapshot.cpp): header, JSON metadata, uint32 runs."""
    meta = ('{"barriers":[{"keep":true,"sphere":[1.0,1.0,1.0,1.0],'
            '"tissue":{"level":150.0,"reach":3.0}},{"keep":false,"sphere":[1.0,2.0,1.0,0.5]}],'
            '"dims":[%d,%d,%d],"erasures":1,"evolved_time":2.5,"iterations":40,'
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
    hid()
    evdev()
    recording()
    autosave()
