// The PACS section of the panel model (PanelModel::pacs): the search form's fields and date
// chips as the site's config lists them, Search, the results as Retrieve buttons, and a
// retrieve's progress with Cancel.
#include "ui/panel_model.hpp"

#include <algorithm>

namespace steerseg::ui {

namespace {

bool offers(const std::vector<std::string>& list, std::string_view name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

} // namespace

std::optional<PacsPanel> buildPacsPanel(const workflow::PacsView& view, const model::PacsKeys& keys,
                                        bool loadScreen) {
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
    search.keys = keys;
    p.search = PanelButton{view.searching ? "Searching...##pacs_search" : "Search##pacs_search",
                           search, false, !view.searching};
    p.searchLine = view.searchLine;
    for (std::size_t i = 0; i < view.studies.size(); ++i) {
        const workflow::PacsStudy& study = view.studies[i];
        p.results.push_back({"Retrieve " + study.label + "##pacs_study" + std::to_string(i),
                             model::RetrievePacs{"", study.studyUid, ""}, false, !view.retrieving});
    }
    return p;
}

} // namespace steerseg::ui
