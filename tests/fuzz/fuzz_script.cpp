// The session-script parser and player on arbitrary bytes: a script either parses or throws
// ScriptError; a parsed one replays against a sink that accepts everything and a status that
// changes each frame, and must end (finish, fail or time out) within a bounded clock.
#include "script/script.hpp"
#include "script/script_player.hpp"

#include <cstdint>
#include <string_view>

namespace {

struct NullSink : steerseg::script::ScriptSink {
    void action(const steerseg::model::Action& /*action*/) override {}
    void input(const steerseg::platform::InputEvent& /*event*/) override {}
    void saveFrame(const std::filesystem::path& /*path*/) override {}
    double maskDice(const std::filesystem::path& /*mask*/,
                    const std::filesystem::path& /*reference*/, int label) override {
        return label < 0 ? 0.5 : 0.9;
    }
    void answerResume(bool /*resume*/) override {}
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    script::Script script;
    try {
        script = script::parseScript(text, "fuzz.session");
    } catch (const script::ScriptError&) {
        return 0;
    }
    try {
        script::ScriptPlayer player(script, {{"SCAN", "/s.nii"}, {"DATA", "/d"}, {"OUT", "/o"}});
        NullSink sink;
        workflow::Status status;
        // Frames 1e7 s apart: every time and timeout a script can give (at most 1e6 s) passes
        // within one frame, so each step is done within three frames (an action, then a wait
        // that starts and times out).
        const std::size_t frames = 3 * script.steps.size() + 3;
        for (std::size_t frame = 0; frame < frames && !player.finished() && !player.failed();
             ++frame) {
            status.state = static_cast<model::State>(frame % 10);
            status.iterations = static_cast<int>(frame % 100000) * 7;
            status.converged = frame % 13 == 0;
            status.exportedPath = frame % 5 == 0 ? "/o/m.nii.gz" : "";
            player.poll(static_cast<double>(frame) * 1e7, status, sink);
        }
        if (!player.finished() && !player.failed()) {
            __builtin_trap(); // a script that never ends: the kiosk would hang
        }
    } catch (const script::ScriptError&) {
        // only the variables check throws
    }
    return 0;
}
