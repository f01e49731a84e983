#include "support/cli_run.hpp"

#include "support/test_data.hpp"

#include <atomic>
#include <fstream>
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

} // namespace steerseg::test
