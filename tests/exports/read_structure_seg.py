#!/usr/bin/python3
"""Reads a DICOM SEG of several segments back with pydicom alone, for io_structure_export_test.

usage: read_structure_seg.py SEG_FILE SOURCE_FOLDER

Prints, tab-separated, one line per segment and one per segment's voxels:
  segment N LABEL CATEGORY_CODE TYPE_CODE ALGORITHM_TYPE ALGORITHM_NAME L a b
  frames N COUNT
  voxels N COUNT v1 v2 ...
where v = k * rows * columns + row * columns + column and k is the rank of the frame's source
instance along the slice normal among the source folder's instances. Exits 1 with one line on
stderr when a frame names no segment, a segment that is not listed, a source instance that is not
in the folder, lies elsewhere than its source, or repeats a (segment, slice).
"""
import os
import sys

import pydicom


def fail(msg):
    print("read_structure_seg: " + msg, file=sys.stderr)
    sys.exit(1)


def main():
    if len(sys.argv) != 3:
        fail("usage: read_structure_seg.py SEG_FILE SOURCE_FOLDER")
    seg = pydicom.dcmread(sys.argv[1])
    if seg.SegmentationType != "BINARY" or seg.BitsAllocated != 1:
        fail("not a binary segmentation")

    sources = {}
    for name in sorted(os.listdir(sys.argv[2])):
        ds = pydicom.dcmread(os.path.join(sys.argv[2], name), stop_before_pixels=True)
        sources[ds.SOPInstanceUID] = ds
    iop = [float(v) for v in next(iter(sources.values())).ImageOrientationPatient]
    normal = [iop[1] * iop[5] - iop[2] * iop[4], iop[2] * iop[3] - iop[0] * iop[5],
              iop[0] * iop[4] - iop[1] * iop[3]]

    def along(ds):
        return sum(float(p) * n for p, n in zip(ds.ImagePositionPatient, normal))

    rank = {uid: k for k, uid in enumerate(sorted(sources, key=lambda u: along(sources[u])))}

    numbers = []
    for item in seg.SegmentSequence:
        n = int(item.SegmentNumber)
        numbers.append(n)
        lab = item.get("RecommendedDisplayCIELabValue") or ["-", "-", "-"]
        print("\t".join(str(v) for v in [
            "segment", n, item.SegmentLabel,
            item.SegmentedPropertyCategoryCodeSequence[0].CodeValue,
            item.SegmentedPropertyTypeCodeSequence[0].CodeValue,
            item.SegmentAlgorithmType, item.get("SegmentAlgorithmName", "-")] + list(lab)))
    if numbers != list(range(1, len(numbers) + 1)):
        fail("segment numbers %s are not 1..N" % numbers)

    rows, cols, frames = seg.Rows, seg.Columns, int(seg.NumberOfFrames)
    raw = bytes(seg.PixelData)
    bits = format(int.from_bytes(raw, "little"), "b")[::-1].ljust(len(raw) * 8, "0")
    plane = rows * cols
    if len(bits) < plane * frames:
        fail("pixel data holds %d bits, %d frames need %d" % (len(bits), frames, plane * frames))
    voxels = {n: [] for n in numbers}
    frame_count = {n: 0 for n in numbers}
    seen = set()
    for f, groups in enumerate(seg.PerFrameFunctionalGroupsSequence):
        n = int(groups.SegmentIdentificationSequence[0].ReferencedSegmentNumber)
        if n not in voxels:
            fail("frame %d names segment %d" % (f + 1, n))
        index = [int(v) for v in groups.FrameContentSequence[0].DimensionIndexValues]
        if index[0] != n:
            fail("frame %d: dimension index %s, segment %d" % (f + 1, index, n))
        uid = groups.DerivationImageSequence[0].SourceImageSequence[0].ReferencedSOPInstanceUID
        if uid not in sources:
            fail("frame %d derives from %s, not in the folder" % (f + 1, uid))
        position = [float(v) for v in groups.PlanePositionSequence[0].ImagePositionPatient]
        expected = [float(v) for v in sources[uid].ImagePositionPatient]
        if max(abs(a - b) for a, b in zip(position, expected)) > 0.01:
            fail("frame %d lies at %s, its source at %s" % (f + 1, position, expected))
        k = rank[uid]
        if (n, k) in seen:
            fail("segment %d has two frames on slice %d" % (n, k))
        seen.add((n, k))
        frame_count[n] += 1
        frame_bits = bits[f * plane:(f + 1) * plane]
        voxels[n] += [k * plane + i for i, b in enumerate(frame_bits) if b == "1"]
    for n in numbers:
        print("\t".join(["frames", str(n), str(frame_count[n])]))
        v = sorted(voxels[n])
        print("\t".join(["voxels", str(n), str(len(v))] + [str(i) for i in v]))


if __name__ == "__main__":
    main()
