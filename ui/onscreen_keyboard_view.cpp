#include "ui/onscreen_keyboard_view.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <imgui.h>

namespace steerseg::ui {

namespace {

const ImVec4 kBackground(0.11F, 0.12F, 0.14F, 1.0F);
const ImVec4 kField(0.02F, 0.02F, 0.03F, 1.0F);
const ImVec4 kOn(0.85F, 0.62F, 0.10F, 1.0F); // shift or caps lock held: the panel's toggles
const ImVec4 kOk(0.18F, 0.45F, 0.26F, 1.0F); // the panel's next step
const ImVec4 kProblem(1.0F, 0.45F, 0.40F, 1.0F);

Rect itemRect() {
    const ImVec2 lo = ImGui::GetItemRectMin();
    const ImVec2 hi = ImGui::GetItemRectMax();
    return {static_cast<int>(lo.x), static_cast<int>(lo.y), static_cast<int>(hi.x - lo.x),
            static_cast<int>(hi.y - lo.y)};
}

// The text as typed, large, with a caret at its end, on a dark field the area's width.
void field(const ImGuiLayer& layer, const std::string& text, float height) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float w = ImGui::GetContentRegionAvail().x;
    list->AddRectFilled(at, ImVec2(at.x + w, at.y + height), ImGui::GetColorU32(kField),
                        ImGui::GetStyle().FrameRounding);
    ImGui::PushFont(layer.largeFont());
    const std::string shown = text + "_";
    const ImVec2 size = ImGui::CalcTextSize(shown.c_str());
    const float pad = ImGui::GetStyle().FramePadding.x;
    // A name longer than the field shows its end, where the typing is.
    const float x = size.x + 2.0F * pad > w ? at.x + w - pad - size.x : at.x + pad;
    list->PushClipRect(at, ImVec2(at.x + w, at.y + height), true);
    list->AddText(ImVec2(x, at.y + 0.5F * (height - size.y)), IM_COL32_WHITE, shown.c_str());
    list->PopClipRect();
    ImGui::PopFont();
    ImGui::Dummy(ImVec2(w, height));
}

} // namespace

KeyboardFrame drawKeyboard(const ImGuiLayer& layer, const OnscreenKeyboard& keyboard,
                           const KeyboardCaption& caption, const Rect& area) {
    KeyboardFrame out;
    if (area.empty()) {
        return out;
    }
    const auto touch = static_cast<float>(layer.touchPx());
    const ImGuiStyle& style = ImGui::GetStyle();
    const float largeSize =
        layer.largeFont() != nullptr ? layer.largeFont()->FontSize : ImGui::GetFontSize();
    const float fieldHeight = std::max(touch, 1.4F * largeSize);
    const float keyHeight = 1.2F * touch;
    // Sized from its rows, not fitted by ImGui: an auto-fitted window is hidden for its first
    // frame, and the kiosk may draw no other before the next tap, which would then be lost.
    const auto rows = static_cast<float>(keyboard.rows().size());
    const float height = 2.0F * style.WindowPadding.y + 2.0F * ImGui::GetTextLineHeight() +
                         fieldHeight + rows * keyHeight + (rows + 2.0F) * style.ItemSpacing.y;
    const auto bottom = static_cast<float>(area.y + area.h);
    const float top = std::max(static_cast<float>(area.y), bottom - std::ceil(height));
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.x), top));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(area.w), bottom - top));
    ImGui::SetNextWindowFocus(); // above the panel, which never comes to the front
    constexpr ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    ImGui::PushStyleColor(ImGuiCol_WindowBg, kBackground);
    if (ImGui::Begin("##steerseg_keyboard", nullptr, flags)) {
        ImGui::TextUnformatted(caption.title.c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("(%zu of %zu)", keyboard.text().size(), keyboard.maxLength());
        field(layer, keyboard.text(), fieldHeight);
        // The line is there whether or not a problem is: the keys do not move under a finger.
        ImGui::PushStyleColor(ImGuiCol_Text, kProblem);
        ImGui::TextUnformatted(caption.problem.empty() ? " " : caption.problem.c_str());
        ImGui::PopStyleColor();

        const float sp = ImGui::GetStyle().ItemSpacing.x;
        const float avail = ImGui::GetContentRegionAvail().x;
        // One key width for every row, from the row that needs the most room.
        float unit = FLT_MAX;
        for (const std::vector<Key>& row : keyboard.rows()) {
            double units = 0.0;
            for (const Key& k : row) {
                units += k.width;
            }
            const float gaps = sp * static_cast<float>(row.size() - 1);
            unit = std::min(unit, (avail - gaps) / static_cast<float>(units));
        }
        unit = std::max(unit, touch);
        for (const std::vector<Key>& row : keyboard.rows()) {
            float rowWidth = sp * static_cast<float>(row.size() - 1);
            for (const Key& k : row) {
                rowWidth += static_cast<float>(k.width) * unit;
            }
            ImGui::SetCursorPosX(ImGui::GetCursorPosX() +
                                 std::max(0.0F, 0.5F * (avail - rowWidth)));
            for (std::size_t i = 0; i < row.size(); ++i) {
                const Key& k = row[i];
                if (i > 0) {
                    ImGui::SameLine();
                }
                const bool on = (k.kind == KeyKind::Shift && keyboard.shift()) ||
                                (k.kind == KeyKind::CapsLock && keyboard.capsLock());
                const bool coloured = on || k.kind == KeyKind::Ok;
                if (coloured) {
                    const ImVec4& c = on ? kOn : kOk;
                    ImGui::PushStyleColor(ImGuiCol_Button, c);
                    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, c);
                }
                const std::string name = keyName(k);
                const std::string label = keyboard.label(k) + "##key" + name;
                if (ImGui::Button(label.c_str(),
                                  ImVec2(static_cast<float>(k.width) * unit, keyHeight))) {
                    out.pressed = k;
                }
                if (coloured) {
                    ImGui::PopStyleColor(2);
                }
                out.keys[name] = itemRect();
            }
        }
        const ImVec2 pos = ImGui::GetWindowPos();
        const ImVec2 size = ImGui::GetWindowSize();
        out.window = {static_cast<int>(pos.x), static_cast<int>(pos.y), static_cast<int>(size.x),
                      static_cast<int>(size.y)};
    }
    ImGui::End();
    ImGui::PopStyleColor();
    return out;
}

} // namespace steerseg::ui
