// The kiosk's start-up lines reach its stdout as they are printed, not when a block buffer
// fills: under journald stdout is a pipe, and a kill -9 or a watchdog abort would otherwise take
// the lines that say how far the start got with it. The kiosk runs offscreen with its stdout to
// a file and is killed with SIGKILL once its first line is there (or after a generous wait).
#include "support/test_data.hpp"

#include <chrono>
#include <fcntl.h>
#include <fstream>
#include <gtest/gtest.h>
#include <signal.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace steerseg::test {
namespace {

std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

pid_t startKiosk(const std::filesystem::path& script, const std::filesystem::path& out) {
    const std::string binary = steersegBinary().string();
    const std::string scriptPath = script.string();
    const pid_t child = ::fork();
    if (child == 0) {
        const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, STDOUT_FILENO);
        const char* argv[] = {binary.c_str(), "kiosk",       "--allow-root", "--platform",
                              "offscreen",    "--size",      "320x200",      "--max-seconds",
                              "120",          "--no-resume", "--script",     scriptPath.c_str(),
                              nullptr};
        ::execv(binary.c_str(), const_cast<char* const*>(argv));
        ::_exit(127);
    }
    return child;
}

TEST(FaultsKioskStdout, TheFirstStartUpLineSurvivesAKill) {
    const auto dir = tempDir("faults-kiosk-stdout");
    std::filesystem::current_path(dir);
    std::ofstream(dir / "long.session") << "wait seconds 100\n";
    const auto out = dir / "stdout";
    const pid_t child = startKiosk(dir / "long.session", out);
    ASSERT_GT(child, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (slurp(out).find('\n') == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status)) << "the kiosk ended before it was killed";
    EXPECT_EQ(slurp(out).rfind("steerseg kiosk: ", 0), 0u) << slurp(out);
}

} // namespace
} // namespace steerseg::test
