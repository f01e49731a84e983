// Binary DICOM SEG through DCMTK's dcmseg, as dcmqi writes them: one segment per structure, the
// frames that hold each segment's voxels, each frame referencing its source slice. docs/dicom.md
// says what is written and how it was validated.
#include "exports/dicom_seg_writer.hpp"

#include "exports/dicom_file_bytes.hpp"
#include "exports/display_color.hpp"
#include "exports/seg_frames.hpp"
#include "files/file_write.hpp"
#include "scan/scan_reader.hpp"

#include <cinttypes>
#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmfg/fgderimg.h>
#include <dcmtk/dcmfg/fgfracon.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>
#include <dcmtk/oflog/oflog.h>
#include <memory>
#include <set>

#ifndef STEERSEG_VERSION
#error "STEERSEG_VERSION must name the project's version"
#endif

namespace steerseg::exports {

namespace {

// Decimal String: at most 16 characters.
std::string ds(double v) {
    char text[32];
    for (int digits = 10; digits > 1; --digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, v);
        if (std::string_view(text).size() <= 16) {
            break;
        }
    }
    return text;
}

void check(const std::filesystem::path& path, const OFCondition& c, const char* step) {
    if (c.bad()) {
        throw files::WriteError(path, std::string("DICOM SEG: ") + step + " failed: " + c.text());
    }
}

std::string newUid(const char* root) {
    char uid[100];
    return dcmGenerateUniqueIdentifier(uid, root);
}

CodeSequenceMacro code(const SegmentCode& c) {
    return CodeSequenceMacro(c.value.c_str(), c.scheme.c_str(), c.meaning.c_str());
}

// Names a segment in a message where there are several.
std::string ofSegment(std::span<const DicomSegment> segments, const DicomSegment& s) {
    return segments.size() > 1 ? " (segment '" + s.label + "')" : "";
}

void checkInputs(const std::filesystem::path& path, const Geometry& g,
                 std::span<const DicomSegment> segments, const scan::DicomSource* source) {
    if (source == nullptr) {
        throw files::WriteError(path, "DICOM SEG needs a scan read from a DICOM series");
    }
    if (segments.empty()) {
        throw files::WriteError(path, "DICOM SEG: no segment to write");
    }
    if (segments.size() > 65535) {
        throw files::WriteError(path, "DICOM SEG: more than 65535 segments");
    }
    for (const DicomSegment& s : segments) {
        if (s.mask.size() != g.voxelCount()) {
            throw files::WriteError(path, "DICOM SEG: the mask has " +
                                              std::to_string(s.mask.size()) + " voxels, the scan " +
                                              std::to_string(g.voxelCount()) +
                                              ofSegment(segments, s));
        }
    }
    if (source->slices.size() != static_cast<std::size_t>(g.dims.z)) {
        throw files::WriteError(path, "DICOM SEG: the scan has " + std::to_string(g.dims.z) +
                                          " slices but its DICOM source " +
                                          std::to_string(source->slices.size()));
    }
    if (g.dims.x > 65535 || g.dims.y > 65535) {
        throw files::WriteError(path, "DICOM SEG: slices of more than 65535 rows or columns");
    }
    if (source->frameOfReferenceUid.empty()) {
        throw files::WriteError(path, "DICOM SEG: the source series has no FrameOfReferenceUID "
                                      "(0020,0052), so the segmentation cannot be placed on it");
    }
    if (source->studyInstanceUid.empty() || source->seriesInstanceUid.empty()) {
        throw files::WriteError(path,
                                "DICOM SEG: the source series has no StudyInstanceUID or "
                                "SeriesInstanceUID, so the segmentation cannot be filed with it");
    }
    for (std::size_t k = 0; k < source->slices.size(); ++k) {
        const scan::DicomSourceSlice& s = source->slices[k];
        if (s.sopClassUid.empty() || s.sopInstanceUid.empty()) {
            throw files::WriteError(path, "DICOM SEG: source slice " + std::to_string(k) +
                                              " has no SOPClassUID or SOPInstanceUID to reference");
        }
    }
}

// The patient, study and frame of reference attributes of the source, as a data set DCMTK's
// importFromSourceImage takes them from.
DcmDataset inheritedDataSet(const scan::DicomSource& source) {
    DcmDataset set;
    for (const scan::DicomAttribute& a : source.inherited) {
        set.putAndInsertString(DcmTag(a.group, a.element), a.value.c_str());
    }
    return set;
}

// One frame's functional groups: where it lies, which source plane it was derived from, and its
// place in the dimension index (segment, slice).
struct FrameGroups {
    std::unique_ptr<FGPlanePosPatient> position;
    std::unique_ptr<FGFrameContent> content;
    std::unique_ptr<FGDerivationImage> derivation;
};

FrameGroups frameGroups(const std::filesystem::path& path, const Geometry& g,
                        const scan::DicomSourceSlice& slice, int k, Uint16 segmentNumber) {
    FrameGroups fg;
    const glm::dvec3 p = slice.position.value_or(g.indexToWorld({0.0, 0.0, k}));
    fg.position.reset(
        FGPlanePosPatient::createMinimal(ds(p.x).c_str(), ds(p.y).c_str(), ds(p.z).c_str()));
    fg.content = std::make_unique<FGFrameContent>();
    check(path, fg.content->setDimensionIndexValues(segmentNumber, 0), "dimension index (segment)");
    check(path, fg.content->setDimensionIndexValues(static_cast<Uint32>(k) + 1, 1),
          "dimension index (position)");
    fg.derivation = std::make_unique<FGDerivationImage>();
    DerivationImageItem* item = nullptr;
    check(path,
          fg.derivation->addDerivationImageItem(CodeSequenceMacro("113076", "DCM", "Segmentation"),
                                                "", item),
          "derivation image");
    auto source = std::make_unique<SourceImageItem>();
    source->getPurposeOfReferenceCode().set("121322", "DCM",
                                            "Source image for image processing operation");
    ImageSOPInstanceReferenceMacro& ref = source->getImageSOPInstanceReference();
    check(path, ref.setReferencedSOPClassUID(slice.sopClassUid.c_str()), "source SOP class");
    check(path, ref.setReferencedSOPInstanceUID(slice.sopInstanceUid.c_str()),
          "source SOP instance");
    item->getSourceImageItems().push_back(source.release());
    return fg;
}

void addSharedGroups(const std::filesystem::path& path, DcmSegmentation& seg, const Geometry& g,
                     const scan::DicomSource& source) {
    FGPixelMeasures measures;
    check(path, measures.setPixelSpacing((ds(g.spacing.y) + "\\" + ds(g.spacing.x)).c_str()),
          "pixel spacing");
    check(path, measures.setSliceThickness(ds(source.sliceThickness.value_or(g.spacing.z)).c_str()),
          "slice thickness");
    check(path, measures.setSpacingBetweenSlices(ds(g.spacing.z).c_str()), "slice spacing");
    check(path, seg.addForAllFrames(measures), "pixel measures");
    const glm::dvec3 row = g.direction[0];
    const glm::dvec3 col = g.direction[1];
    const std::unique_ptr<FGPlaneOrientationPatient> orientation(
        FGPlaneOrientationPatient::createMinimal(ds(row.x).c_str(), ds(row.y).c_str(),
                                                 ds(row.z).c_str(), ds(col.x).c_str(),
                                                 ds(col.y).c_str(), ds(col.z).c_str()));
    check(path, seg.addForAllFrames(*orientation), "plane orientation");
}

Uint16 addSegment(const std::filesystem::path& path, DcmSegmentation& seg,
                  const DicomSegment& options) {
    DcmSegment* segment = nullptr;
    check(path,
          DcmSegment::create(segment, options.label.c_str(), code(options.category),
                             code(options.type), DcmSegTypes::SAT_SEMIAUTOMATIC, "steerseg"),
          "segment");
    std::unique_ptr<DcmSegment> owned(segment);
    if (options.color) {
        const std::array<std::uint16_t, 3> lab = dicomLabFromRgb(*options.color);
        check(path, owned->setRecommendedDisplayCIELabValue(lab[0], lab[1], lab[2]),
              "recommended display colour");
    }
    AlgorithmIdentificationMacro algorithm;
    // A level set is a deformable model (CID 7162).
    algorithm.getAlgorithmFamilyCode().set("123111", "DCM", "Deformable Models");
    check(path, algorithm.setAlgorithmName("steerseg"), "algorithm name");
    check(path, algorithm.setAlgorithmVersion(STEERSEG_VERSION), "algorithm version");
    check(path, owned->setSegmentationAlgorithmIdentification(algorithm), "algorithm");
    Uint16 number = 0;
    check(path, seg.addSegment(owned.get(), number), "segment");
    owned.release(); // the segmentation owns it now
    return number;
}

// Every instance of the source series, once, in the Referenced Series Sequence.
void addReferences(const std::filesystem::path& path, DcmSegmentation& seg,
                   const scan::DicomSource& source) {
    IODReferences refs;
    std::set<std::string> seen;
    for (const scan::DicomSourceSlice& s : source.slices) {
        if (seen.insert(s.sopInstanceUid).second) {
            refs.add(new IODImageReference(
                source.patientId.c_str(), source.studyInstanceUid.c_str(),
                source.seriesInstanceUid.c_str(), s.sopInstanceUid.c_str(), s.sopClassUid.c_str()));
        }
    }
    if (seg.getCommonInstanceReference().addReferences(refs, source.studyInstanceUid.c_str()) !=
        seen.size()) {
        throw files::WriteError(path,
                                "DICOM SEG: the source instances could not all be referenced");
    }
}

std::unique_ptr<DcmSegmentation>
buildSegmentation(const std::filesystem::path& path, const Geometry& g,
                  std::span<const DicomSegment> segments, const std::vector<Frame>& frames,
                  const scan::DicomSource& source, const DicomSegSeries& series,
                  SegInstance& instance) {
    const IODGeneralEquipmentModule::EquipmentInfo equipment("steerseg", "steerseg", "none",
                                                             STEERSEG_VERSION);
    // Content Creator's Name (type 2) names a person, whom steerseg does not know.
    const ContentIdentificationMacro content("1", "STEERSEG", "steerseg level-set segmentation",
                                             "");
    DcmSegmentation* raw = nullptr;
    check(path,
          DcmSegmentation::createBinarySegmentation(raw, static_cast<Uint16>(g.dims.y),
                                                    static_cast<Uint16>(g.dims.x), equipment,
                                                    content),
          "creating the segmentation");
    std::unique_ptr<DcmSegmentation> seg(raw);
    DcmDataset inherited = inheritedDataSet(source);
    check(path, seg->importFromSourceImage(inherited), "copying patient and study");
    instance.sopClassUid = UID_SegmentationStorage;
    instance.seriesInstanceUid = newUid(SITE_SERIES_UID_ROOT);
    instance.sopInstanceUid = newUid(SITE_INSTANCE_UID_ROOT);
    check(path, seg->getSeries().setSeriesInstanceUID(instance.seriesInstanceUid.c_str()),
          "series UID");
    check(path, seg->getSOPCommon().setSOPInstanceUID(instance.sopInstanceUid.c_str()),
          "instance UID");
    check(path, seg->getSegmentationSeriesModule().setSeriesNumber(series.number.c_str()),
          "series number");
    check(path, seg->getSeries().setSeriesDescription(series.description.c_str()),
          "series description");
    if (source.lossyCompressed) {
        check(path,
              seg->setLossyImageCompressionFlag(source.lossyRatio.c_str(),
                                                source.lossyMethod.c_str(), OFFalse),
              "lossy compression flag");
    }
    const std::string dimensions = newUid(SITE_INSTANCE_UID_ROOT);
    IODMultiframeDimensionModule& dims = seg->getDimensions();
    check(path,
          dims.addDimensionIndex(DCM_ReferencedSegmentNumber, dimensions.c_str(),
                                 DCM_SegmentIdentificationSequence, "ReferencedSegmentNumber"),
          "dimension (segment)");
    check(path,
          dims.addDimensionIndex(DCM_ImagePositionPatient, dimensions.c_str(),
                                 DCM_PlanePositionSequence, "ImagePositionPatient"),
          "dimension (position)");
    addSharedGroups(path, *seg, g, source);
    for (const DicomSegment& s : segments) {
        instance.segmentNumbers.push_back(addSegment(path, *seg, s));
    }
    instance.segmentNumber = instance.segmentNumbers.front();
    addReferences(path, *seg, source);

    const std::size_t plane =
        static_cast<std::size_t>(g.dims.x) * static_cast<std::size_t>(g.dims.y);
    std::vector<Uint8> frame(plane);
    for (const Frame& f : frames) {
        const auto slab =
            segments[f.segment].mask.subspan(static_cast<std::size_t>(f.k) * plane, plane);
        for (std::size_t v = 0; v < plane; ++v) {
            frame[v] = slab[v] != 0 ? 1 : 0;
        }
        const Uint16 number = instance.segmentNumbers[f.segment];
        const FrameGroups fg =
            frameGroups(path, g, source.slices[static_cast<std::size_t>(f.k)], f.k, number);
        OFVector<FGBase*> groups;
        groups.push_back(fg.position.get());
        groups.push_back(fg.content.get());
        groups.push_back(fg.derivation.get());
        check(path, seg->addFrame(frame.data(), number, groups), "adding a frame");
    }
    return seg;
}

// Referenced Frame Number (IS) of sources in multi-frame files. DCMTK 3.6.7's
// setReferencedFrameNumber puts binary values on this text attribute and always fails, so the
// numbers go into the written data set: frame n's first Source Image item.
void addReferencedFrameNumbers(const std::filesystem::path& path, DcmDataset& dataset,
                               const std::vector<Frame>& frames, const scan::DicomSource& source) {
    DcmSequenceOfItems* perFrame = nullptr;
    check(path, dataset.findAndGetSequence(DCM_PerFrameFunctionalGroupsSequence, perFrame),
          "finding the per-frame groups");
    if (perFrame == nullptr || perFrame->card() != frames.size()) {
        throw files::WriteError(path, "DICOM SEG: the per-frame groups do not match the frames");
    }
    for (std::size_t n = 0; n < frames.size(); ++n) {
        const int frame = source.slices[static_cast<std::size_t>(frames[n].k)].frameNumber;
        if (frame == 0) {
            continue;
        }
        DcmItem* derivation = nullptr;
        DcmItem* sourceImage = nullptr;
        check(path,
              perFrame->getItem(static_cast<unsigned long>(n))
                  ->findAndGetSequenceItem(DCM_DerivationImageSequence, derivation),
              "finding a derivation image");
        check(path, derivation->findAndGetSequenceItem(DCM_SourceImageSequence, sourceImage),
              "finding a source image");
        check(path,
              sourceImage->putAndInsertString(DCM_ReferencedFrameNumber,
                                              std::to_string(frame).c_str()),
              "source frame number");
    }
}

} // namespace

SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& geometry,
                          std::span<const DicomSegment> segments, const scan::DicomSource* source,
                          const DicomSegSeries& series) {
    checkInputs(path, geometry, segments, source);
    std::vector<Frame> frames;
    for (std::size_t n = 0; n < segments.size(); ++n) {
        const std::vector<int> slices = segmentedSlices(geometry, segments[n].mask);
        if (slices.empty()) {
            throw files::WriteError(path, "DICOM SEG: the mask is empty for segment '" +
                                              segments[n].label +
                                              "', and each segment needs at least one segmented "
                                              "frame");
        }
        for (const int k : slices) {
            frames.push_back({n, k});
        }
    }
    // dcmiod checks dimensions before the per-frame groups are written and warns that it
    // cannot; dcmseg's own check runs afterwards. Real problems still fail the write.
    OFLog::getLogger("dcmtk.dcmiod").setLogLevel(OFLogger::ERROR_LOG_LEVEL);
    std::vector<std::byte> bytes;
    SegInstance instance;
    try {
        const std::unique_ptr<DcmSegmentation> seg =
            buildSegmentation(path, geometry, segments, frames, *source, series, instance);
        DcmFileFormat file;
        DcmDataset& dataset = *file.getDataset();
        check(path, seg->writeDataset(dataset), "building the data set");
        addReferencedFrameNumbers(path, dataset, frames, *source);
        const std::vector<std::uint8_t> pixels = packFrames(geometry, segments, frames);
        check(path,
              dataset.putAndInsertUint8Array(DCM_PixelData, pixels.data(),
                                             static_cast<unsigned long>(pixels.size())),
              "packing the frames");
        bytes = encodeExportFile(path, file, "DICOM SEG");
    } catch (const files::WriteError&) {
        throw;
    } catch (const std::exception& e) {
        throw files::WriteError(path, std::string("DICOM SEG: ") + e.what());
    }
    files::writeFileAtomically(path, {std::span<const std::byte>(bytes)});
    return instance;
}

SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& geometry,
                          std::span<const std::uint8_t> mask, const scan::DicomSource* source,
                          const DicomSegOptions& options) {
    const DicomSegment segment{options.label, options.category, options.type, options.color, mask};
    return writeDicomSeg(path, geometry, std::span(&segment, 1), source,
                         {options.seriesDescription, options.seriesNumber});
}

} // namespace steerseg::exports
