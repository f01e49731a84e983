#!/usr/bin/env python3
"""Reads a DICOM SR Measurement Report (TID 1500) with pydicom, independently of DCMTK, for
tests/exports/io_measurement_report_test.cpp.

Usage: read_measurement_report.py REPORT.dcm

Prints one line per fact, words separated by tabs:
  header  SOPClassUID  Modality  StudyInstanceUID  SeriesInstanceUID  PatientID  TemplateIdentifier
  observer  person|device  value
  group  N  tracking-identifier  finding-code  referenced-SOP-instance  segment-number  source-series
  num  N  code  scheme  unit  derivation-code-or-dash  numeric-value  floating-point-value
N counts the measurement groups from 1. Exits 1 with a message for anything it cannot read.
"""
import sys

import pydicom

IMAGING_MEASUREMENTS = ("126010", "DCM")
MEASUREMENT_GROUP = ("125007", "DCM")
TRACKING_IDENTIFIER = ("112039", "DCM")
FINDING = ("121071", "DCM")
REFERENCED_SEGMENT = ("121191", "DCM")
SOURCE_SERIES = ("121232", "DCM")
DERIVATION = ("121401", "DCM")
PERSON_OBSERVER = ("121008", "DCM")
DEVICE_OBSERVER_UID = ("121012", "DCM")


def code(item):
    c = item.ConceptNameCodeSequence[0]
    return (c.CodeValue, c.CodingSchemeDesignator)


def walk(items):
    for item in items:
        yield item
        if "ContentSequence" in item:
            yield from walk(item.ContentSequence)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    ds = pydicom.dcmread(sys.argv[1])
    template = ds.ContentTemplateSequence[0].TemplateIdentifier
    print("\t".join(["header", ds.SOPClassUID, ds.Modality, ds.StudyInstanceUID,
                     ds.SeriesInstanceUID, str(ds.get("PatientID", "")), template]))
    for item in walk(ds.ContentSequence):
        if item.ValueType == "PNAME" and code(item) == PERSON_OBSERVER:
            print("\t".join(["observer", "person", str(item.PersonName)]))
        if item.ValueType == "UIDREF" and code(item) == DEVICE_OBSERVER_UID:
            print("\t".join(["observer", "device", item.UID]))
    container = [i for i in ds.ContentSequence
                 if i.ValueType == "CONTAINER" and code(i) == IMAGING_MEASUREMENTS]
    if len(container) != 1:
        print("no single Imaging Measurements container", file=sys.stderr)
        return 1
    n = 0
    for group in container[0].ContentSequence:
        if group.ValueType != "CONTAINER" or code(group) != MEASUREMENT_GROUP:
            continue
        n += 1
        tracking = finding = instance = number = series = "-"
        for item in group.ContentSequence:
            key = code(item)
            if key == TRACKING_IDENTIFIER:
                tracking = item.TextValue
            elif key == FINDING:
                finding = item.ConceptCodeSequence[0].CodeValue
            elif key == REFERENCED_SEGMENT:
                ref = item.ReferencedSOPSequence[0]
                instance = ref.ReferencedSOPInstanceUID
                number = str(ref.ReferencedSegmentNumber)
            elif key == SOURCE_SERIES:
                series = item.UID
        print("\t".join(["group", str(n), tracking, finding, instance, number, series]))
        for item in group.ContentSequence:
            if item.ValueType != "NUM":
                continue
            value = item.MeasuredValueSequence[0]
            derivation = "-"
            for child in item.get("ContentSequence", []):
                if code(child) == DERIVATION:
                    derivation = child.ConceptCodeSequence[0].CodeValue
            c = item.ConceptNameCodeSequence[0]
            print("\t".join(["num", str(n), c.CodeValue, c.CodingSchemeDesignator,
                             value.MeasurementUnitsCodeSequence[0].CodeValue, derivation,
                             str(value.NumericValue), repr(float(value.FloatingPointValue))]))
    if n == 0:
        print("no measurement group", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:  # a broken report is a test failure, said in one line
        print(f"cannot read the report: {e}", file=sys.stderr)
        sys.exit(1)
