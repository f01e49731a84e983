// TID 1500 through DCMTK's dcmsr content mapping resource (cmr), as dcmqi's tid1500writer
// builds it: the report, its observation context and image library, one TID 1411 group per
// segment with TID 1419 measurements, then a DSRDocument in the source's study.
#include "exports/measurement_report.hpp"

#include "exports/dicom_file_bytes.hpp"
#include "files/file_error.hpp"
#include "files/file_write.hpp"

#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmsr/cmr/tid1500.h>
#include <dcmtk/dcmsr/dsrdoc.h>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string_view>
#include <vector>

#ifndef STEERSEG_VERSION
#error "STEERSEG_VERSION must name the project's version"
#endif

namespace steerseg::exports {

namespace {

using Group = TID1500_MeasurementReport::TID1411_Measurements;

// The concepts and units (docs/exports.md, "Measurement report"). SCT and DCM codes of CID 7469
// (Generic Intensity and Size Measurements), its derivations from CID 7464, units of CID 7181.
const DSRCodedEntryValue kVolume("118565006", "SCT", "Volume");
const DSRCodedEntryValue kSurfaceArea("C0JK", "IBSI", "Surface area of mesh");
const DSRCodedEntryValue kLongAxis("103339001", "SCT", "Long Axis");
const DSRCodedEntryValue kShortAxis("103340004", "SCT", "Short Axis");
const DSRCodedEntryValue kDiameter("81827009", "SCT", "Diameter");
const DSRCodedEntryValue kAttenuation("112031", "DCM", "Attenuation Coefficient");
const DSRCodedEntryValue kMrSignal("110852", "DCM", "MR signal intensity");
const DSRCodedEntryValue kMean("373098007", "SCT", "Mean");
const DSRCodedEntryValue kStandardDeviation("386136009", "SCT", "Standard Deviation");
const DSRCodedEntryValue kMinimum("255605001", "SCT", "Minimum");
const DSRCodedEntryValue kMaximum("56851009", "SCT", "Maximum");
const DSRCodedEntryValue kMillilitre("ml", "UCUM", "milliliter");
const DSRCodedEntryValue kMillimetre("mm", "UCUM", "millimeter");
const DSRCodedEntryValue kSquareMillimetre("mm2", "UCUM", "square millimeter");
const DSRCodedEntryValue kHounsfield("[hnsf'U]", "UCUM", "Hounsfield Unit");
const DSRCodedEntryValue kNoUnits("1", "UCUM", "no units");
// CID 100: the modality's unspecified body region, else the generic imaging procedure.
const DSRCodedEntryValue kCtProcedure("25045-6", "LN", "CT unspecified body region");
const DSRCodedEntryValue kMrProcedure("25056-3", "LN", "MRI unspecified body region");
const DSRCodedEntryValue kImagingProcedure("363679005", "SCT", "Imaging procedure");

void check(const std::filesystem::path& path, const OFCondition& c, const char* step) {
    if (c.bad()) {
        throw files::WriteError(path, std::string("measurement report: ") + step +
                                          " failed: " + c.text());
    }
}

std::string newUid(const char* root) {
    char uid[100];
    return dcmGenerateUniqueIdentifier(uid, root);
}

// Decimal String: at most 16 characters, as many significant digits as fit (the exact value
// goes beside it as Floating Point Value).
std::string ds(double v) {
    char text[32];
    for (int digits = 12; digits > 1; --digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::string_view(text).size() <= 16) {
            break;
        }
    }
    return text;
}

DSRCodedEntryValue coded(const SegmentCode& c) {
    return {c.value.c_str(), c.scheme.c_str(), c.meaning.c_str()};
}

// What the scan's values measure, and in which unit: HU on CT, MR's arbitrary signal; other
// modalities' values (PET's activity, say) need attributes the source does not keep, so their
// intensity is left out rather than reported under a wrong concept.
struct Intensity {
    DSRCodedEntryValue quantity;
    DSRCodedEntryValue unit;
};

std::optional<Intensity> intensityFor(const std::string& modality) {
    if (modality == "CT") {
        return Intensity{kAttenuation, kHounsfield};
    }
    if (modality == "MR") {
        return Intensity{kMrSignal, kNoUnits};
    }
    return std::nullopt;
}

DSRCodedEntryValue procedureFor(const std::string& modality) {
    if (modality == "CT") {
        return kCtProcedure;
    }
    if (modality == "MR") {
        return kMrProcedure;
    }
    return kImagingProcedure;
}

void addMeasurement(const std::filesystem::path& path, Group& group,
                    const DSRCodedEntryValue& quantity, double value,
                    const DSRCodedEntryValue& unit,
                    const DSRCodedEntryValue& derivation = DSRCodedEntryValue()) {
    Group::MeasurementValue number(ds(value).c_str(), unit);
    check(path, number.setFloatingPointRepresentation(value), "a floating point value");
    check(path, group.addMeasurement(quantity, number), "a measurement");
    Group::TID1419_Measurement& added = group.getMeasurement();
    if (!derivation.isEmpty()) {
        check(path, added.setDerivation(derivation), "a derivation");
    }
    check(path, added.setAlgorithmIdentification("steerseg", STEERSEG_VERSION), "the algorithm");
}

// The report starts with one empty group; each segment fills the current one, a new one when
// it is taken (addVolumetricROIMeasurements adds none while the current is empty).
void addGroup(const std::filesystem::path& path, TID1500_MeasurementReport& report,
              const ReportedSegment& segment, const SegInstance& seg,
              const scan::DicomSource& source) {
    check(path, report.addVolumetricROIMeasurements(), "a measurement group");
    Group& group = report.getVolumetricROIMeasurements();
    check(path, group.setTrackingIdentifier(segment.label.c_str()), "the tracking identifier");
    check(path, group.setTrackingUniqueIdentifier(newUid(SITE_INSTANCE_UID_ROOT).c_str()),
          "the tracking UID");
    check(path, group.setFinding(coded(segment.finding)), "the finding");
    if (segment.site) {
        check(path, group.addFindingSite(coded(*segment.site)), "the finding site");
    }
    DSRImageReferenceValue reference(seg.sopClassUid.c_str(), seg.sopInstanceUid.c_str());
    reference.getSegmentList().addItem(segment.number);
    check(path, group.setReferencedSegment(reference), "the referenced segment");
    check(path, group.setSourceSeriesForSegmentation(source.seriesInstanceUid.c_str()),
          "the source series");

    const MaskMeasurements& m = segment.measurements;
    addMeasurement(path, group, kVolume, m.volumeMl, kMillilitre);
    addMeasurement(path, group, kSurfaceArea, m.surfaceAreaMm2, kSquareMillimetre);
    addMeasurement(path, group, kLongAxis, m.axial.longest.lengthMm, kMillimetre);
    addMeasurement(path, group, kShortAxis, m.axial.perpendicular.lengthMm, kMillimetre);
    addMeasurement(path, group, kDiameter, m.longest3d.lengthMm, kMillimetre, kMaximum);
    if (const std::optional<Intensity> intensity = intensityFor(source.modality)) {
        addMeasurement(path, group, intensity->quantity, m.intensity.mean, intensity->unit, kMean);
        addMeasurement(path, group, intensity->quantity, m.intensity.sd, intensity->unit,
                       kStandardDeviation);
        addMeasurement(path, group, intensity->quantity, m.intensity.min, intensity->unit,
                       kMinimum);
        addMeasurement(path, group, intensity->quantity, m.intensity.max, intensity->unit,
                       kMaximum);
    }
}

// The source's instances, once each: the image library's entries and the evidence.
std::vector<const scan::DicomSourceSlice*> sourceInstances(const scan::DicomSource& source) {
    std::vector<const scan::DicomSourceSlice*> out;
    std::set<std::string> seen;
    for (const scan::DicomSourceSlice& s : source.slices) {
        if (!s.sopInstanceUid.empty() && seen.insert(s.sopInstanceUid).second) {
            out.push_back(&s);
        }
    }
    return out;
}

void addImageLibrary(const std::filesystem::path& path, TID1500_MeasurementReport& report,
                     const scan::DicomSource& source) {
    TID1600_ImageLibrary& library = report.getImageLibrary();
    check(path, library.createNewImageLibrary(), "the image library");
    check(path, library.addImageGroup(), "the image library group");
    for (const scan::DicomSourceSlice* s : sourceInstances(source)) {
        DcmItem entry;
        check(path, entry.putAndInsertString(DCM_SOPClassUID, s->sopClassUid.c_str()),
              "an image's SOP class");
        check(path, entry.putAndInsertString(DCM_SOPInstanceUID, s->sopInstanceUid.c_str()),
              "an image's SOP instance");
        if (!source.modality.empty()) {
            check(path, entry.putAndInsertString(DCM_Modality, source.modality.c_str()),
                  "an image's modality");
        }
        check(path, library.addImageEntry(entry, TID1600_ImageLibrary::withoutDescriptors),
              "an image library entry");
    }
}

void buildReport(const std::filesystem::path& path, TID1500_MeasurementReport& report,
                 const scan::DicomSource& source, const SegInstance& seg,
                 std::span<const ReportedSegment> segments,
                 const MeasurementReportOptions& options) {
    check(path, report.setLanguage(CID5000_Languages::English), "the language");
    TID1001_ObservationContext& context = report.getObservationContext();
    check(path, context.addPersonObserver(options.observerName.c_str()), "the person observer");
    const std::string deviceUid =
        options.deviceUid.empty() ? applianceDeviceUid() : options.deviceUid;
    check(path,
          context.addDeviceObserver(deviceUid.c_str(), "steerseg", "steerseg",
                                    "steerseg " STEERSEG_VERSION),
          "the device observer");
    check(path, report.addProcedureReported(procedureFor(source.modality)),
          "the procedure reported");
    addImageLibrary(path, report, source);
    for (const ReportedSegment& segment : segments) {
        addGroup(path, report, segment, seg, source);
    }
    if (!report.isValid()) {
        throw files::WriteError(path, "measurement report: DCMTK finds the TID 1500 report "
                                      "incomplete");
    }
}

void addEvidence(const std::filesystem::path& path, DSRDocument& doc,
                 const scan::DicomSource& source, const SegInstance& seg) {
    DSRSOPInstanceReferenceList& evidence = doc.getCurrentRequestedProcedureEvidence();
    check(path,
          evidence.addItem(source.studyInstanceUid.c_str(), seg.seriesInstanceUid.c_str(),
                           seg.sopClassUid.c_str(), seg.sopInstanceUid.c_str()),
          "the SEG as evidence");
    for (const scan::DicomSourceSlice* s : sourceInstances(source)) {
        check(path,
              evidence.addItem(source.studyInstanceUid.c_str(), source.seriesInstanceUid.c_str(),
                               s->sopClassUid.c_str(), s->sopInstanceUid.c_str()),
              "a source image as evidence");
    }
}

// The patient and study of the source, as the SEG has them; the frame of reference is no part
// of an SR.
void inheritPatientAndStudy(const std::filesystem::path& path, DcmDataset& dataset,
                            const scan::DicomSource& source) {
    for (const scan::DicomAttribute& a : source.inherited) {
        if (a.group == 0x0020 && (a.element == 0x0052 || a.element == 0x1040)) {
            continue;
        }
        check(path, dataset.putAndInsertString(DcmTag(a.group, a.element), a.value.c_str()),
              "copying patient and study");
    }
}

} // namespace

