#include "scan/dicom/multiframe.hpp"

#include <gdcmDataSet.h>
#include <gdcmSequenceOfItems.h>

namespace steerseg::scan {

namespace {

const gdcm::Tag kSharedGroups(0x5200, 0x9229);
const gdcm::Tag kPerFrameGroups(0x5200, 0x9230);
const gdcm::Tag kPlanePosition(0x0020, 0x9113);
const gdcm::Tag kPlaneOrientation(0x0020, 0x9116);
const gdcm::Tag kPixelMeasures(0x0028, 0x9110);
const gdcm::Tag kPixelValueTransformation(0x0028, 0x9145);

gdcm::SmartPointer<gdcm::SequenceOfItems> sequence(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    if (!ds.FindDataElement(tag)) {
        return nullptr;
    }
    return ds.GetDataElement(tag).GetValueAsSQ();
}

// The first item of sequence `tag` inside `ds`, or null.
const gdcm::DataSet* firstItem(const gdcm::DataSet* ds, const gdcm::Tag& tag,
                               gdcm::SmartPointer<gdcm::SequenceOfItems>& keep) {
    if (ds == nullptr) {
        return nullptr;
    }
    keep = sequence(*ds, tag);
    if (!keep || keep->GetNumberOfItems() < 1) {
        return nullptr;
    }
    return &keep->GetItem(1).GetNestedDataSet();
}

// A functional group macro for one frame: the per-frame item's if present, else the shared one.
struct GroupLookup {
    const gdcm::DataSet* perFrame = nullptr;
    const gdcm::DataSet* shared = nullptr;
    gdcm::SmartPointer<gdcm::SequenceOfItems> keepPerFrame, keepShared;

    const gdcm::DataSet* find(const gdcm::Tag& macro) {
        if (const gdcm::DataSet* item = firstItem(perFrame, macro, keepPerFrame)) {
            return item;
        }
        return firstItem(shared, macro, keepShared);
    }
};

} // namespace

void readFunctionalGroups(const std::filesystem::path& path, const gdcm::DataSet& ds,
                          DicomHeader& h) {
    const auto sharedSeq = sequence(ds, kSharedGroups);
    const auto perFrameSeq = sequence(ds, kPerFrameGroups);
    if (!sharedSeq && !perFrameSeq) {
        return;
    }
    const gdcm::DataSet* shared = (sharedSeq && sharedSeq->GetNumberOfItems() >= 1)
                                      ? &sharedSeq->GetItem(1).GetNestedDataSet()
                                      : nullptr;
    const auto frames = static_cast<std::size_t>(h.frames);
    const bool perFrameUsable = perFrameSeq && perFrameSeq->GetNumberOfItems() == frames;

    bool allPositions = perFrameUsable;
    for (std::size_t f = 0; f < frames; ++f) {
        GroupLookup look;
        look.shared = shared;
        if (perFrameUsable) {
            look.perFrame = &perFrameSeq->GetItem(f + 1).GetNestedDataSet();
        }
        const std::string where = "frame " + std::to_string(f + 1) + " ";
        if (const gdcm::DataSet* pos = look.find(kPlanePosition)) {
            const auto v = readDecimals(path, *pos, gdcm::Tag(0x0020, 0x0032), 3,
                                        (where + "ImagePositionPatient").c_str());
            if (!v.empty()) {
                h.planes[f].position = glm::dvec3(v[0], v[1], v[2]);
            } else {
                allPositions = false;
            }
        } else {
            allPositions = false;
        }
        if (const gdcm::DataSet* pvt = look.find(kPixelValueTransformation)) {
            const auto slope = readDecimals(path, *pvt, gdcm::Tag(0x0028, 0x1053), 1,
                                            (where + "RescaleSlope").c_str());
            const auto intercept = readDecimals(path, *pvt, gdcm::Tag(0x0028, 0x1052), 1,
                                                (where + "RescaleIntercept").c_str());
            if (!slope.empty()) {
                h.planes[f].rescale.slope = slope[0];
            }
            if (!intercept.empty()) {
                h.planes[f].rescale.intercept = intercept[0];
            }
        }
        // Orientation and pixel spacing must be the same for every frame of one volume; the
        // first frame's are taken and the others compared.
        if (const gdcm::DataSet* orient = look.find(kPlaneOrientation)) {
            const auto v = readDecimals(path, *orient, gdcm::Tag(0x0020, 0x0037), 6,
                                        (where + "ImageOrientationPatient").c_str());
            if (!v.empty()) {
                const std::pair<glm::dvec3, glm::dvec3> o{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
                if (f == 0) {
                    h.orientation = o;
                } else if (!h.orientation || glm::length(o.first - h.orientation->first) > 1e-4 ||
                           glm::length(o.second - h.orientation->second) > 1e-4) {
                    throw ScanError(path, where + "has a different orientation from frame 1");
                }
            }
        }
        if (const gdcm::DataSet* measures = look.find(kPixelMeasures)) {
            const auto ps = readDecimals(path, *measures, gdcm::Tag(0x0028, 0x0030), 2,
                                         (where + "PixelSpacing").c_str());
            if (!ps.empty()) {
                const glm::dvec2 s(ps[1], ps[0]);
                if (f == 0) {
                    h.pixelSpacing = s;
                } else if (!h.pixelSpacing || glm::length(s - *h.pixelSpacing) > 1e-4) {
                    throw ScanError(path, where + "has a different pixel spacing from frame 1");
                }
            }
            if (f == 0) {
                const auto thick =
                    readDecimals(path, *measures, gdcm::Tag(0x0018, 0x0050), 1, "SliceThickness");
                const auto between = readDecimals(path, *measures, gdcm::Tag(0x0018, 0x0088), 1,
                                                  "SpacingBetweenSlices");
                if (!thick.empty()) {
                    h.sliceThickness = thick[0];
                }
                if (!between.empty()) {
                    h.spacingBetweenSlices = between[0];
                }
            }
        }
    }
    h.framesFromGroups = allPositions;
}

} // namespace steerseg::scan
