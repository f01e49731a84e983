// steerseg command line: the composition root for batch use. Each command lives in its own
// cmd_*.cpp; this file only dispatches and turns exceptions into one-line messages.
#include "cli/args.hpp"
#include "cli/commands.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

struct Command {
    const char* name;
    const char* summary;
    int (*run)(std::span<const std::string>);
};

constexpr Command kCommands[] = {
    {"info", "info PATH: print a scan's geometry and intensity range as JSON",
     steerseg::cli::runInfo},
    {"gpu-info",
     "gpu-info [--platform auto|surfaceless|device]: print the GLES renderer and limits",
     steerseg::cli::runGpuInfo},
    {"render",
     "render --input SCAN --view 3d|axial|coronal|sagittal [--slice N] [--clip nx,ny,nz,d] [--roi "
     "inside|dim|off] [--surface opaque|translucent|hidden] [--preset bone|soft|mr] [--window L,W] "
     "[--camera anterior|lateral|superior] [--orbit YAW,PITCH] [--zoom F] [--pan R,U] [--speed --T "
     "T --eps E] [--no-labels] [--mask MASK | --seed ... ] [--size WxH] --output PNG: draw one "
     "view to an image",
     steerseg::cli::runRender},
    {"segment",
     "segment --input PATH --seed i,j,k,r [--seed ...] [--erase i,j,k,r ...] --T v --eps v --alpha "
     "a "
     "(--iterations N | --time t | --converge [--max-iterations N]) [--dense] --output MASK "
     "[--report REPORT.json]: level-set segmentation on the GPU",
     steerseg::cli::runSegment},
};

void printUsage(std::FILE* out) {
    std::fprintf(out, "usage: steerseg COMMAND [options]\n\ncommands:\n");
    for (const Command& c : kCommands) {
        std::fprintf(out, "  %s\n", c.summary);
    }
    std::fprintf(out, "\nA scan PATH may be a file, a DICOM folder, or %s.\n", "builtin:sample");
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        printUsage(words.empty() ? stderr : stdout);
        return words.empty() ? 2 : 0;
    }
    for (const Command& c : kCommands) {
        if (words[0] != c.name) {
            continue;
        }
        try {
            return c.run(std::span<const std::string>(words).subspan(1));
        } catch (const steerseg::cli::UsageError& e) {
            std::fprintf(stderr, "steerseg %s: %s\nusage: steerseg %s\n", c.name, e.what(),
                         c.summary);
            return 2;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "steerseg %s: %s\n", c.name, e.what());
            return 1;
        }
    }
    std::fprintf(stderr, "steerseg: unknown command '%s'\n", words[0].c_str());
    printUsage(stderr);
    return 2;
}
