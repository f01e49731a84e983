// The light build's check of the DICOM node: there is none (DCMTK is not in the GPU pack), a
// failure when the configuration turns it on, since the appliance would not do what it says.
#include "cli/self_test_dicom.hpp"
#include "model/light_build.hpp"

namespace steerseg::cli {

std::vector<CheckResult> checkDicomNode(const config::DicomConfig& dicom) {
    if (!dicom.enabled) {
        return {{"dicom node", CheckLevel::Ok, "off ([dicom] enabled = false)", {}}};
    }
    return {{"dicom node",
             CheckLevel::Fail,
             model::leftOutOfLightBuild("The DICOM node ([dicom] enabled = true)", "DCMTK"),
             {}}};
}

} // namespace steerseg::cli
