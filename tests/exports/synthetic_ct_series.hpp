#pragma once

// A synthetic axial CT series written with DCMTK, for the tests of the DICOM objects that refer
// to one (the SEG of several structures, the measurement report).
#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace steerseg::test {

inline std::string uid() {
    char text[100];
    return dcmGenerateUniqueIdentifier(text, SITE_INSTANCE_UID_ROOT);
}

inline constexpr int kColumns = 24;
inline constexpr int kRows = 20;
inline constexpr int kSlices = 10;

// HU at a voxel: varied, so that mean, sd, min and max all mean something.
inline int hounsfield(int i, int j, int k) {
    return -60 + (3 * i + 5 * j + 7 * k) % 53;
}

// Who and when the series is of, and how its files are named.
struct SeriesSpec {
    std::string patientName = "Test^Report";
    std::string patientId = "SR-TEST-1";
    std::string studyDate = "20261201";
    bool descendingFiles = false; // file names in descending slice order: not slice order
};

// An axial CT series, one slice per file, 0.8 x 0.7 mm pixels, 2 mm apart; stored values with
// a rescale intercept of -1024. Returns its Series Instance UID.
inline std::string writeSeries(const std::filesystem::path& dir, const SeriesSpec& spec = {}) {
    const std::string study = uid();
    const std::string series = uid();
    const std::string frame = uid();
    for (int k = 0; k < kSlices; ++k) {
        DcmFileFormat file;
        DcmDataset& d = *file.getDataset();
        d.putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
        d.putAndInsertString(DCM_SOPInstanceUID, uid().c_str());
        d.putAndInsertString(DCM_StudyInstanceUID, study.c_str());
        d.putAndInsertString(DCM_SeriesInstanceUID, series.c_str());
        d.putAndInsertString(DCM_FrameOfReferenceUID, frame.c_str());
        d.putAndInsertString(DCM_PositionReferenceIndicator, "");
        d.putAndInsertString(DCM_PatientName, spec.patientName.c_str());
        d.putAndInsertString(DCM_PatientID, spec.patientId.c_str());
        d.putAndInsertString(DCM_PatientBirthDate, "19700101");
        d.putAndInsertString(DCM_PatientSex, "O");
        d.putAndInsertString(DCM_StudyDate, spec.studyDate.c_str());
        d.putAndInsertString(DCM_StudyTime, "093000");
        d.putAndInsertString(DCM_StudyID, "7");
        d.putAndInsertString(DCM_AccessionNumber, "SR1");
        d.putAndInsertString(DCM_ReferringPhysicianName, "");
        d.putAndInsertString(DCM_Modality, "CT");
        d.putAndInsertString(DCM_SeriesNumber, "2");
        d.putAndInsertString(DCM_InstanceNumber, std::to_string(k + 1).c_str());
        d.putAndInsertString(DCM_ImageType, "ORIGINAL\\PRIMARY\\AXIAL");
        d.putAndInsertString(DCM_ImagePositionPatient,
                             ("-10\\-8\\" + std::to_string(2 * k - 50)).c_str());
        d.putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
        d.putAndInsertString(DCM_PixelSpacing, "0.7\\0.8"); // rows apart, then columns
        d.putAndInsertString(DCM_SliceThickness, "2");
        d.putAndInsertString(DCM_RescaleIntercept, "-1024");
        d.putAndInsertString(DCM_RescaleSlope, "1");
        d.putAndInsertUint16(DCM_SamplesPerPixel, 1);
        d.putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
        d.putAndInsertUint16(DCM_Rows, kRows);
        d.putAndInsertUint16(DCM_Columns, kColumns);
        d.putAndInsertUint16(DCM_BitsAllocated, 16);
        d.putAndInsertUint16(DCM_BitsStored, 16);
        d.putAndInsertUint16(DCM_HighBit, 15);
        d.putAndInsertUint16(DCM_PixelRepresentation, 0);
        std::vector<Uint16> pixels;
        for (int j = 0; j < kRows; ++j) {
            for (int i = 0; i < kColumns; ++i) {
                pixels.push_back(static_cast<Uint16>(1024 + hounsfield(i, j, k)));
            }
        }
        d.putAndInsertUint16Array(DCM_PixelData, pixels.data(),
                                  static_cast<unsigned long>(pixels.size()));
        char name[32];
        std::snprintf(name, sizeof name, "im%03d.dcm", spec.descendingFiles ? kSlices - 1 - k : k);
        EXPECT_TRUE(file.saveFile((dir / name).c_str(), EXS_LittleEndianExplicit).good());
    }
    return series;
}

} // namespace steerseg::test
