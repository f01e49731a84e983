// The light build's commands that need DCMTK (listen, send, query, retrieve, and export, whose
// --send and DICOM SEG go through it): refused by name, status 1. `steerseg --help` still lists
// them, so the full build's usage reads the same.
#include "cli/commands.hpp"
#include "model/light_build.hpp"

#include <stdexcept>

namespace steerseg::cli {

namespace {

[[noreturn]] void leftOut(const char* command) {
    throw std::runtime_error(
        model::leftOutOfLightBuild(std::string("The command '") + command + "'", "DCMTK"));
}

} // namespace

int runExport(std::span<const std::string> /*args*/) {
    leftOut("export");
}

int runListen(std::span<const std::string> /*args*/) {
    leftOut("listen");
}

int runSend(std::span<const std::string> /*args*/) {
    leftOut("send");
}

int runQuery(std::span<const std::string> /*args*/) {
    leftOut("query");
}

int runRetrieve(std::span<const std::string> /*args*/) {
    leftOut("retrieve");
}

} // namespace steerseg::cli
