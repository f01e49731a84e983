#include "ui/overlays.hpp"

#include "ui/view_caption.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <optional>
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

namespace {

// The box's twelve edges over the 3D view, through the camera that drew it: the outer faces of
// its voxels. Drawn over the picture (not hidden behind the surface): the UI has no depth.
void wireBox(ImDrawList* list, const ScreenState::VolumeView& view, const model::Box& box,
             ImU32 colour, float width) {
    if (view.rect.empty() || view.renderSize.x <= 0 || view.renderSize.y <= 0) {
        return;
    }
    const glm::dvec2 scale = glm::dvec2(view.rect.w, view.rect.h) / glm::dvec2(view.renderSize);
    std::array<std::optional<ImVec2>, 8> corner;
    for (int c = 0; c < 8; ++c) {
        glm::dvec3 index;
        for (int a = 0; a < 3; ++a) {
            index[a] = (c & (1 << a)) != 0 ? box.hi[a] + 0.5 : box.lo[a] - 0.5;
        }
        const glm::dvec3 p =
            view.camera.project(view.geometry.indexToWorld(index), view.renderSize);
        if (p.z > 0.0 && std::isfinite(p.x) && std::isfinite(p.y)) { // not behind the eye
            corner[static_cast<std::size_t>(c)] =
                ImVec2(static_cast<float>(view.rect.x + p.x * scale.x),
                       static_cast<float>(view.rect.y + p.y * scale.y));
        }
    }
    list->PushClipRect(ImVec2(static_cast<float>(view.rect.x), static_cast<float>(view.rect.y)),
                       ImVec2(static_cast<float>(view.rect.x + view.rect.w),
                              static_cast<float>(view.rect.y + view.rect.h)),
                       true);
    for (int c = 0; c < 8; ++c) {
        for (const int bit : {1, 2, 4}) {
            const auto& a = corner[static_cast<std::size_t>(c)];
            const auto& b = corner[static_cast<std::size_t>(c | bit)];
            if ((c & bit) == 0 && a && b) {
                list->AddLine(*a, *b, colour, width);
            }
        }
    }
    list->PopClipRect();
}

} // namespace

void drawMeasuredDiameters(const ImGuiLayer& layer, const ScreenState& screen,
                           const workflow::Status& status) {
    if (status.measurements.empty()) {
        return;
    }
    const auto width = static_cast<float>(0.05 * layer.touchPx());
    ImDrawList* list = ImGui::GetForegroundDrawList();
    for (const std::optional<SliceView>* view : {&screen.slice1, &screen.slice2}) {
        if (!*view) {
            continue;
        }
        const SliceView& v = **view;
        const Rect& r = v.rect;
        list->PushClipRect(ImVec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                           ImVec2(static_cast<float>(r.x + r.w), static_cast<float>(r.y + r.h)),
                           true);
        for (const workflow::StructureMeasured& m : status.measurements) {
            const AxialDiameters& a = m.measured.axial;
            if (!m.visible || v.frame.sliceAxis != a.sliceAxis || v.frame.slice != a.slice) {
                continue;
            }
            const auto byte = [](double c) {
                return static_cast<int>(std::clamp(c, 0.0, 1.0) * 255);
            };
            const ImU32 colour =
                IM_COL32(byte(m.colour.r), byte(m.colour.g), byte(m.colour.b), 255);
            int n = 0;
            for (const MeasuredLine* line : {&a.longest, &a.perpendicular}) {
                const glm::dvec2 p = screenOfVoxel(v, line->index[0]);
                const glm::dvec2 q = screenOfVoxel(v, line->index[1]);
                const ImVec2 from(static_cast<float>(p.x), static_cast<float>(p.y));
                const ImVec2 to(static_cast<float>(q.x), static_cast<float>(q.y));
                list->AddLine(from, to, colour, n == 0 ? width : 0.6F * width);
                char text[32];
                std::snprintf(text, sizeof text, "%.1f mm", line->lengthMm);
                list->AddText(ImVec2(0.5F * (from.x + to.x), 0.5F * (from.y + to.y)), colour, text);
                ++n;
            }
        }
        list->PopClipRect();
    }
}

void drawBoxes(const ImGuiLayer& layer, const ScreenState& screen, const workflow::Status& status,
               const std::optional<model::Box>& draft) {
    if (!status.box && !draft) {
        return;
    }
    const auto width = static_cast<float>(0.06 * layer.touchPx());
    ImDrawList* list = ImGui::GetForegroundDrawList();
    if (screen.view3d) {
        if (status.box) {
            wireBox(list, *screen.view3d, *status.box, IM_COL32(255, 150, 30, 230), width);
        }
        if (draft) {
            wireBox(list, *screen.view3d, *draft, IM_COL32(255, 210, 140, 240), width);
        }
    }
    for (const std::optional<SliceView>* view : {&screen.slice1, &screen.slice2}) {
        if (!*view) {
            continue;
        }
        const Rect& r = (*view)->rect;
        // A box beyond the zoomed view's picture stays within it.
        list->PushClipRect(ImVec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                           ImVec2(static_cast<float>(r.x + r.w), static_cast<float>(r.y + r.h)),
                           true);
        const auto rect = [&](const model::Box& box, ImU32 line, ImU32 fill) {
            if (const std::optional<ScreenBox> s = boxOnScreen(**view, box)) {
                const ImVec2 lo(static_cast<float>(s->min.x), static_cast<float>(s->min.y));
                const ImVec2 hi(static_cast<float>(s->max.x), static_cast<float>(s->max.y));
                if (fill != 0) {
                    list->AddRectFilled(lo, hi, fill);
                }
                list->AddRect(lo, hi, line, 0.0F, ImDrawFlags_None, width);
            }
        };
        if (status.box) {
            rect(*status.box, IM_COL32(255, 150, 30, 230), 0);
        }
        if (draft) {
            rect(*draft, IM_COL32(255, 210, 140, 240), IM_COL32(255, 150, 30, 50));
        }
        list->PopClipRect();
    }
}

} // namespace steerseg::ui
