#include "ui/overlays.hpp"

#include "ui/view_caption.hpp"

#include <imgui.h>
#include <string>

namespace steerseg::ui {

namespace {

void caption(const Rect& rect, const std::string& text, float pad) {
    if (rect.empty() || text.empty()) {
        return;
    }
    ImDrawList* list = ImGui::GetForegroundDrawList();
    const ImVec2 at(static_cast<float>(rect.x) + pad, static_cast<float>(rect.y) + pad);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    // A dark backing keeps the caption legible over bright scan data.
    list->AddRectFilled(ImVec2(at.x - 0.5F * pad, at.y - 0.25F * pad),
                        ImVec2(at.x + size.x + 0.5F * pad, at.y + size.y + 0.25F * pad),
                        IM_COL32(0, 0, 0, 150), 0.25F * pad);
    list->AddText(at, IM_COL32(255, 255, 255, 235), text.c_str());
}

} // namespace

void drawViewCaptions(const ImGuiLayer& layer, const ScreenState& screen,
                      const workflow::Status& status) {
    if (status.state == model::State::NoScan || status.state == model::State::Loading) {
        return;
    }
    const auto pad = static_cast<float>(0.25 * layer.touchPx());
    caption(screen.layout.view3d, view3dCaption(), pad);
    if (screen.slice1) {
        caption(screen.layout.slice1,
                contourCaption(status.view.first, screen.slice1->frame, status.scan.dims), pad);
    }
    if (screen.slice2) {
        caption(screen.layout.slice2,
                speedCaption(status.view.second, screen.slice2->frame, status.scan.dims), pad);
    }
}

void drawStrokePath(const ImGuiLayer& layer, const std::vector<glm::dvec2>& path,
                    model::StrokeMode mode) {
    if (path.empty()) {
        return;
    }
    ImU32 colour = IM_COL32(80, 220, 80, 200); // add: the seeds' green
    if (mode == model::StrokeMode::Erase) {
        colour = IM_COL32(235, 70, 70, 200);
    } else if (mode == model::StrokeMode::Outside) {
        colour = IM_COL32(80, 150, 255, 200);
    }
    std::vector<ImVec2> points;
    points.reserve(path.size());
    for (const glm::dvec2& p : path) {
        points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    }
    const auto width = static_cast<float>(0.12 * layer.touchPx());
    ImDrawList* list = ImGui::GetForegroundDrawList();
    list->AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_None,
                      width);
    list->AddCircleFilled(points.back(), width, colour);
}

} // namespace steerseg::ui
