#pragma once

// Replays a Script frame by frame: the kiosk's loop calls poll() once a frame with the script
// clock and the workflow's Status; the player hands the due steps to a ScriptSink and holds the
// rest behind waits and checks. GL-free: the sink is the kiosk (or a test).
#include "model/action.hpp"
#include "platform/input_event.hpp"
#include "script/script.hpp"
#include "workflow/status.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

namespace steerseg::script {

// Where the steps go. Each call may throw std::exception with one line: the step then fails
// with that line.
class ScriptSink {
  public:
    virtual ~ScriptSink() = default;
    ScriptSink() = default;
    ScriptSink(const ScriptSink&) = delete;
    ScriptSink& operator=(const ScriptSink&) = delete;

    virtual void action(const model::Action& action) = 0;
    // Device level: into the input path as the platform would deliver it (time = script clock).
    virtual void input(const platform::InputEvent& event) = 0;
    // The full screen as drawn at the end of this frame, to a PNG.
    virtual void saveFrame(const std::filesystem::path& path) = 0;
    // Dice of a mask file against a reference label file on the same grid (maskDice() in
    // kiosk/mask_dice.hpp does it); label < 0: the reference's non-zero voxels.
    virtual double maskDice(const std::filesystem::path& mask,
                            const std::filesystem::path& reference, int label) = 0;
    // Raw device input (`raw`, time = script clock) and whole recordings (`replay`) for the
    // input hub. A sink without one refuses them, which fails the step.
    virtual void raw(const platform::input::RawRecord& record);
    virtual void replay(const std::filesystem::path& recording);

    // `autosave resume|discard`: the answer to the offer of an unfinished session.
    virtual void answerResume(bool resume) = 0;
};

// SCAN (--scan), DATA (STEERSEG_DATA_DIR), OUT (where relative frame, export and dice-mask
// paths go; the kiosk sets it from --frames, else the current folder). EXPORTED is the player's.
using Variables = std::map<std::string, std::string, std::less<>>;

class ScriptPlayer {
  public:
    // Throws ScriptError listing every step that names a variable `variables` lacks.
    ScriptPlayer(Script script, Variables variables);

    // One frame. `now` is the script clock in seconds (any origin; the first call is the
    // script's start) and must not go backwards; `status` is the workflow's status this frame,
    // after the actions of the previous poll were applied. Emits every step that is due, in
    // order; a wait or a check after an action emitted in this same call waits for the next
    // frame's status.
    void poll(double now, const workflow::Status& status, ScriptSink& sink);

    [[nodiscard]] bool finished() const { return next_ >= script_.steps.size() && !failed(); }
    [[nodiscard]] bool failed() const { return !failure_.empty(); }
    // "SESSION:LINE: STEP: reason", empty unless failed().
    [[nodiscard]] const std::string& failure() const { return failure_; }
    // The step about to run (or waiting), for a status line; size() once finished.
    [[nodiscard]] std::size_t nextStep() const { return next_; }
    [[nodiscard]] const Script& script() const { return script_; }

  private:
    void complete(double at);
    void fail(const Step& step, const std::string& reason);
    // $EXPORTED, then a relative path under OUT (when `underOut`).
    std::string runtimePath(const std::string& path, const workflow::Status& status,
                            bool underOut) const;
    // Returns true when the wait is over (done or failed).
    bool pollWait(const Step& step, const WaitStep& wait, double now,
                  const workflow::Status& status);
    void runDice(const Step& step, const DiceStep& dice, const workflow::Status& status,
                 ScriptSink& sink);

    Script script_;
    Variables variables_;
    std::size_t next_ = 0;
    bool started_ = false;
    double start_ = 0.0;
    double previousDone_ = 0.0; // when the step before the next one was done
    double lastNow_ = 0.0;
    std::string failure_;
    // The wait in progress.
    bool waiting_ = false;
    double waitStart_ = 0.0;
    int waitBaseIterations_ = 0;
    bool waitSawEvolving_ = false;
};

} // namespace steerseg::script
