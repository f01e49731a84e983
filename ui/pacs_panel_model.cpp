// The PACS section of the panel model (PanelModel::pacs): the choice of query peer, the search
// form's fields and date chips as the site's config lists them, Search, the results as Retrieve
// and Series buttons, a study's series each with its Retrieve, and a retrieve's progress with
// Cancel.
#include "ui/panel_model.hpp"

#include <algorithm>

namespace steerseg::ui {

namespace {

bool offers(const std::vector<std::string>& list, std::string_view name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

} // namespace

std::string pacsSeriesLabel(const workflow::PacsSeries& series) {
    std::string line;
    for (const std::string& part :
         {series.modality, series.number.empty() ? "" : "#" + series.number, series.description,
          series.images < 0 ? "" : "(" + std::to_string(series.images) + " images)"}) {
        if (!part.empty()) {
            line += (line.empty() ? "" : "  ") + part;
        }
    }
    return line.empty() ? "series" : line;
}

std::optional<PacsPanel> buildPacsPanel(const workflow::PacsView& view, const model::PacsKeys& keys,
                                        const std::string& peer, bool loadScreen) {
    if (view.peers.empty() || (!loadScreen && !view.retrieving)) {
        return std::nullopt;
    }
    PacsPanel p;
    if (view.retrieving || view.retrieves > 0) {
        p.progress = view.expected > 0 ? static_cast<double>(view.received) / view.expected : -1.0;
        p.progressText = std::to_string(view.received) +
                         (view.expected > 0 ? " of " + std::to_string(view.expected) : "") +
                         " images";
        p.retrieveLine = view.retrieveLine;
        if (view.retrieving) {
            p.cancel = PanelButton{"Cancel retrieve##pacs_cancel", model::CancelRetrieve{}};
        }
    }
    if (!loadScreen) {
        return p; // the progress only, while a retrieve runs on
    }
    const std::string chosen = offers(view.peers, peer) ? peer : view.peers.front();
    if (view.peers.size() > 1) {
        for (const std::string& name : view.peers) {
            p.peers.push_back({name, name + "##pacs_peer_" + name, name == chosen});
        }
    }
    for (const std::string& name : view.fields) {
        const std::optional<model::SearchField> field = model::searchFieldFromName(name);
        if (!field) {
            continue;
        }
        if (*field == model::SearchField::StudyDate) {
            for (const std::string& preset : view.datePresets) {
                if (const auto known = model::datePresetFromName(preset)) {
                    p.dates.push_back(
                        {preset,
                         std::string(model::datePresetLabel(*known)) + "##pacs_date_" + preset,
                         keys.studyDate == preset});
                }
            }
        }
        // A date typed or a chip's: the chip is its own label, so the field shows only a typed one.
        const std::string& value = keyOf(keys, *field);
        const bool chip =
            *field == model::SearchField::StudyDate && offers(view.datePresets, value);
        p.fields.push_back({*field, std::string(model::searchFieldLabel(*field)) + ": " +
                                        (value.empty() || chip ? "-" : value) + "##pacs_" + name});
    }
    model::SearchPacs search;
    search.peer = chosen;
    search.keys = keys;
    p.search = PanelButton{view.searching ? "Searching...##pacs_search" : "Search##pacs_search",
                           search, false, !view.searching};
    p.searchLine = view.searchLine;
    for (std::size_t i = 0; i < view.studies.size(); ++i) {
        const workflow::PacsStudy& study = view.studies[i];
        const std::string n = std::to_string(i);
        p.results.push_back({"Retrieve " + study.label + "##pacs_study" + n,
                             model::RetrievePacs{view.studiesPeer, study.studyUid, ""}, false,
                             !view.retrieving});
        const bool listed = !view.seriesStudyUid.empty() && study.studyUid == view.seriesStudyUid;
        p.seriesOf.push_back({"Series##pacs_series_of" + n,
                              model::ListPacsSeries{view.studiesPeer, study.studyUid}, listed});
        if (listed && !p.seriesStudy) {
            p.seriesStudy = i;
        }
    }
    if (!p.seriesStudy) {
        return p; // no listing, or one of a study this search did not find
    }
    p.seriesLine = view.seriesLine;
    for (std::size_t k = 0; k < view.series.size(); ++k) {
        const workflow::PacsSeries& s = view.series[k];
        p.series.push_back({"Retrieve " + pacsSeriesLabel(s) + "##pacs_series" + std::to_string(k),
                            model::RetrievePacs{view.seriesPeer, view.seriesStudyUid, s.seriesUid},
                            false, !view.retrieving});
    }
    return p;
}

} // namespace steerseg::ui
