#include "platform/window/window_display.hpp"

#include "platform/window/sdl_input.hpp"

#include <GLES3/gl31.h>
#include <SDL.h>
#include <chrono>
#include <cstdio>
#include <string>

namespace steerseg::platform {

namespace {

std::string sdlError() {
    const char* error = SDL_GetError();
    return error != nullptr && *error != '\0' ? error : "no reason given";
}

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// "OpenGL ES 3.1 Mesa ..." -> true when it is ES 3.1 or newer.
bool isEs31OrNewer(const char* version) {
    int major = 0;
    int minor = 0;
    return version != nullptr && std::sscanf(version, "OpenGL ES %d.%d", &major, &minor) == 2 &&
           (major > 3 || (major == 3 && minor >= 1));
}

class WindowDisplay final : public Display {
  public:
    explicit WindowDisplay(const DisplayOptions& options) {
        if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
            throw DisplayError("window: SDL_Init(VIDEO) failed: " + sdlError());
        }
        videoInitialised_ = true;
        try {
            open(options);
        } catch (...) {
            close();
            throw;
        }
    }
    ~WindowDisplay() override { close(); }
    WindowDisplay(const WindowDisplay&) = delete;
    WindowDisplay& operator=(const WindowDisplay&) = delete;

    [[nodiscard]] const DisplayInfo& info() const override { return info_; }
    [[nodiscard]] unsigned int framebuffer() const override { return 0; }

    void present() override { SDL_GL_SwapWindow(window_); }

    void pollEvents(std::vector<InputEvent>& out) override {
        SDL_Event event;
        while (SDL_PollEvent(&event) != 0) {
            if (event.type == SDL_WINDOWEVENT &&
                event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                updateSizes();
            }
            int mouseX = 0;
            int mouseY = 0;
            SDL_GetMouseState(&mouseX, &mouseY);
            input_.map(event, steadySeconds(), mouseX, mouseY, out);
        }
    }

  private:
    void open(const DisplayOptions& options) {
        if (options.width <= 0 || options.height <= 0) {
            throw DisplayError("window: bad size " + std::to_string(options.width) + "x" +
                               std::to_string(options.height));
        }
        // X11 offers ES through GLX_EXT_create_context_es2_profile; where that is missing or
        // refuses ES 3.1, EGL on X11 is tried before giving up.
        std::string firstError;
        try {
            createWindowAndContext(options);
            return;
        } catch (const DisplayError& e) {
            firstError = e.what();
        }
        destroyWindowAndContext();
        if (std::string(SDL_GetCurrentVideoDriver()) != "x11") {
            throw DisplayError(firstError);
        }
        SDL_SetHint(SDL_HINT_VIDEO_X11_FORCE_EGL, "1");
        try {
            createWindowAndContext(options);
        } catch (const DisplayError& e) {
            throw DisplayError(std::string(e.what()) + " (through GLX: " + firstError + ")");
        }
    }

    void createWindowAndContext(const DisplayOptions& options) {
        SDL_GL_ResetAttributes();
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
        SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
        SDL_GL_SetAttribute(SDL_GL_RED_SIZE, 8);
        SDL_GL_SetAttribute(SDL_GL_GREEN_SIZE, 8);
        SDL_GL_SetAttribute(SDL_GL_BLUE_SIZE, 8);
        SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
        SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
        SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
        Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI | SDL_WINDOW_RESIZABLE;
        if (options.fullscreen) {
            flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
        }
        window_ = SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED,
                                   SDL_WINDOWPOS_CENTERED, options.width, options.height, flags);
        if (window_ == nullptr) {
            throw DisplayError("window: SDL_CreateWindow failed: " + sdlError());
        }
        context_ = SDL_GL_CreateContext(window_);
        if (context_ == nullptr) {
            throw DisplayError("window: no OpenGL ES 3.1 context: " + sdlError());
        }
        if (SDL_GL_MakeCurrent(window_, context_) != 0) {
            throw DisplayError("window: SDL_GL_MakeCurrent failed: " + sdlError());
        }
        const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        if (!isEs31OrNewer(version)) {
            throw DisplayError(std::string("window: no OpenGL ES 3.1 context: got \"") +
                               (version != nullptr ? version : "nothing") + "\"");
        }
        // vsync paces the frame loop; a driver without it leaves the loop to its own budget.
        bool vsync = SDL_GL_SetSwapInterval(1) == 0;
        if (!vsync) {
            SDL_GL_SetSwapInterval(0);
        }
        updateSizes();
        describe(version, vsync);
    }

    void updateSizes() {
        int windowWidth = 0;
        int windowHeight = 0;
        SDL_GetWindowSize(window_, &windowWidth, &windowHeight);
        SDL_GL_GetDrawableSize(window_, &info_.width, &info_.height);
        input_.setSizes(windowWidth, windowHeight, info_.width, info_.height);
        info_.dpi = 96.0;
        float horizontalDpi = 0.0F;
        const int displayIndex = SDL_GetWindowDisplayIndex(window_);
        if (displayIndex >= 0 &&
            SDL_GetDisplayDPI(displayIndex, nullptr, &horizontalDpi, nullptr) == 0 &&
            horizontalDpi > 0.0F) {
            // SDL's DPI is per screen coordinate; the framebuffer may hold more pixels.
            info_.dpi = static_cast<double>(horizontalDpi) *
                        (windowWidth > 0 ? static_cast<double>(info_.width) / windowWidth : 1.0);
        }
        SDL_DisplayMode mode;
        info_.refreshHz = 0.0;
        if (displayIndex >= 0 && SDL_GetCurrentDisplayMode(displayIndex, &mode) == 0) {
            info_.refreshHz = mode.refresh_rate;
        }
    }

    void describe(const char* version, bool vsync) {
        char dpi[32];
        std::snprintf(dpi, sizeof dpi, "%.0f", info_.dpi);
        info_.description = std::string("window ") + std::to_string(info_.width) + "x" +
                            std::to_string(info_.height) + " on " + SDL_GetCurrentVideoDriver() +
                            ", " + dpi + " dpi, " + (vsync ? "vsync" : "no vsync") + ", " + version;
    }

    void destroyWindowAndContext() {
        if (context_ != nullptr) {
            SDL_GL_DeleteContext(context_);
            context_ = nullptr;
        }
        if (window_ != nullptr) {
            SDL_DestroyWindow(window_);
            window_ = nullptr;
        }
    }

    void close() {
        destroyWindowAndContext();
        if (videoInitialised_) {
            SDL_QuitSubSystem(SDL_INIT_VIDEO);
            videoInitialised_ = false;
            // Only SDL_Quit closes SDL's D-Bus connection; nothing else in steerseg uses SDL.
            if (SDL_WasInit(SDL_INIT_EVERYTHING) == 0) {
                SDL_Quit();
            }
        }
    }

    bool videoInitialised_ = false;
    SDL_Window* window_ = nullptr;
    SDL_GLContext context_ = nullptr;
    window::SdlInputMapper input_;
    DisplayInfo info_;
};

} // namespace

std::unique_ptr<Display> openWindowDisplay(const DisplayOptions& options) {
    return std::make_unique<WindowDisplay>(options);
}

} // namespace steerseg::platform
