// The PACS's verbs (docs/scripts.md; docs/dicom-network.md "The kiosk's search"): `search`
// with the form's keys by the config's field names, `series` of a study ($FOUND: the last
// search's first), `retrieve` a study or one of its series ($SERIES: the last listing's first),
// `cancel_retrieve`. A UID is checked here; a peer's name is the kiosk's to know (the player
// checks it against the status's query peers when the step runs).
#include "script/script_verbs.hpp"

#include <string>

namespace steerseg::script::detail {

namespace {

StepKind actionStep(model::Action action) {
    return ActionStep{std::move(action)};
}

std::string peerWord(Words& w) {
    std::string name = w.text("the peer's name");
    if (name.empty()) {
        throw LineError("the peer's name is empty");
    }
    return name;
}

StepKind search(Words& w) {
    constexpr const char* kUsage = "search [peer NAME] [patient_name P] [patient_id ID] "
                                   "[study_date YYYYMMDD[-YYYYMMDD]|PRESET] [modality M] "
                                   "[accession N]";
    model::SearchPacs s;
    while (!w.empty()) {
        const std::string key = w.text("a search key");
        if (key == "peer") {
            s.peer = peerWord(w);
        } else if (const auto field = model::searchFieldFromName(key)) {
            model::keyOf(s.keys, *field) = w.text("the key's value");
        } else {
            throw LineError("search '" + key + "': " + kUsage);
        }
    }
    if (const std::string problem = model::pacsKeysProblem(s.keys); !problem.empty()) {
        throw LineError(problem);
    }
    return actionStep(s);
}

std::string uidWord(Words& w, const char* what) {
    std::string uid = w.text(what);
    if (uid.starts_with('$')) {
        checkVariables(uid);
    } else if (const std::string problem = model::uidProblem(uid); !problem.empty()) {
        throw LineError(problem);
    }
    return uid;
}

StepKind retrieve(Words& w) {
    constexpr const char* kUsage = "retrieve STUDY_UID|$FOUND [SERIES_UID|$SERIES] [peer NAME]";
    model::RetrievePacs r;
    r.studyUid = uidWord(w, "the study's UID");
    bool named = w.accept("peer");
    if (!named && !w.empty()) {
        r.seriesUid = uidWord(w, "the series' UID");
        named = w.accept("peer");
    }
    if (named) {
        r.peer = peerWord(w);
    }
    w.finish(kUsage);
    return actionStep(r);
}

StepKind series(Words& w) {
    constexpr const char* kUsage = "series STUDY_UID|$FOUND [peer NAME]";
    model::ListPacsSeries l;
    l.studyUid = uidWord(w, "the study's UID");
    if (w.accept("peer")) {
        l.peer = peerWord(w);
    }
    w.finish(kUsage);
    return actionStep(l);
}

} // namespace

void addPacsVerbs(VerbTable& table) {
    table.insert({
        {"search", search},
        {"series", series},
        {"retrieve", retrieve},
        {"cancel_retrieve",
         [](Words& w) {
             w.finish("cancel_retrieve");
             return actionStep(model::CancelRetrieve{});
         }},
    });
}

} // namespace steerseg::script::detail
