#include "support/test_data.hpp"

#include <cstdlib>
#include <unistd.h>

namespace steerseg::test {

std::optional<std::filesystem::path> dataDir() {
    std::filesystem::path dir;
    if (const char* env = std::getenv("STEERSEG_DATA_DIR"); env != nullptr && *env != '\0') {
        dir = env;
    } else if (const char* src = std::getenv("STEERSEG_SOURCE_DIR"); src != nullptr) {
        dir = std::filesystem::path(src) / ".." / "shared" / "data";
    } else if (const char* built = STEERSEG_DEFAULT_SOURCE_DIR; *built != '\0') {
        dir = std::filesystem::path(built) / ".." / "shared" / "data";
    } else {
        return std::nullopt;
    }
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) {
        return std::nullopt;
    }
    return dir;
}

std::optional<std::filesystem::path> dataPath(const std::filesystem::path& relative) {
    auto dir = dataDir();
    if (!dir) {
        return std::nullopt;
    }
    auto p = *dir / relative;
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) {
        return std::nullopt;
    }
    return p;
}

bool dataRequired() {
    const char* env = std::getenv("STEERSEG_REQUIRE_DATA");
    return env != nullptr && std::string(env) == "1";
}

std::string missingDataMessage(const std::filesystem::path& relative) {
    const auto dir = dataDir();
    std::string msg = "real scan data '" + relative.string() + "' not found ";
    msg += dir ? "in " + dir->string() : std::string("(no data folder)");
    msg += " (set STEERSEG_DATA_DIR; default ../shared/data)";
    if (dataRequired()) {
        msg += "; STEERSEG_REQUIRE_DATA=1 makes missing data a failure";
    }
    return msg;
}

std::filesystem::path steersegBinary() {
    const char* env = std::getenv("STEERSEG_BINARY");
    return env != nullptr ? std::filesystem::path(env)
                          : std::filesystem::path(STEERSEG_DEFAULT_BINARY);
}

std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("steerseg-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace steerseg::test
