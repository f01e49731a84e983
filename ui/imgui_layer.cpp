#include "ui/imgui_layer.hpp"

#include "gpu/gl.hpp"
#include "gpu/gl_state_guard.hpp"
#include "ui/imgui_gles3_backend.hpp"
#include "ui/layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <imgui.h>
#include <iterator>
#include <stdexcept>

namespace steerseg::ui {

namespace {

// Basic Latin and Latin-1, the dashes and the minus sign (captions, units).
const ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x2013, 0x2014, 0x2212, 0x2212, 0};
constexpr double kLargeFontScale = 1.6;

// A TrueType or OpenType file starts with one of these tags.
bool looksLikeFont(const std::vector<unsigned char>& d) {
    if (d.size() < 12) {
        return false;
    }
    const std::string tag(d.begin(), d.begin() + 4);
    return tag == std::string("\0\1\0\0", 4) || tag == "true" || tag == "OTTO";
}

std::vector<unsigned char> readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return {};
    }
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class ContextScope {
  public:
    explicit ContextScope(ImGuiContext* c) : previous_(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(c);
    }
    ~ContextScope() { ImGui::SetCurrentContext(previous_); }
    ContextScope(const ContextScope&) = delete;
    ContextScope& operator=(const ContextScope&) = delete;

  private:
    ImGuiContext* previous_;
};

} // namespace

ImGuiLayer::ImGuiLayer(const ImGuiLayerOptions& options) {
    IMGUI_CHECKVERSION();
    touchPx_ = touchTargetPx(options.touchMm, options.dpi);
    const double scale =
        std::isfinite(options.fontScale) ? std::clamp(options.fontScale, 0.5, 4.0) : 1.0;
    fontPx_ = std::clamp(std::round(touchPx_ * 0.5 * scale), 13.0, 192.0);
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // an appliance keeps no window layout between runs
    io.LogFilename = nullptr;
    io.ConfigFlags |= ImGuiConfigFlags_NoMouseCursorChange;
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.ScaleAllSizes(static_cast<float>(fontPx_ / 13.0));
    style.WindowRounding = 0.0F;
    style.FrameRounding = static_cast<float>(0.15 * fontPx_);
    style.GrabMinSize = static_cast<float>(0.6 * touchPx_);
    style.ScrollbarSize = static_cast<float>(0.5 * touchPx_);
    loadFonts(options.fontPath.empty() ? std::string(kDefaultFontPath) : options.fontPath);
    {
        gpu::GlStateGuard guard;
        backend_ = steerseg_ImGui_ImplGles3_Init("#version 300 es");
    }
    if (!backend_) {
        ImGui::DestroyContext(context_);
        context_ = nullptr;
        throw std::runtime_error("ui: Dear ImGui's GLES 3 renderer did not start");
    }
}

ImGuiLayer::~ImGuiLayer() {
    if (context_ == nullptr) {
        return;
    }
    ImGui::SetCurrentContext(context_);
    if (inFrame_) {
        ImGui::EndFrame();
    }
    {
        gpu::GlStateGuard guard;
        steerseg_ImGui_ImplGles3_Shutdown();
    }
    ImGui::DestroyContext(context_);
}

void ImGuiLayer::loadFonts(const std::string& path) {
    ImGuiIO& io = ImGui::GetIO();
    fontData_ = readFile(path);
    if (looksLikeFont(fontData_)) {
        ImFontConfig config;
        config.FontDataOwnedByAtlas = false;
        auto* data = static_cast<void*>(fontData_.data());
        const int size = static_cast<int>(fontData_.size());
        ImFont* base = io.Fonts->AddFontFromMemoryTTF(data, size, static_cast<float>(fontPx_),
                                                      &config, kGlyphRanges);
        largeFont_ = io.Fonts->AddFontFromMemoryTTF(
            data, size, static_cast<float>(std::round(fontPx_ * kLargeFontScale)), &config,
            kGlyphRanges);
        // Built here, not on the first frame, so a font stb_truetype refuses falls back too.
        if (base != nullptr && largeFont_ != nullptr && io.Fonts->Build()) {
            io.FontDefault = base;
            return;
        }
        io.Fonts->Clear();
    }
    static bool said = false;
    if (!said) {
        said = true;
        std::fprintf(stderr, "ui: font %s is missing or not a font; using ImGui's built-in font\n",
                     path.c_str());
    }
    fallbackFont_ = true;
    fontData_.clear();
    ImFontConfig config;
    config.SizePixels = static_cast<float>(fontPx_);
    io.FontDefault = io.Fonts->AddFontDefault(&config);
    ImFontConfig large;
    large.SizePixels = static_cast<float>(std::round(fontPx_ * kLargeFontScale));
    largeFont_ = io.Fonts->AddFontDefault(&large);
}

