// steerseg command line: the composition root for batch use. Each command lives in its own
// cmd_*.cpp; this file only dispatches and turns exceptions into one-line messages.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "gpu/gl_error.hpp"
#include "platform/display.hpp"
#include "platform/gpu_context.hpp"
#include "scan/scan_reader.hpp"
#include "script/script.hpp"

#include <algorithm>
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
     "[--camera anterior|lateral|superior] [--orbit YAW,PITCH] [--zoom F] [--pan R,U] "
     "[--speed-view [--T T --eps E]] [--no-labels] [--mask MASK | --seed ... ] [--size WxH] "
     "--output PNG: draw one "
     "view to an image",
     steerseg::cli::runRender},
    {"segment",
     "segment --input PATH --seed i,j,k,r [--seed ...] [--erase i,j,k,r ...] [--barrier i,j,k,r "
     "...] --T v --eps v --alpha a (--iterations N | --time t | --converge [--max-iterations N]) "
     "[--stop-on-leak] [--dense] [--speed threshold|edge|classify] [--smooth N] "
     "[--conductance v] [--kappa v] [--inside i,j,k,r ...] [--outside i,j,k,r ...] "
     "[--probe i,j,k,r] --output OUT "
     "[--format F] [--report REPORT.json] [--reference LABELS [--reference-label N]]: level-set "
     "segmentation on the GPU; OUT as for export (surfaces from the level set itself); the "
     "report gives the Dice against LABELS' voxels equal to N (or non-zero). Or: segment --input "
     "PATH [--box i0,j0,k0,i1,j1,k1] --click i,j,k,+|-[,r] [--click ...] [--max-iterations N] "
     "[--config FILE] --output OUT [--report R.json] [--reference LABELS [--reference-label N]]: "
     "an operator's box and corrections through the kiosk's workflow, the solver run to its "
     "stop after each (docs/steering.md; --box alone: the box's run)",
     steerseg::cli::runSegment},
    {"export",
     "export --input SCAN --mask MASK --output OUT.nii.gz|.nii|.nrrd|.seg.nrrd|.dcm|.stl|.ply|.tif "
     "[--format F] [--segment-name N --segment-color r,g,b --segment-label L] [--send PEER "
     "[--config FILE]]: a mask on the "
     "scan's grid, again as a mask, a 3D Slicer segmentation, a closed surface mesh in LPS "
     "millimetres or a TIFF stack (no GPU); --send puts a DICOM SEG into the outbox for a "
     "configured DICOM peer and sends it",
     steerseg::cli::runExport},
    {"measure",
     "measure --input SCAN --mask MASK [--label N] [--json]: a structure's volume, surface area "
     "(of the exported mesh), RECIST axial diameters, longest 3D diameter and intensity over "
     "the mask (non-zero, or the voxels equal to N) on the scan's grid, named by the ITK-SNAP "
     "label description beside a label map, if any (no GPU; docs/measurements.md)",
     steerseg::cli::runMeasure},
    {"kiosk",
     "kiosk [--platform auto|kms|window|offscreen] [--config FILE] [--scan PATH] [--script "
     "SESSION] [--frames DIR] [--size WxH] [--stats FILE] [--max-seconds S] [--resume | "
     "--no-resume]: the fullscreen appliance (touch, keys and scripted sessions; "
     "docs/scripts.md); --resume picks up an unfinished session's autosave",
     steerseg::cli::runKiosk},
    {"self-test",
     "--self-test [--platform auto|surfaceless|device] [--config FILE] [--allow-root]: check "
     "what the appliance needs (GL, shaders, config, writable folders, controllers); one line "
     "per check, status 1 when a required one fails",
     steerseg::cli::runSelfTest},
    {"input-monitor",
     "input-monitor [--config FILE] [--seconds N] [--record FILE] | --replay FILE: list the "
     "input devices and the configured ones they match, print decoded events and their bound "
     "actions, record raw streams, or decode a recording (docs/input-devices.md)",
     steerseg::cli::runInputMonitor},
    {"send",
     "send (--to PEER | --host H --port N --called-aet AE [--tls]) [--aet AE] [--config FILE] "
     "FILE... | "
     "send --outbox [--to PEER FILE...] [--wait S] [--config FILE]: C-STORE each DICOM file to a "
     "peer, one line per file, status 0 only when the peer accepted every one; --outbox queues "
     "them in the persistent outbox and delivers what is due, retrying for S seconds, status 0 "
     "when the outbox is empty (docs/dicom-network.md)",
     steerseg::cli::runSend},
    {"listen",
     "listen [--config FILE] [--aet AE] [--port N] [--store DIR] [--allow AE[@ADDRESS] ...] "
     "[--quota-mb N] [--tls]: the DICOM Storage SCP in the foreground until SIGTERM, filing what "
     "the "
     "allowed callers send into DIR/<study>/<series>/; with no --allow, the [[dicom.peers]] "
     "with receive = true; --tls: TLS only, with [dicom]'s certificate",
     steerseg::cli::runListen},
    {"query",
     "query --to PEER [--patient-id ID] [--patient-name PATTERN] [--study-date "
     "YYYYMMDD[-YYYYMMDD]] [--modality M] [--accession N] [--study UID] [--json] [--timeout S] "
     "[--config FILE]: ask a PACS peer with query = true which studies match (C-FIND, * and ? "
     "in names), or with --study which series that study has; one line each, or JSON",
     steerseg::cli::runQuery},
    {"retrieve",
     "retrieve --to PEER --study UID [--series UID] [--store DIR] [--timeout S] [--config "
     "FILE]: bring a study or one series from a PACS peer into the incoming store (the peer's "
     "retrieve: C-GET, or C-MOVE to [dicom] aet, listening on [dicom] port meanwhile), "
     "progress on stderr; SIGINT cancels",
     steerseg::cli::runRetrieve},
};

