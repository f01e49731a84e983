#include "support/cli_run.hpp"

#include "support/test_data.hpp"

#include <atomic>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

namespace steerseg::test {

namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

CliRun runSteerseg(const std::string& arguments) {
    const auto binary = steersegBinary();
    if (!std::filesystem::exists(binary)) {
        throw std::runtime_error("steerseg binary not found at " + binary.string() +
                                 " (set STEERSEG_BINARY)");
    }
    static std::atomic<int> counter{0};
    const auto dir = tempDir("cli-" + std::to_string(counter++));
    const std::string command = "'" + binary.string() + "' " + arguments + " >'" +
                                (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
    const int status = std::system(command.c_str());
    CliRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir / "out");
    r.err = slurp(dir / "err");
    std::filesystem::remove_all(dir);
    return r;
}

ShellRun runShell(const std::string& command) {
    ShellRun r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return r;
    }
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) {
        r.output += buffer;
    }
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

std::string shellQuoted(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

void expectDciodvfyValid(const std::filesystem::path& file, const std::string& iod) {
    const ShellRun r = runShell("/usr/bin/dciodvfy " + shellQuoted(file));
    EXPECT_NE(("\n" + r.output).find("\n" + iod + "\n"), std::string::npos) << r.output;
    std::istringstream lines(r.output);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("Error", 0) == 0) {
            ADD_FAILURE() << "dciodvfy: " << line;
        } else if (line.rfind("Warning", 0) == 0) {
            std::cout << "  dciodvfy " << line << "\n";
        }
    }
}

} // namespace steerseg::test
