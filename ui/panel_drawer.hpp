#pragma once

// How the panel draws what its model offers (ui/panel): buttons of at least the touch target's
// size, in grids and rows, progress bars, readouts and tables, each widget's rectangle recorded
// by its label for taps by tests and scripts. Shared by panel.cpp and the PACS section's
// panel_pacs.cpp; only they include it (it needs an ImGui frame).
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"
#include "ui/panel_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <map>
#include <string>
#include <vector>

namespace steerseg::ui::drawing {

using model::Action;

inline const ImVec4 kActive(0.85F, 0.62F, 0.10F, 1.0F); // the selected parameter, toggles on
inline const ImVec4 kBannerOk(0.16F, 0.36F, 0.58F, 1.0F);
inline const ImVec4 kBannerRun(0.14F, 0.50F, 0.22F, 1.0F);
inline const ImVec4 kBannerError(0.70F, 0.14F, 0.12F, 1.0F);
inline const ImVec4 kErrorText(1.0F, 0.45F, 0.40F, 1.0F);
inline const ImVec4 kNav(0.18F, 0.45F, 0.26F, 1.0F); // the workflow's next and previous step

// A swatch's text: dark on a light colour, white on a dark one.
inline ImVec4 textOn(const glm::dvec3& c) {
    const double luma = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
    return luma > 0.55 ? ImVec4(0.05F, 0.05F, 0.05F, 1.0F) : ImVec4(1.0F, 1.0F, 1.0F, 1.0F);
}

class Drawer {
  public:
    Drawer(const ImGuiLayer& layer, std::map<std::string, Rect, std::less<>>& rects,
           std::vector<Action>& actions, std::vector<PanelButton>& completions)
        : layer_(layer), rects_(rects), actions_(actions), completions_(completions),
          touch_(static_cast<float>(layer.touchPx())) {}

    void banner(const PanelModel& m, model::State state) {
        const ImVec4 colour = m.error                           ? kBannerError
                              : state == model::State::Evolving ? kBannerRun
                                                                : kBannerOk;
        ImDrawList* list = ImGui::GetWindowDrawList();
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float w = ImGui::GetContentRegionAvail().x;
        const float h = std::max(touch_, largeSize() * 1.5F);
        list->AddRectFilled(at, ImVec2(at.x + w, at.y + h), ImGui::GetColorU32(colour),
                            ImGui::GetStyle().FrameRounding);
        ImGui::PushFont(layer_.largeFont());
        const ImVec2 text = ImGui::CalcTextSize(m.banner.c_str());
        list->AddText(ImVec2(at.x + 0.5F * (w - text.x), at.y + 0.5F * (h - text.y)),
                      IM_COL32_WHITE, m.banner.c_str());
        ImGui::PopFont();
        ImGui::Dummy(ImVec2(w, h));
        for (const std::string* alarm : {&m.auditAlarm, &m.gpuAlarm}) {
            if (!alarm->empty()) {
                ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
                ImGui::TextWrapped("%s", alarm->c_str());
                ImGui::PopStyleColor();
            }
        }
        if (!m.scanName.empty()) {
            ImGui::TextDisabled("%s", m.scanName.c_str());
        }
        ImGui::TextWrapped("%s", m.hint.c_str());
        if (!m.message.empty()) {
            if (m.error) {
                ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
            }
            ImGui::TextWrapped("%s", m.message.c_str());
            if (m.error) {
                ImGui::PopStyleColor();
            }
        }
    }

    void progress(double fraction) {
        const bool known = fraction >= 0.0 && std::isfinite(fraction);
        const double shown = known ? std::min(fraction, 1.0) : 0.0;
        char overlay[32];
        if (known) {
            std::snprintf(overlay, sizeof overlay, "%.0f %%", 100.0 * shown);
        } else {
            std::snprintf(overlay, sizeof overlay, "reading...");
        }
        ImGui::ProgressBar(static_cast<float>(shown), ImVec2(-FLT_MIN, touch_), overlay);
    }

    // A retrieve's bar: the images received of those expected, or how many so far while the
    // PACS has not said (`fraction` < 0).
    void progress(double fraction, const std::string& text) {
        const double shown =
            fraction >= 0.0 && std::isfinite(fraction) ? std::min(fraction, 1.0) : 0.0;
        ImGui::ProgressBar(static_cast<float>(shown), ImVec2(-FLT_MIN, touch_), text.c_str());
        record("##pacs_progress");
    }

    // A small line per controller, so a knob that does nothing shows why at a glance.
    void devices(const std::vector<Readout>& items) {
        if (items.empty() || !ImGui::BeginTable("##devices", 2)) {
            return;
        }
        for (const Readout& item : items) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", item.label.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(item.value.c_str());
        }
        ImGui::EndTable();
    }

