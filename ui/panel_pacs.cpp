// The panel's PACS section (PanelModel::pacs; docs/dicom-network.md "The kiosk's search"): the
// query peers to choose from, the search form, the studies found each with Retrieve and Series,
// the series of one under it each with its own Retrieve, and a retrieve's progress with Cancel.
// The peers, fields and chips are the form's (Completion::Form): Panel::formTapped acts on them.
#include "ui/panel.hpp"
#include "ui/panel_drawer.hpp"

namespace steerseg::ui {

namespace drawing {

namespace {

std::vector<PanelButton> formButtons(const PacsPanel& p) {
    std::vector<PanelButton> out;
    for (const PacsPeerChoice& c : p.peers) {
        out.push_back({c.label, model::SearchPacs{}, c.chosen, true, Completion::Form});
    }
    return out;
}

void line(const std::string& text) {
    if (!text.empty()) {
        ImGui::TextWrapped("%s", text.c_str());
    }
}

} // namespace

void drawPacs(Drawer& d, const PacsPanel& p) {
    if (!p.fields.empty()) {
        if (!p.peers.empty()) {
            d.heading("Search which PACS");
            d.grid(formButtons(p), 3);
        }
        d.heading("Search the PACS (tap a field to type)");
        std::vector<PanelButton> fields;
        for (const PacsField& f : p.fields) {
            fields.push_back({f.label, model::SearchPacs{}, false, true, Completion::Form});
        }
        d.grid(fields, 2);
        std::vector<PanelButton> chips;
        for (const PacsChip& c : p.dates) {
            chips.push_back({c.label, model::SearchPacs{}, c.chosen, true, Completion::Form});
        }
        d.grid(chips, 3);
        d.grid({p.search}, 1);
        line(p.searchLine);
        for (std::size_t i = 0; i < p.results.size(); ++i) {
            d.row(p.results[i], p.seriesOf.at(i));
            if (p.seriesStudy != i) {
                continue;
            }
            // The study's series under it, each a retrieve of its own.
            d.indent(true);
            line(p.seriesLine);
            d.grid(p.series, 1);
            d.indent(false);
        }
    }
    if (p.progress) {
        d.heading("Retrieve");
        d.progress(*p.progress, p.progressText);
        line(p.retrieveLine);
        if (p.cancel) {
            d.grid({*p.cancel}, 1);
        }
    }
}

} // namespace drawing

void Panel::formTapped(const PacsPanel& p, const std::string& label) {
    for (const PacsPeerChoice& c : p.peers) {
        if (c.label == label) {
            pacsForm_.choosePeer(c.name);
        }
    }
    for (const PacsField& f : p.fields) {
        if (f.label == label) {
            editing_.closeColours();
            pacsForm_.openField(f.field);
        }
    }
    for (const PacsChip& c : p.dates) {
        if (c.label == label) {
            pacsForm_.choosePreset(c.preset);
        }
    }
}

} // namespace steerseg::ui