void printUsage(std::FILE* out) {
    std::fprintf(out, "usage: steerseg COMMAND [options]\n\ncommands:\n");
    for (const Command& c : kCommands) {
        std::fprintf(out, "  %s\n", c.summary);
    }
    std::fprintf(out, "\nA scan PATH may be a file, a DICOM folder, or %s.\n", "builtin:sample");
    std::fprintf(out, "\nexit status:\n%s", steerseg::cli::exitStatusHelp());
}

// A command's --help (or -h), wherever it stands among the options, asks for that command's
// usage: the operator gets it on stdout and status 0, not the parser's unknown option.
bool asksForHelp(std::span<const std::string> options) {
    return std::any_of(options.begin(), options.end(),
                       [](const std::string& w) { return w == "--help" || w == "-h"; });
}

} // namespace

namespace steerseg::cli {

// Most specific type first: WriteError is a ScanError.
ExitStatus exitStatusOf(const std::exception& e) {
    if (dynamic_cast<const UsageError*>(&e) != nullptr) {
        return kExitUsage;
    }
    if (dynamic_cast<const files::WriteError*>(&e) != nullptr) {
        return kExitWrite;
    }
    if (dynamic_cast<const script::ScriptError*>(&e) != nullptr) {
        return kExitUsage;
    }
    if (dynamic_cast<const platform::GpuContextError*>(&e) != nullptr ||
        dynamic_cast<const platform::DisplayError*>(&e) != nullptr ||
        dynamic_cast<const gpu::GlError*>(&e) != nullptr) {
        return kExitGpu;
    }
    return kExitFailure;
}

const char* exitStatusHelp() {
    return "  0  done\n"
           "  1  the scan (or --mask) cannot be read, a kiosk script's step failed, or another "
           "failure\n"
           "  2  a bad or missing option or session script, or a --seed/--erase that does not fit "
           "the scan\n"
           "  3  no GPU context or display, the GPU reported an error, or the scan does not fit "
           "the GPU\n"
           "  4  an output file cannot be written\n"
           "Every failure prints one line on stderr naming the file or option and the problem.\n";
}

} // namespace steerseg::cli

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
        printUsage(words.empty() ? stderr : stdout);
        return words.empty() ? steerseg::cli::kExitUsage : steerseg::cli::kExitOk;
    }
    // The appliance's check is a flag by tradition (`steerseg --self-test`); it is a command.
    if (words[0] == "--self-test") {
        words[0] = "self-test";
    }
    for (const Command& c : kCommands) {
        if (words[0] != c.name) {
            continue;
        }
        const auto options = std::span<const std::string>(words).subspan(1);
        if (asksForHelp(options)) {
            std::printf("usage: steerseg %s\n", c.summary);
            return steerseg::cli::kExitOk;
        }
        try {
            return c.run(options);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "steerseg %s: %s\n", c.name, e.what());
            // A script's error names its own line; the command's usage after it would bury it.
            if (dynamic_cast<const steerseg::cli::UsageError*>(&e) != nullptr) {
                std::fprintf(stderr, "usage: steerseg %s\n", c.summary);
            }
            return steerseg::cli::exitStatusOf(e);
        }
    }
    std::fprintf(stderr, "steerseg: unknown command '%s'\n", words[0].c_str());
    printUsage(stderr);
    return steerseg::cli::kExitUsage;
}