    // Two label/value pairs a row, the values large.
    void readouts(const std::vector<Readout>& items) {
        if (items.empty() || !ImGui::BeginTable("##readouts", 4)) {
            return;
        }
        ImGui::TableSetupColumn("##l1", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("##v1", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("##l2", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("##v2", ImGuiTableColumnFlags_WidthStretch);
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (i % 2 == 0) {
                ImGui::TableNextRow();
            }
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", items[i].label.c_str());
            ImGui::TableNextColumn();
            ImGui::PushFont(layer_.largeFont());
            ImGui::TextUnformatted(items[i].value.c_str());
            ImGui::PopFont();
        }
        ImGui::EndTable();
    }

    // One row a structure: its name, then its figures.
    void measurements(const std::vector<PanelModel::MeasurementRow>& rows) {
        if (!ImGui::BeginTable("##measurements", 5, ImGuiTableFlags_RowBg)) {
            return;
        }
        for (const PanelModel::MeasurementRow& r : rows) {
            ImGui::TableNextRow();
            for (const std::string* cell : {&r.name, &r.volume, &r.axes, &r.longest, &r.values}) {
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(cell->c_str());
            }
        }
        ImGui::EndTable();
    }

    // [name] [-] [slider] [+]: the name selects the parameter for the knob.
    void param(const ParamRow& row) {
        const std::string id = paramId(row.param);
        // Tighter gaps than elsewhere: four targets share the row.
        const float sp = std::min(ImGui::GetStyle().ItemSpacing.x, 0.12F * touch_);
        ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(sp, ImGui::GetStyle().ItemSpacing.y));
        // A narrow panel (high DPI) gives the name what the other three targets leave.
        const float rest = ImGui::GetContentRegionAvail().x - 3.0F * (touch_ + sp);
        const float nameW = std::max(touch_, std::min(1.6F * touch_, rest));
        button({row.label + "##select" + id, model::SelectParam{row.param}, row.selected},
               ImVec2(nameW, touch_), "select##" + id);
        ImGui::SameLine();
        button({"-##" + id, model::NudgeParam{row.param, -1.0}}, ImVec2(touch_, touch_));
        ImGui::SameLine();
        double value = std::clamp(row.value, row.range.min, row.range.max);
        ImGui::SetNextItemWidth(std::max(touch_, ImGui::GetContentRegionAvail().x - touch_ - sp));
        const float padY = std::max(0.0F, 0.5F * (touch_ - ImGui::GetFontSize()));
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding,
                            ImVec2(ImGui::GetStyle().FramePadding.x, padY));
        const std::string slider = "##slider" + id;
        const char* format = row.param == model::Param::Alpha ? "%.2f" : "%.1f";
        if (ImGui::SliderScalar(slider.c_str(), ImGuiDataType_Double, &value, &row.range.min,
                                &row.range.max, format)) {
            actions_.emplace_back(model::SetParam{row.param, value});
        }
        ImGui::PopStyleVar();
        record(slider);
        ImGui::SameLine();
        button({"+##" + id, model::NudgeParam{row.param, 1.0}}, ImVec2(touch_, touch_));
        ImGui::PopStyleVar();
    }

    void window(const WindowRow& w) {
        const float padY = std::max(0.0F, 0.5F * (touch_ - ImGui::GetFontSize()));
        ImGui::PushStyleVar(ImGuiStyleVar_FramePadding,
                            ImVec2(ImGui::GetStyle().FramePadding.x, padY));
        double level = w.level;
        double width = w.width;
        const double widthMin = 1.0;
        const double widthMax = std::max(w.max - w.min, 2.0);
        ImGui::SetNextItemWidth(-FLT_MIN);
        const bool a = ImGui::SliderScalar("##level", ImGuiDataType_Double, &level, &w.min, &w.max,
                                           "level %.0f");
        record("##level");
        ImGui::SetNextItemWidth(-FLT_MIN);
        const bool b = ImGui::SliderScalar("##width", ImGuiDataType_Double, &width, &widthMin,
                                           &widthMax, "width %.0f");
        record("##width");
        ImGui::PopStyleVar();
        if (a || b) {
            actions_.emplace_back(model::SetWindow{level, width});
        }
    }

