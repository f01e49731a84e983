#pragma once

// What a scan read from a DICOM series remembers of its source, so that a result written back as
// DICOM (a segmentation) can reference the instances it was drawn on and belong to the same
// patient, study and frame of reference. Library-neutral: text values as stored.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::scan {

// The image plane at one slice k of the volume.
struct DicomSourceSlice {
    std::string sopClassUid;            // SOPClassUID, else the file meta's MediaStorageSOPClassUID
    std::string sopInstanceUid;         // SOPInstanceUID, else MediaStorageSOPInstanceUID
    int frameNumber = 0;                // 1-based frame of a multi-frame instance; 0: single frame
    std::optional<glm::dvec3> position; // its ImagePositionPatient (LPS mm), where it has one
};

// One attribute copied from the source as text (its bytes, padding removed).
struct DicomAttribute {
    std::uint16_t group = 0;
    std::uint16_t element = 0;
    std::string value;
};

struct DicomSource {
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string frameOfReferenceUid;
    std::string patientId;
    std::string
        modality; // Modality (0008,0060) of the first file: what the values measure (HU on CT)
    std::optional<double> sliceThickness;
    // LossyImageCompression "01" on any slice: derived objects must say so too.
    bool lossyCompressed = false;
    std::string lossyRatio;  // LossyImageCompressionRatio of the first lossy slice
    std::string lossyMethod; // LossyImageCompressionMethod
    // The patient, general study, patient study and frame of reference attributes present in
    // the series' first file, and its SpecificCharacterSet (the text keeps its encoding).
    std::vector<DicomAttribute> inherited;
    // slices[k]: the source plane of volume slice k (k ascending along the normal).
    std::vector<DicomSourceSlice> slices;
};

} // namespace steerseg::scan
