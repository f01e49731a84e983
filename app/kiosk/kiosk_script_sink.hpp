#pragma once

// What a script does to the running kiosk: actions, input events and raw device records join
// the frame's queues, frames are written once drawn, the resume offer gets its answer.
#include "model/action.hpp"
#include "platform/input/raw_record.hpp"
#include "platform/input_event.hpp"
#include "script/mask_dice.hpp"
#include "script/script_player.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace steerseg::kiosk {

class KioskScriptSink final : public script::ScriptSink {
  public:
    std::vector<model::Action> actions;
    std::vector<platform::InputEvent> events;
    std::vector<std::filesystem::path> frames;
    std::vector<platform::input::RawRecord> raws;
    std::vector<std::filesystem::path> recordings;

    void action(const model::Action& a) override { actions.push_back(a); }
    void raw(const platform::input::RawRecord& r) override { raws.push_back(r); }
    void replay(const std::filesystem::path& path) override { recordings.push_back(path); }
    void input(const platform::InputEvent& e) override { events.push_back(e); }
    void saveFrame(const std::filesystem::path& path) override { frames.push_back(path); }
    void answerResume(bool resume) override { resumeAnswer = resume; }
    std::optional<bool> resumeAnswer;
    double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                    int label) override {
        return script::maskDice(mask, reference, label);
    }
};

} // namespace steerseg::kiosk
