// `steerseg --self-test`: what the appliance needs at start, one line per check, exit status 1
// when a required one fails. The GL checks run offscreen on the same driver the kiosk uses.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/self_test_checks.hpp"
#include "cli/self_test_dicom.hpp"
#include "gpu/gl.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/program.hpp"
#include "gpu/shader_library.hpp"
#include "input/input_hub.hpp"
#include "model/action.hpp"
#include "model/level_set_params.hpp"
#include "model/solver_types.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "platform/input/sources.hpp"
#include "session/numerics_check.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <unistd.h>

namespace steerseg::cli {

namespace {

// Each [[input.devices]] entry opened as the kiosk would: present, or the source's reason (not
// plugged in, no permission and which group or rule is missing). Controllers are optional (a
// console may run on touch alone), so a missing one warns.
CheckResult checkConfiguredControllers(const config::KioskConfig& cfg) {
    CheckResult r{"configured controllers", CheckLevel::Ok, "", {}};
    const auto specs = input::deviceSpecs(cfg.input.devices);
    if (specs.empty()) {
        r.detail = "none configured ([[input.devices]])";
        return r;
    }
    std::size_t present = 0;
    for (const auto& spec : specs) {
        std::string problem;
        if (platform::input::openSource(spec, problem) != nullptr) {
            ++present;
            r.problems.push_back(spec.name + ": present" +
                                 (problem.empty() ? "" : " (" + problem + ")"));
        } else {
            r.problems.push_back(problem);
        }
    }
    r.detail = std::to_string(present) + " of " + std::to_string(specs.size()) + " present";
    if (present < specs.size()) {
        r.level = CheckLevel::Warn;
    }
    return r;
}

// "OpenGL ES 3.2 Mesa 22.3.6" -> 3.2; 0.0 when the string is not a GLES version.
double glesVersion(const std::string& version) {
    const std::string prefix = "OpenGL ES ";
    if (version.rfind(prefix, 0) != 0) {
        return 0.0;
    }
    int major = 0;
    int minor = 0;
    if (std::sscanf(version.c_str() + prefix.size(), "%d.%d", &major, &minor) != 2) {
        return 0.0;
    }
    return major + minor / 10.0;
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

CheckResult checkGl(const std::string& backend) {
    const gpu::GpuInfo info = gpu::queryGpuInfo();
    const std::string what = info.version + " (" + info.renderer + ", EGL " + backend + ")";
    // The solver and the views are compute shaders: GLES 3.1.
    if (glesVersion(info.version) < 3.1) {
        return {"gl", CheckLevel::Fail, what + ": OpenGL ES 3.1 or later is needed", {}};
    }
    return {"gl", CheckLevel::Ok, what, {}};
}

// Every shader the binary embeds, built as the solver and the views build them (their
// defines, the default brick size), so a driver that rejects one fails here, not mid-session.
// A .vert pairs with the .frag of the same name.
CheckResult checkShaders() {
    const int brick = model::defaultBrickSize();
    char far[32];
    std::snprintf(far, sizeof far, "%.1f", static_cast<double>(model::kPhiFar));
    char rescale[32];
    std::snprintf(rescale, sizeof rescale, "%.4f", static_cast<double>(model::kRescaleWeight));
    const gpu::Defines defines{{"BRICK_SIZE", std::to_string(brick)},
                               {"PHI_FAR", far},
                               {"RESCALE_WEIGHT", rescale},
                               {"LOCAL_SIZE", std::to_string(std::min(brick * brick * brick, 64))}};
    CheckResult r{"shaders", CheckLevel::Ok, "", {}};
    int built = 0;
    const auto names = gpu::shaderNames();
    const auto has = [&](const std::string& n) {
        return std::find(names.begin(), names.end(), n) != names.end();
    };
    for (const std::string_view view : names) {
        const std::string name(view);
        const std::string stem = name.substr(0, name.rfind('.'));
        try {
            if (name.ends_with(".comp")) {
                gpu::buildComputeProgram(name, defines);
                ++built;
            } else if (name.ends_with(".vert")) {
                if (!has(stem + ".frag")) {
                    r.problems.push_back(name + ": no " + stem + ".frag to pair with");
                    continue;
                }
                gpu::buildGraphicsProgram(name, stem + ".frag");
                ++built;
            } else if (name.ends_with(".frag") && !has(stem + ".vert")) {
                r.problems.push_back(name + ": no " + stem + ".vert to pair with");
            }
        } catch (const gpu::GlError& e) {
            r.problems.push_back(firstLine(e.what()));
        }
    }
    if (!r.problems.empty()) {
        r.level = CheckLevel::Fail;
        r.detail = std::to_string(r.problems.size()) + " program(s) failed, " +
                   std::to_string(built) + " built";
    } else {
        r.detail = std::to_string(built) + " programs built";
    }
    return r;
}

// Each speed computed on this GPU against its CPU twin (session/numerics_check): a speed whose
// numbers are wrong here would give an operator a wrong mask, so it fails the self-test.
std::vector<CheckResult> checkNumerics() {
    const session::NumericsReport report = session::checkGpuNumerics();
    std::vector<CheckResult> out;
    for (const session::SpeedNumerics& s : report.speeds) {
        char largest[32];
        std::snprintf(largest, sizeof largest, "%.3g", s.largestDifference);
        out.push_back({"numerics " + std::string(model::speedKindName(s.kind)),
                       s.passed ? CheckLevel::Ok : CheckLevel::Fail,
                       std::string(s.passed ? "matches the CPU" : "WRONG on this GPU") +
                           ", largest difference " + largest + ": " + s.detail,
                       {}});
    }
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", report.seconds);
    out.push_back({"numerics",
                   report.allPassed() ? CheckLevel::Ok : CheckLevel::Fail,
                   std::to_string(report.speeds.size()) +
                       " speeds on the built-in phantom against their CPU twins in " + seconds +
                       " s",
                   {}});
    return out;
}

} // namespace

int runSelfTest(std::span<const std::string> words) {
    // --allow-root only so that the kiosk's own command line checks as it runs; the user check
    // still warns that root's answers are not the service user's.
    const Args args(words, {"platform", "config"}, {"allow-root"});
    const auto platformChoice =
        platform::parseOffscreenPlatform(args.value("platform").value_or("auto"));
    std::optional<std::filesystem::path> configFile;
    if (const auto c = args.value("config")) {
        configFile = *c;
    }

    std::vector<CheckResult> results;
    if (auto user = checkUser(::geteuid() == 0)) {
        results.push_back(*user);
    }
    // No context is a failed check like the others, so the rest of the report still comes.
    std::unique_ptr<platform::GpuContext> context;
    try {
        context = platform::createOffscreenContext(platformChoice);
    } catch (const std::exception& e) {
        results.push_back({"gl", CheckLevel::Fail, firstLine(e.what()), {}});
        results.push_back({"shaders", CheckLevel::Fail, "not built: no GL context", {}});
    }
    if (context) {
        results.push_back(checkGl(context->backendName()));
        results.push_back(checkShaders());
        for (CheckResult& r : checkNumerics()) {
            results.push_back(std::move(r));
        }
    }

    const config::BindingCheck bindable = model::isBindable;
    const config::LoadedConfig loaded =
        config::loadConfig(config::kioskConfigSources(configFile), bindable);
    results.push_back(checkConfig(loaded));
    results.push_back(checkWritableFolder("export folder", loaded.config.exports.folder));
    {
        std::filesystem::path auditFolder = loaded.config.audit.path.parent_path();
        if (auditFolder.empty()) {
            auditFolder = ".";
        }
        results.push_back(checkWritableFolder("audit log folder", auditFolder));
        results.push_back(checkAuditLog(loaded.config.audit.path));
    }
    results.push_back(checkWritableFolder("autosave folder", loaded.config.autosave.folder));
    results.push_back(checkControllers(findControllerNodes("/dev")));
    results.push_back(checkConfiguredControllers(loaded.config));
    for (CheckResult& r : checkDicomNode(loaded.config.dicom)) {
        results.push_back(std::move(r));
    }

    std::fputs(formatReport(results).c_str(), stdout);
    return anyFailed(results) ? kExitFailure : kExitOk;
}

} // namespace steerseg::cli
