#include "ui/prompt.hpp"

#include <cfloat>
#include <imgui.h>

namespace steerseg::ui {

PromptFrame drawPrompt(const ImGuiLayer& layer, const Prompt& prompt, const Rect& panel) {
    PromptFrame out;
    if (panel.empty() || prompt.choices.empty()) {
        return out;
    }
    const auto touch = static_cast<float>(layer.touchPx());
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(panel.x), static_cast<float>(panel.y)));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(panel.w), 0.0F));
    ImGui::SetNextWindowFocus(); // above the panel, which never comes to the front
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_AlwaysAutoResize;
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.13F, 0.20F, 0.30F, 1.0F));
    if (ImGui::Begin("##steerseg_prompt", nullptr, flags)) {
        ImGui::PushFont(layer.largeFont());
        ImGui::TextWrapped("%s", prompt.title.c_str());
        ImGui::PopFont();
        ImGui::TextWrapped("%s", prompt.text.c_str());
        ImGui::Spacing();
        for (std::size_t i = 0; i < prompt.choices.size(); ++i) {
            if (ImGui::Button(prompt.choices[i].c_str(), ImVec2(-FLT_MIN, touch))) {
                out.chosen = i;
            }
            const ImVec2 lo = ImGui::GetItemRectMin();
            const ImVec2 hi = ImGui::GetItemRectMax();
            out.buttons.push_back({static_cast<int>(lo.x), static_cast<int>(lo.y),
                                   static_cast<int>(hi.x - lo.x), static_cast<int>(hi.y - lo.y)});
        }
    }
    ImGui::End();
    ImGui::PopStyleColor();
    return out;
}

} // namespace steerseg::ui
