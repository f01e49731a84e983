#!/usr/bin/python3
"""Reads a DICOM SEG back independently of steerseg and DCMTK (pydicom only), for the tests.

usage: read_dicom_seg.py SEG_FILE SOURCE_FOLDER

For every frame: finds the source instance (and frame, in a multi-frame source) by the Source
Image Sequence's Referenced SOP Instance UID (and Frame Number), checks that the frame's Image
Position Patient equals that instance's or frame's (within
0.01 mm), that the referenced instance belongs to the series the SEG references, that
patient, study, frame of reference, orientation and pixel spacing match the source, unpacks
the frame's 1-bit pixels and prints one line per source slice:
    slice SOP_INSTANCE_UID[:FRAME] COUNT v1 v2 ...
where v are the segmented pixel indices (row * columns + column) in the source image. Exits
non-zero with one line on stderr on any mismatch.
"""
import os
import sys

import pydicom


def fail(msg):
    print("read_dicom_seg: " + msg, file=sys.stderr)
    sys.exit(1)


def main():
    if len(sys.argv) != 3:
        fail("usage: read_dicom_seg.py SEG_FILE SOURCE_FOLDER")
    seg = pydicom.dcmread(sys.argv[1])
    if seg.SOPClassUID != "1.2.840.10008.5.1.4.1.1.66.4":
        fail("not a Segmentation Storage object: " + seg.SOPClassUID)
    if seg.SegmentationType != "BINARY" or seg.BitsAllocated != 1:
        fail("not a binary segmentation")

    sources = {}
    for name in sorted(os.listdir(sys.argv[2])):
        path = os.path.join(sys.argv[2], name)
        if not os.path.isfile(path):
            continue
        try:
            ds = pydicom.dcmread(path, stop_before_pixels=True)
        except Exception:  # not DICOM: skipped, as steerseg's reader does
            continue
        # A file with an empty SOPInstanceUID is known by its meta header's instance UID.
        instance = ds.get("SOPInstanceUID") or ds.file_meta.get("MediaStorageSOPInstanceUID")
        if instance:
            sources[instance] = ds

    referenced = set()
    for series in seg.ReferencedSeriesSequence:
        for inst in series.ReferencedInstanceSequence:
            if inst.ReferencedSOPInstanceUID not in sources:
                fail("referenced instance %s is not in the source folder" %
                     inst.ReferencedSOPInstanceUID)
            src = sources[inst.ReferencedSOPInstanceUID]
            if src.SeriesInstanceUID != series.SeriesInstanceUID:
                fail("instance %s referenced under the wrong series" %
                     inst.ReferencedSOPInstanceUID)
            # A file with an empty SOPClassUID is known by its meta header's class.
            src_class = src.get("SOPClassUID") or src.file_meta.MediaStorageSOPClassUID
            if inst.ReferencedSOPClassUID != src_class:
                fail("instance %s referenced with the wrong SOP class" %
                     inst.ReferencedSOPInstanceUID)
            referenced.add(inst.ReferencedSOPInstanceUID)

    first = next(iter(sources.values()))

    def plane_attribute(src, frame, sequence, keyword):
        """An attribute of a source image, or of one frame of an enhanced multi-frame one."""
        if keyword in src:
            return src.get(keyword)
        if frame:
            groups = src.PerFrameFunctionalGroupsSequence[frame - 1]
            if sequence in groups:
                return groups.get(sequence)[0].get(keyword)
        return src.SharedFunctionalGroupsSequence[0].get(sequence)[0].get(keyword)

    for keyword in ("PatientID", "PatientName", "StudyInstanceUID", "FrameOfReferenceUID"):
        if str(seg.get(keyword, "")) != str(first.get(keyword, "")):
            fail("%s differs from the source: %r vs %r" %
                 (keyword, seg.get(keyword), first.get(keyword)))

    rows, cols, frames = seg.Rows, seg.Columns, int(seg.NumberOfFrames)
    # 1-bit frames are packed back to back, least significant bit first, without padding
    # between frames (PS3.5 8.1.1).
    # (No numpy in Debian's python3 here: the bits as a string, least significant first.)
    raw = bytes(seg.PixelData)
    bits = format(int.from_bytes(raw, "little"), "b")[::-1].ljust(len(raw) * 8, "0")
    plane = rows * cols
    if len(bits) < plane * frames:
        fail("pixel data holds %d bits, %d frames need %d" % (len(bits), frames, plane * frames))

    out = {}
    for f, groups in enumerate(seg.PerFrameFunctionalGroupsSequence):
        source_items = groups.DerivationImageSequence[0].SourceImageSequence
        uid = source_items[0].ReferencedSOPInstanceUID
        frame = int(source_items[0].get("ReferencedFrameNumber", 0) or 0)
        if uid not in sources or uid not in referenced:
            fail("frame %d derives from %s, not a referenced source instance" % (f + 1, uid))
        src = sources[uid]
        if src.Rows != rows or src.Columns != cols:
            fail("frame %d: source %s is %dx%d" % (f + 1, uid, src.Columns, src.Rows))
        position = [float(v) for v in groups.PlanePositionSequence[0].ImagePositionPatient]
        expected = [float(v) for v in
                    plane_attribute(src, frame, "PlanePositionSequence", "ImagePositionPatient")]
        if max(abs(a - b) for a, b in zip(position, expected)) > 0.01:
            fail("frame %d lies at %s but its source %s at %s" % (f + 1, position, uid, expected))
        if groups.SegmentIdentificationSequence[0].ReferencedSegmentNumber != 1:
            fail("frame %d belongs to another segment" % (f + 1))
        key = "%s:%d" % (uid, frame) if frame else uid
        if key in out:
            fail("two frames derive from %s" % key)
        frame_bits = bits[f * plane:(f + 1) * plane]
        out[key] = [i for i, b in enumerate(frame_bits) if b == "1"]

    shared = seg.SharedFunctionalGroupsSequence[0]
    iop = [float(v) for v in shared.PlaneOrientationSequence[0].ImageOrientationPatient]
    src_iop = [float(v) for v in
               plane_attribute(first, 1, "PlaneOrientationSequence", "ImageOrientationPatient")]
    if max(abs(a - b) for a, b in zip(iop, src_iop)) > 1e-4:
        fail("orientation %s differs from the source's %s" % (iop, src_iop))

    spacing = [float(v) for v in shared.PixelMeasuresSequence[0].PixelSpacing]
    src_spacing = [float(v) for v in
                   plane_attribute(first, 1, "PixelMeasuresSequence", "PixelSpacing")]
    if max(abs(a - b) for a, b in zip(spacing, src_spacing)) > 1e-4:
        fail("pixel spacing %s differs from the source's %s" % (spacing, src_spacing))

    for uid in sorted(out):
        print("slice %s %d %s" % (uid, len(out[uid]), " ".join(str(v) for v in out[uid])))


if __name__ == "__main__":
    main()
