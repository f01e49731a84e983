// The light build's readers for the two kinds of scan whose libraries the GPU pack leaves out:
// such a scan is refused by name (the dispatcher, NIfTI, NRRD, MetaImage and MGZ are the full
// build's own).
#include "model/light_build.hpp"
#include "scan/readers.hpp"

namespace steerseg::scan {

Volume readImageStack(const std::filesystem::path& path, const ReadLimits& /*limits*/) {
    throw ScanError(path, model::leftOutOfLightBuild("Reading 2D images", "OpenImageIO"));
}

Volume readDicom(const std::filesystem::path& path, const ReadLimits& /*limits*/,
                 DicomSource* /*source*/) {
    throw ScanError(path, model::leftOutOfLightBuild("Reading DICOM", "GDCM"));
}

} // namespace steerseg::scan
