// The PACS's actions (model::SearchPacs, ListPacsSeries, RetrievePacs, CancelRetrieve): the
// workflow knows no network. It checks what it can of their arguments, so that a garbled one is
// refused in the operator's message and the audit log like any other action, and leaves the
// state as it is; the kiosk hands the accepted ones to its DICOM node.
#include "workflow/workflow.hpp"

namespace steerseg::workflow {

Workflow::Outcome Workflow::on(const model::SearchPacs& a) {
    if (const std::string problem = model::pacsKeysProblem(a.keys); !problem.empty()) {
        return no("search: " + problem);
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::RetrievePacs& a) {
    if (const std::string problem = model::uidProblem(a.studyUid); !problem.empty()) {
        return no("retrieve: the study " + problem);
    }
    if (!a.seriesUid.empty()) {
        if (const std::string problem = model::uidProblem(a.seriesUid); !problem.empty()) {
            return no("retrieve: the series " + problem);
        }
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::ListPacsSeries& a) {
    if (const std::string problem = model::uidProblem(a.studyUid); !problem.empty()) {
        return no("series: the study " + problem);
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::CancelRetrieve&) {
    return ok();
}

} // namespace steerseg::workflow
