#include "ui/structure_contours.hpp"

#include "ui/slice_mapping.hpp"

#include <imgui.h>

namespace steerseg::ui {

namespace {

ImU32 colourOf(const glm::dvec3& c) {
    const auto byte = [](double v) { return static_cast<int>(std::clamp(v, 0.0, 1.0) * 255.0); };
    return IM_COL32(byte(c.r), byte(c.g), byte(c.b), 230);
}

} // namespace

void StructureContours::draw(const ImGuiLayer& layer, const ScreenState& screen,
                             const glm::ivec3& dims) {
    const workflow::StructureList* list = screen.structures;
    if (list == nullptr || list->items.size() < 2) {
        return;
    }
    const auto width = static_cast<float>(0.04 * layer.touchPx());
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const std::array<const std::optional<SliceView>*, 2> views{&screen.slice1, &screen.slice2};
    for (std::size_t n = 0; n < views.size(); ++n) {
        if (!*views[n]) {
            continue;
        }
        const SliceView& view = **views[n];
        Plane& plane = planes_[n];
        const int axis = view.frame.sliceAxis;
        const int index = view.frame.slice;
        if (plane.version != screen.structuresVersion || plane.axis != axis ||
            plane.index != index || plane.edges.size() != list->items.size()) {
            plane = {screen.structuresVersion, axis, index, {}};
            for (std::size_t s = 0; s < list->items.size(); ++s) {
                const workflow::Structure& st = list->items[s];
                const bool shown = s != list->active && st.info.visible && !st.mask.runs.empty();
                plane.edges.push_back(
                    shown ? planeBoundary(maskPlane(st.mask, dims, axis, index), dims, axis, index)
                          : std::vector<MaskEdge>{});
            }
        }
        const Rect& r = view.rect;
        draw->PushClipRect(ImVec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                           ImVec2(static_cast<float>(r.x + r.w), static_cast<float>(r.y + r.h)),
                           true);
        for (std::size_t s = 0; s < plane.edges.size(); ++s) {
            const ImU32 colour = colourOf(list->items[s].info.colour);
            for (const MaskEdge& e : plane.edges[s]) {
                const glm::dvec2 a = screenOfVoxel(view, e.a);
                const glm::dvec2 b = screenOfVoxel(view, e.b);
                draw->AddLine(ImVec2(static_cast<float>(a.x), static_cast<float>(a.y)),
                              ImVec2(static_cast<float>(b.x), static_cast<float>(b.y)), colour,
                              width);
            }
        }
        draw->PopClipRect();
    }
}

} // namespace steerseg::ui