std::string applianceDeviceUid() {
    std::ifstream in("/etc/machine-id");
    std::string id;
    in >> id;
    if (id.size() != 32 || id.find_first_not_of("0123456789abcdef") != std::string::npos) {
        return newUid(SITE_INSTANCE_UID_ROOT);
    }
    // 128 bits in decimal by long division: digits most significant first.
    std::vector<int> hex;
    for (const char c : id) {
        hex.push_back(c <= '9' ? c - '0' : c - 'a' + 10);
    }
    std::string decimal;
    while (!hex.empty()) {
        std::vector<int> quotient;
        int remainder = 0;
        for (const int h : hex) {
            const int value = remainder * 16 + h;
            if (!quotient.empty() || value / 10 != 0) {
                quotient.push_back(value / 10);
            }
            remainder = value % 10;
        }
        decimal.insert(decimal.begin(), static_cast<char>('0' + remainder));
        hex = std::move(quotient);
    }
    return "2.25." + decimal;
}

void writeMeasurementReport(const std::filesystem::path& path, const scan::DicomSource& source,
                            const SegInstance& seg, std::span<const ReportedSegment> segments,
                            const MeasurementReportOptions& options) {
    if (segments.empty()) {
        throw files::WriteError(path, "measurement report: no segment to report");
    }
    for (const ReportedSegment& segment : segments) {
        if (segment.measurements.voxels == 0) {
            throw files::WriteError(path, "measurement report: segment " +
                                              std::to_string(segment.number) +
                                              " has no voxel inside, so nothing to measure");
        }
    }
    if (source.studyInstanceUid.empty() || source.seriesInstanceUid.empty()) {
        throw files::WriteError(path, "measurement report: the source series has no "
                                      "StudyInstanceUID or SeriesInstanceUID to file it with");
    }
    std::vector<std::byte> bytes;
    try {
        TID1500_MeasurementReport report(CMR_CID7021::ImagingMeasurementReport);
        buildReport(path, report, source, seg, segments, options);
        DSRDocument doc;
        check(path, doc.setTreeFromRootTemplate(report, OFTrue), "the document tree");
        check(path, doc.createNewSeriesInStudy(source.studyInstanceUid.c_str()), "the series");
        check(path, doc.setSeriesDescription(options.seriesDescription.c_str()),
              "the series description");
        check(path, doc.setSeriesNumber(options.seriesNumber.c_str()), "the series number");
        check(path, doc.setInstanceNumber("1"), "the instance number");
        check(path, doc.setManufacturer("steerseg"), "the manufacturer");
        check(path, doc.setManufacturerModelName("steerseg"), "the model name");
        check(path, doc.setSoftwareVersions(STEERSEG_VERSION), "the software version");
        addEvidence(path, doc, source, seg);
        check(path, doc.completeDocument(), "completing the document");
        DcmFileFormat file;
        DcmDataset& dataset = *file.getDataset();
        check(path, doc.write(dataset), "building the data set");
        inheritPatientAndStudy(path, dataset, source);
        bytes = encodeExportFile(path, file, "measurement report");
    } catch (const files::WriteError&) {
        throw;
    } catch (const std::exception& e) {
        throw files::WriteError(path, std::string("measurement report: ") + e.what());
    }
    files::writeFileAtomically(path, {std::span<const std::byte>(bytes)});
}

} // namespace steerseg::exports