    // Buttons in rows of up to `perRow`, each at least a touch target wide. Whether one was
    // pressed.
    bool grid(const std::vector<PanelButton>& buttons, int perRow, const ImVec4* colour = nullptr) {
        const float sp = ImGui::GetStyle().ItemSpacing.x;
        const float avail = ImGui::GetContentRegionAvail().x;
        const int fit = std::max(1, static_cast<int>((avail + sp) / (touch_ + sp)));
        const int n = std::max(1, std::min(perRow, fit));
        const float w =
            std::max(touch_, (avail - sp * static_cast<float>(n - 1)) / static_cast<float>(n));
        bool pressed = false;
        for (std::size_t i = 0; i < buttons.size(); ++i) {
            if (i % static_cast<std::size_t>(n) != 0) {
                ImGui::SameLine();
            }
            if (colour != nullptr) {
                ImGui::PushStyleColor(ImGuiCol_Button, *colour);
            }
            pressed = button(buttons[i], ImVec2(w, touch_)) || pressed;
            if (colour != nullptr) {
                ImGui::PopStyleColor();
            }
        }
        return pressed;
    }

    // One wide button and a narrow one (a touch target and a half) beside it on its right:
    // a result and what else it offers.
    void row(const PanelButton& wide, const PanelButton& narrow) {
        const float sp = ImGui::GetStyle().ItemSpacing.x;
        const float narrowW = 1.6F * touch_;
        const float wideW = std::max(touch_, ImGui::GetContentRegionAvail().x - narrowW - sp);
        button(wide, ImVec2(wideW, touch_));
        ImGui::SameLine();
        button(narrow, ImVec2(narrowW, touch_));
    }

    // Indents what follows by half a touch target (a study's series under it), or undoes it.
    void indent(bool in) {
        if (in) {
            ImGui::Indent(0.5F * touch_);
        } else {
            ImGui::Unindent(0.5F * touch_);
        }
    }

    void heading(const char* text) {
        ImGui::Spacing();
        ImGui::TextDisabled("%s", text);
    }

  private:
    static std::string paramId(model::Param p) {
        switch (p) {
        case model::Param::T:
            return "T";
        case model::Param::Eps:
            return "eps";
        case model::Param::Alpha:
            return "alpha";
        case model::Param::Radius:
            return "radius";
        }
        return "?";
    }

    float largeSize() const {
        return layer_.largeFont() != nullptr ? layer_.largeFont()->FontSize : ImGui::GetFontSize();
    }

    void record(const std::string& label) {
        const ImVec2 lo = ImGui::GetItemRectMin();
        const ImVec2 hi = ImGui::GetItemRectMax();
        rects_[label] = Rect{static_cast<int>(lo.x), static_cast<int>(lo.y),
                             static_cast<int>(hi.x - lo.x), static_cast<int>(hi.y - lo.y)};
    }

    bool button(const PanelButton& b, const ImVec2& size, const std::string& key = {}) {
        ImGui::BeginDisabled(!b.enabled);
        int colours = 0;
        int vars = 0;
        if (b.swatch) {
            // A colour: the button is that colour; the highlighted one (the structure's own,
            // an open palette) is framed.
            const ImVec4 c(static_cast<float>(b.swatch->r), static_cast<float>(b.swatch->g),
                           static_cast<float>(b.swatch->b), 1.0F);
            ImGui::PushStyleColor(ImGuiCol_Button, c);
            ImGui::PushStyleColor(ImGuiCol_ButtonHovered, c);
            ImGui::PushStyleColor(ImGuiCol_ButtonActive, c);
            ImGui::PushStyleColor(ImGuiCol_Text, textOn(*b.swatch));
            colours = 4;
            if (b.active) {
                ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1.0F, 1.0F, 1.0F, 1.0F));
                ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, 0.1F * touch_);
                ++colours;
                ++vars;
            }
        } else if (b.active) {
            ImGui::PushStyleColor(ImGuiCol_Button, kActive);
            ImGui::PushStyleColor(ImGuiCol_ButtonHovered, kActive);
            colours = 2;
        }
        const bool pressed = ImGui::Button(b.label.c_str(), size);
        if (vars > 0) {
            ImGui::PopStyleVar(vars);
        }
        if (colours > 0) {
            ImGui::PopStyleColor(colours);
        }
        ImGui::EndDisabled();
        record(key.empty() ? b.label : key);
        if (pressed && b.enabled) {
            if (b.completion == Completion::None) {
                actions_.push_back(b.action);
            } else {
                completions_.push_back(b); // the panel opens what completes it
            }
        }
        return pressed && b.enabled;
    }

    const ImGuiLayer& layer_;
    std::map<std::string, Rect, std::less<>>& rects_;
    std::vector<Action>& actions_;
    std::vector<PanelButton>& completions_;
    float touch_;
};

// The search form, the results with their series and a retrieve's progress (PanelModel::pacs):
// panel_pacs.cpp.
void drawPacs(Drawer& d, const PacsPanel& p);

} // namespace steerseg::ui::drawing
