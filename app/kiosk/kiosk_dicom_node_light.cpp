// The light build's DICOM node: none (DCMTK is not in the GPU pack). A configuration that turns
// it on gets one line saying so on the first frame, as the full node's failures are told, and
// the kiosk runs on without receiving or sending: exports still go to files.
#include "kiosk/kiosk_dicom_node.hpp"
#include "model/light_build.hpp"

namespace steerseg::kiosk {

struct DicomNode::Link {};

DicomNode::DicomNode(const config::DicomConfig& dicom) : dicom_(dicom) {
    if (dicom_.enabled) {
        shared_.log.push_back(
            model::leftOutOfLightBuild("The DICOM node ([dicom] enabled = true)", "DCMTK"));
    }
}

DicomNode::~DicomNode() = default;

void DicomNode::frame(const workflow::Status& /*status*/, workflow::AuditLog& /*audit*/,
                      std::ostream& err) {
    for (const std::string& line : shared_.log) {
        err << "steerseg kiosk: dicom: " << line << '\n';
    }
    shared_.log.clear();
}

void DicomNode::request(const model::Action& action) {
    shared_.log.push_back(std::string(model::actionName(action)) + ": " +
                          model::leftOutOfLightBuild("The PACS search", "DCMTK"));
}

void DicomNode::show(workflow::Status& status) const {
    status.pacs = {};
    status.received.clear();
    status.outbox.clear();
    status.receivedNote.clear();
}

workflow::Status DicomNode::shown(const workflow::Status& status) const {
    workflow::Status s = status;
    show(s);
    return s;
}

void DicomNode::finish(workflow::AuditLog& audit, std::ostream& err) {
    frame({}, audit, err);
}

} // namespace steerseg::kiosk
