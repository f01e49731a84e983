// Export: the mask to a path the operator (or script) gives, or to the export folder under a
// name from the scan and the UTC time. A failure goes back to review with the writer's message
// and keeps the work, so the operator can try again (another folder, a freed disk).
#include "workflow/utc_time.hpp"
#include "workflow/workflow.hpp"

#include <stdexcept>
#include <system_error>

namespace steerseg::workflow {

namespace {

// File-name safe: letters, digits, '.', '-', '_' (others become '_'), no leading dot, bounded.
std::string fileStem(const std::string& name) {
    std::string out;
    for (const char c : name) {
        const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
        out += safe ? c : '_';
    }
    while (!out.empty() && out.front() == '.') {
        out.erase(out.begin());
    }
    if (out.size() > 100) {
        out.resize(100);
    }
    return out.empty() ? std::string("scan") : out;
}

std::filesystem::path withFormat(const std::filesystem::path& base, const std::string& format) {
    return base.string() + "." + format;
}

} // namespace

std::filesystem::path Workflow::defaultExportBase() const {
    const std::string stem = fileStem(status_.scan.name) + "_" + compactUtc(settings_.clock());
    std::filesystem::path base = settings_.exportFolder / stem;
    // Two exports within a second must not overwrite each other, in any format.
    const auto taken = [&](const std::filesystem::path& b) {
        std::error_code ec;
        for (const std::string& format : settings_.exportFormats) {
            if (std::filesystem::exists(withFormat(b, format), ec)) {
                return true;
            }
        }
        return false;
    };
    for (int n = 2; taken(base) && n < 1000; ++n) {
        base = settings_.exportFolder / (stem + "-" + std::to_string(n));
    }
    return base;
}

namespace {

// The first line of an exception's message, never empty.
std::string firstLine(const std::exception& e) {
    std::string message = e.what();
    message = message.substr(0, message.find_first_of("\r\n"));
    return message.empty() ? std::string("the export failed") : message;
}

} // namespace

std::vector<ExportedStructure> Workflow::exportedStructures() const {
    std::vector<ExportedStructure> out;
    const bool asScanStarted =
        structures_.items.size() == 1 &&
        structures_.items.front().info ==
            model::structureFor(model::kFirstStructureName, settings_.structureKinds, 0);
    if (asScanStarted) {
        return out; // the level set alone, as the exports wrote it before structures
    }
    // Labels and segment numbers count the structures written, 1..N, in the list's order: a
    // DICOM SEG's segment numbers start at 1 and rise by 1.
    for (std::size_t i = 0; i < structures_.items.size(); ++i) {
        const Structure& s = structures_.items[i];
        const bool active = i == structures_.active;
        if (active ? !status_.hasLevelSet : s.mask.runs.empty()) {
            continue; // nothing drawn yet: no segment
        }
        out.push_back({s.info, static_cast<int>(out.size()) + 1, active ? nullptr : &s.mask});
    }
    return out;
}

Workflow::Outcome Workflow::exportTo(const std::string& requested) {
    const std::vector<ExportedStructure> structures = exportedStructures();
    const auto write = [&](const std::filesystem::path& p) {
        return structures.empty() ? engine_.exportMask(p) : engine_.exportStructures(p, structures);
    };
    enter(model::State::Exporting);
    std::filesystem::path path;
    std::vector<std::string> files;
    // Every configured format is tried: one that fails (DICOM SEG for a scan not from DICOM, a
    // mesh of an empty segmentation) does not keep the others from being written.
    std::vector<std::string> failures;
    std::size_t written = 0;
    try {
        if (requested.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(settings_.exportFolder, ec);
            if (ec) {
                throw std::runtime_error("export folder " + settings_.exportFolder.string() + ": " +
                                         ec.message());
            }
            const std::filesystem::path base = defaultExportBase();
            for (const std::string& format : settings_.exportFormats) {
                try {
                    const std::filesystem::path target = withFormat(base, format);
                    for (const std::filesystem::path& f : write(target)) {
                        files.push_back(f.string());
                    }
                    if (written++ == 0) {
                        path = withFormat(base, format);
                    }
                } catch (const std::exception& e) {
                    failures.push_back(firstLine(e));
                }
            }
        } else {
            path = requested;
            for (const std::filesystem::path& f : write(path)) {
                files.push_back(f.string());
            }
            written = 1;
        }
    } catch (const std::exception& e) {
        failures.push_back(firstLine(e));
    }
    if (!failures.empty()) {
        std::string message = failures.front();
        if (failures.size() > 1) {
            message += " (and " + std::to_string(failures.size() - 1) + " more failed)";
        }
        if (written > 0) {
            message += "; " + std::to_string(written) + " written, first " + path.string();
        }
        enter(model::State::Review, message);
        return no(message);
    }
    dirty_ = false;
    status_.exportedPath = path.string();
    status_.exportedFiles = std::move(files);
    ++status_.exports;
    enter(model::State::Done,
          "exported to " + status_.exportedPath +
              (written > 1 ? " and " + std::to_string(written - 1) + " more" : ""));
    return ok();
}

Workflow::Outcome Workflow::on(const model::Export& a) {
    return exportTo(a.path);
}

} // namespace steerseg::workflow
