#include "kiosk/kiosk_startup.hpp"

#include "files/file_error.hpp"
#include "model/action.hpp"
#include "platform/egl/offscreen_display.hpp"
#include "platform/kms/kms_display.hpp"
#include "platform/window/window_display.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <unistd.h>

namespace steerseg::kiosk {

namespace {

std::atomic<bool> g_stop{false};

extern "C" void onStopSignal(int /*signal*/) {
    g_stop = true;
}

} // namespace

StopSignals::StopSignals() {
    g_stop = false;
    term_ = std::signal(SIGTERM, onStopSignal);
    int_ = std::signal(SIGINT, onStopSignal);
}

StopSignals::~StopSignals() {
    std::signal(SIGTERM, term_);
    std::signal(SIGINT, int_);
}

bool StopSignals::stopRequested() {
    return g_stop;
}

void StopSignals::requestStop() {
    g_stop = true;
}

config::LoadedConfig readConfig(const KioskOptions& options, std::ostream& err) {
    const config::BindingCheck check = model::isBindable;
    config::LoadedConfig loaded =
        config::loadConfig(config::kioskConfigSources(options.config), check);
    for (const config::ConfigProblem& p : loaded.problems) {
        err << "steerseg kiosk: config: " << config::describe(p) << '\n';
    }
    return loaded;
}

std::unique_ptr<platform::Display> openDisplay(const std::string& platform,
                                               const platform::DisplayOptions& options) {
    if (platform == "offscreen") {
        return platform::openOffscreenDisplay(options);
    }
    if (platform == "window") {
        return platform::openWindowDisplay(options);
    }
    if (platform == "kms") {
        return platform::openKmsDisplay(options);
    }
    throw platform::DisplayError("unknown display platform '" + platform +
                                 "' (kms, window, offscreen)");
}

namespace {

// $OUT as one absolute folder name, whatever form --frames took: the player puts every relative
// output path under $OUT, so a relative $OUT ("out") would put `export $OUT/mask.nii.gz` under
// it a second time (out/out/mask.nii.gz, issue 49), and a trailing slash would double the
// separator in every path the script names.
std::string outFolder(const std::optional<std::filesystem::path>& frames) {
    if (!frames) {
        return std::filesystem::current_path().string();
    }
    std::filesystem::path dir = std::filesystem::absolute(*frames).lexically_normal();
    if (!dir.has_filename() && dir != dir.root_path()) {
        dir = dir.parent_path();
    }
    return dir.string();
}

} // namespace

std::unique_ptr<script::ScriptPlayer> makePlayer(const KioskOptions& options) {
    if (!options.script) {
        return nullptr;
    }
    script::Variables vars;
    if (!options.scan.empty()) {
        vars["SCAN"] = options.scan;
    }
    if (const char* data = std::getenv("STEERSEG_DATA_DIR"); data != nullptr && *data != '\0') {
        vars["DATA"] = data;
    }
    vars["OUT"] = outFolder(options.frames);
    return std::make_unique<script::ScriptPlayer>(script::loadScript(*options.script),
                                                  std::move(vars));
}

namespace {

void requireWritableFolder(const std::filesystem::path& dir, const char* option) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        throw files::WriteError(dir, std::string("cannot create the ") + option + " folder (" +
                                         ec.message() + ")");
    }
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        throw files::WriteError(dir, std::string("cannot write in the ") + option + " folder (" +
                                         std::strerror(errno) + ")");
    }
}

// Opened for appending, which creates it where it is missing (and removed again then): access()
// would pass root on any folder, /proc included.
void requireWritableFile(const std::filesystem::path& file, const char* option) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        throw files::WriteError(file, std::string(option) + " names a folder, not a file");
    }
    const bool existed = std::filesystem::exists(file, ec);
    errno = 0;
    if (!std::ofstream(file, std::ios::app)) {
        throw files::WriteError(file, std::string("cannot write the ") + option + " file (" +
                                          std::strerror(errno != 0 ? errno : EIO) + ")");
    }
    if (!existed) {
        std::filesystem::remove(file, ec);
    }
}

} // namespace

void prepareOutputs(const KioskOptions& options) {
    if (options.frames) {
        requireWritableFolder(*options.frames, "--frames");
    }
    if (options.stats) {
        requireWritableFile(*options.stats, "--stats");
    }
}

} // namespace steerseg::kiosk
