#include "support/test_data.hpp"

#include <algorithm>
#include <cstdlib>
#include <unistd.h>
#include <vector>

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

namespace {

// The folders tempDir made in this process, removed when it ends (CTest runs each test in a
// process of its own): a developer's /tmp gathered thousands of them. STEERSEG_KEEP_TEST_DIRS
// keeps them, to look at what a failing test wrote.
class TempDirs {
  public:
    ~TempDirs() {
        // A forked child that exits without exec runs this too: the folders are its parent's.
        if (::getpid() != owner_) {
            return;
        }
        if (const char* keep = std::getenv("STEERSEG_KEEP_TEST_DIRS"); keep != nullptr && *keep) {
            return;
        }
        for (const auto& dir : dirs_) {
            std::error_code ec; // a folder a test made unremovable stays; nothing to report to
            std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                                         std::filesystem::perm_options::add, ec);
            std::filesystem::remove_all(dir, ec);
        }
    }
    void add(const std::filesystem::path& dir) {
        if (std::find(dirs_.begin(), dirs_.end(), dir) == dirs_.end()) {
            dirs_.push_back(dir);
        }
    }

  private:
    pid_t owner_ = ::getpid();
    std::vector<std::filesystem::path> dirs_;
};

TempDirs& tempDirs() {
    static TempDirs dirs;
    return dirs;
}

} // namespace

std::filesystem::path tempDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("steerseg-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    tempDirs().add(dir);
    return dir;
}

} // namespace steerseg::test