void ImGuiLayer::feed(const platform::InputEvent& event) {
    using Kind = platform::InputEvent::Kind;
    if (event.kind != Kind::PointerDown && event.kind != Kind::PointerMove &&
        event.kind != Kind::PointerUp && event.kind != Kind::Wheel) {
        return;
    }
    if (!std::isfinite(event.x) || !std::isfinite(event.y)) {
        if (event.kind != Kind::PointerUp) {
            return;
        }
    }
    constexpr std::size_t kMaxPending = 4096; // a stalled frame loop must not grow this forever
    if (pending_.size() >= kMaxPending) {
        pending_.pop_front();
    }
    pending_.push_back(event);
}

// Moves apply at once; a button change ends this frame's share of the queue, so ImGui sees
// every press and release in a frame of its own.
void ImGuiLayer::applyPointer() {
    using Kind = platform::InputEvent::Kind;
    ImGuiIO& io = ImGui::GetIO();
    io.MouseWheel = 0.0F;
    while (!pending_.empty()) {
        const platform::InputEvent e = pending_.front();
        const bool finite = std::isfinite(e.x) && std::isfinite(e.y);
        if (e.kind == Kind::Wheel) {
            pending_.pop_front();
            if (std::isfinite(e.wheel)) {
                io.MousePos = ImVec2(e.x, e.y);
                io.MouseWheel += e.wheel;
            }
            continue;
        }
        if (e.kind == Kind::PointerDown) {
            if (driver_ >= 0 && driver_ != e.pointer) {
                pending_.pop_front(); // a second finger: the gestures' business
                continue;
            }
            if (io.MouseDown[0]) {
                pending_.pop_front(); // a repeated down
                continue;
            }
            pending_.pop_front();
            driver_ = e.pointer;
            io.MousePos = ImVec2(e.x, e.y);
            io.MouseDown[0] = true;
            return;
        }
        if (e.kind == Kind::PointerUp) {
            pending_.pop_front();
            if (e.pointer != driver_) {
                continue;
            }
            if (finite) {
                io.MousePos = ImVec2(e.x, e.y);
            }
            io.MouseDown[0] = false;
            driver_ = -1;
            return;
        }
        pending_.pop_front();
        // Moves: the mouse hovering (no finger down) or the driving finger.
        if (finite && (driver_ < 0 || e.pointer == driver_)) {
            io.MousePos = ImVec2(e.x, e.y);
        }
    }
}

void ImGuiLayer::beginFrame(const glm::ivec2& screenSize, double time) {
    ImGui::SetCurrentContext(context_);
    if (inFrame_) {
        ImGui::EndFrame(); // a frame begun and never ended: close it rather than assert
    }
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(std::max(screenSize.x, 1)),
                            static_cast<float>(std::max(screenSize.y, 1)));
    io.DisplayFramebufferScale = ImVec2(1.0F, 1.0F);
    const double dt = lastTime_ < 0.0 || !(time > lastTime_) ? 1.0 / 60.0 : time - lastTime_;
    io.DeltaTime = static_cast<float>(std::clamp(dt, 1e-4, 1.0));
    if (std::isfinite(time)) {
        lastTime_ = time;
    }
    applyPointer();
    {
        // The backend creates its objects (and uploads the font) on its first frame; an
        // unpack buffer left bound would be read instead of the font's pixels.
        gpu::GlStateGuard guard;
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        steerseg_ImGui_ImplGles3_NewFrame();
    }
    ImGui::NewFrame();
    inFrame_ = true;
}

void ImGuiLayer::endFrame() {
    ImGui::SetCurrentContext(context_);
    if (!inFrame_) {
        return;
    }
    inFrame_ = false;
    ImGui::Render();
    gpu::GlStateGuard guard;
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    steerseg_ImGui_ImplGles3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wantsPointer() const {
    const ContextScope scope(context_);
    return ImGui::GetIO().WantCaptureMouse;
}

} // namespace steerseg::ui
