#include "ui/panel.hpp"

#include "ui/panel_drawer.hpp"

#include <algorithm>
#include <imgui.h>
#include <imgui_internal.h> // GetActiveID, the window's MoveId: touch scrolling

namespace steerseg::ui {

using drawing::Drawer;
using model::Action;

std::vector<Action> Panel::draw(const ImGuiLayer& layer, const workflow::Status& status,
                                const Rect& rect, const std::vector<std::string>& scans) {
    std::vector<Action> actions;
    rects_.clear();
    editing_.follow(status);
    if (rect.empty()) {
        return actions;
    }
    const PanelModel model =
        buildPanelModel(status, scans,
                        PanelEditors{editing_.renameOpen(), editing_.coloursOpen(),
                                     pacsForm_.keys(), pacsForm_.peer()});
    pacsForm_.follow(status.pacs, model.pacs && !model.pacs->fields.empty());
    std::vector<PanelButton> completions;
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(rect.x), static_cast<float>(rect.y)));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(rect.w), static_cast<float>(rect.h)));
    constexpr ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar;
    if (ImGui::Begin("##steerseg_panel", nullptr, flags)) {
        // No scrollbar, so no widget moves when one appears; the wheel scrolls, and (ImGui
        // 1.86 knows no touch scrolling) so does a finger dragging the panel's background.
        // A press on the background makes the window's move id active (even with NoMove).
        if (ImGui::GetActiveID() == ImGui::GetCurrentWindow()->MoveId &&
            ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
            ImGui::SetScrollY(ImGui::GetScrollY() - ImGui::GetIO().MouseDelta.y);
        }
        Drawer d(layer, rects_, actions, completions);
        // A wide panel (below the views on a portrait screen) puts the state and readouts
        // beside the controls instead of scrolling them away.
        const bool twoColumns =
            rect.w > rect.h && rect.w >= 8 * layer.touchPx() && ImGui::BeginTable("##columns", 2);
        if (twoColumns) {
            ImGui::TableNextColumn();
        }
        d.banner(model, status.state);
        if (!model.receivedNote.empty()) {
            ImGui::TextWrapped("%s", model.receivedNote.c_str());
        }
        if (model.progress) {
            d.progress(*model.progress);
        }
        if (!model.nav.empty()) {
            d.grid(model.nav, static_cast<int>(model.nav.size()), &drawing::kNav);
        }
        d.readouts(model.readouts);
        if (!model.tools.empty()) {
            d.heading("Actions");
            d.grid(model.tools, 3);
        }
        if (twoColumns) {
            ImGui::TableNextColumn();
        }
        if (!model.params.empty()) {
            d.heading("Parameters (tap a name for the knob)");
            for (const ParamRow& row : model.params) {
                d.param(row);
            }
        }
        if (!model.speeds.empty()) {
            d.heading("Speed");
            d.grid(model.speeds, 3);
            if (!model.examples.empty()) {
                ImGui::TextWrapped("Examples: %s", model.examples.c_str());
            }
            if (!model.speedNote.empty()) {
                ImGui::TextWrapped("%s", model.speedNote.c_str());
            }
            if (!model.exampleTools.empty()) {
                d.grid(model.exampleTools, 2);
            }
        }
        if (!model.presets.empty()) {
            d.heading("Presets");
            d.grid(model.presets, 2);
        }
        if (model.window) {
            d.heading("Window");
            d.window(*model.window);
        }
        if (!model.measurements.empty()) {
            d.heading("Measurements (axial long x short axis, longest 3D)");
            d.measurements(model.measurements);
        }
        if (!model.structures.empty()) {
            d.heading("Structures (tap one to steer it)");
            d.grid(model.structures, 3);
            d.grid(model.structureTools, 2);
            if (d.grid(model.colours, 4)) {
                editing_.closeColours(); // one tap picks
            }
            d.grid(model.newStructures, 2);
        }
        if (!model.views.empty()) {
            d.heading("Contour view / speed view");
            d.grid(model.views, 3);
        }
        if (!model.received.empty()) {
            d.heading("Received (newest first)");
            d.grid(model.received, 1);
        }
        if (model.pacs) {
            drawing::drawPacs(d, *model.pacs);
        }
        if (!model.scans.empty()) {
            d.heading("Scans");
            d.grid(model.scans, 1);
        }
        if (!model.outbox.empty()) {
            d.heading("Waiting to be sent");
            for (const std::string& line : model.outbox) {
                ImGui::TextWrapped("%s", line.c_str());
            }
        }
        if (!model.devices.empty()) {
            d.heading("Controllers");
            d.devices(model.devices);
        }
        if (twoColumns) {
            ImGui::EndTable();
        }
    }
    ImGui::End();
    for (const PanelButton& b : completions) {
        if (b.completion == Completion::Form && model.pacs) {
            formTapped(*model.pacs, b.label);
            continue;
        }
        const auto* edit = std::get_if<model::EditStructure>(&b.action);
        if (edit == nullptr) {
            continue;
        }
        if (b.completion == Completion::Name) {
            editing_.openRename(edit->name);
        } else if (b.completion == Completion::Colour) {
            editing_.toggleColours(edit->name);
        }
    }
    return actions;
}

std::vector<Action> Panel::drawKeyboard(const ImGuiLayer& layer, const Rect& area) {
    std::vector<Action> actions;
    keyboard_ = {};
    if (const OnscreenKeyboard* search = pacsForm_.keyboard();
        search != nullptr && !editing_.renameOpen()) {
        const std::string title =
            "Search: " + std::string(model::searchFieldLabel(*pacsForm_.editing()));
        keyboard_ = ui::drawKeyboard(layer, *search, {title, ""}, area);
        if (keyboard_.pressed) {
            pacsForm_.press(*keyboard_.pressed);
        }
        return actions;
    }
    const OnscreenKeyboard* keyboard = editing_.keyboard();
    if (keyboard == nullptr) {
        return actions;
    }
    keyboard_ = ui::drawKeyboard(
        layer, *keyboard, {"Rename '" + editing_.renaming() + "'", editing_.problem()}, area);
    if (keyboard_.pressed) {
        if (std::optional<Action> rename = editing_.press(*keyboard_.pressed)) {
            actions.push_back(std::move(*rename));
        }
    }
    return actions;
}

std::optional<Rect> Panel::widgetRect(std::string_view label) const {
    const auto it = rects_.find(label);
    if (it == rects_.end()) {
        return std::nullopt;
    }
    return it->second;
}

} // namespace steerseg::ui
