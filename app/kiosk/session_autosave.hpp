#pragma once

// The kiosk's autosave pass and resume (docs/kiosk.md, "Autosave and resume"). Each frame it
// takes a snapshot of the session when the workflow changed state, when the level set or the
// parameters changed outside a run, and every interval while the surface evolves: the mask is
// read back on the frame thread (the GL context's), everything else is written by
// AutosaveWriter's thread. At start it looks for an unfinished session and, once the operator
// (or --resume, or a script) says so, loads its scan and puts its surface, parameters, counts
// and state back.
#include "autosave/autosave_store.hpp"
#include "autosave/autosave_writer.hpp"
#include "config/kiosk_config.hpp"
#include "kiosk/kiosk_options.hpp"
#include "workflow/workflow.hpp"

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::engine {
class SessionEngine;
} // namespace steerseg::engine

namespace steerseg::kiosk {

class SessionAutosave {
  public:
    // Looks at the folder (each damaged autosave passed over is one line on `err`) and, with
    // ResumeChoice::Yes, starts resuming at once. Must be made before the audit log opens: a
    // resume reads the log it continues.
    SessionAutosave(const config::AutosaveConfig& config, const std::filesystem::path& auditLog,
                    ResumeChoice choice, std::ostream& err);
    ~SessionAutosave();
    SessionAutosave(const SessionAutosave&) = delete;
    SessionAutosave& operator=(const SessionAutosave&) = delete;

    // An unfinished session waits for Resume or Discard.
    [[nodiscard]] bool offering() const { return offer_.has_value() && !resuming_; }
    // One line for the prompt: "CT_sarcoma, evolving, saved 13:01:40 UTC".
    [[nodiscard]] std::string offerText() const;
    // The answer. Resume: the next frame queues the autosave's scan; Discard: a fresh start.
    void answer(bool resume);
    // A resume is under way (its scan loading): the start-up scan must not be loaded over it.
    [[nodiscard]] bool resuming() const { return resuming_; }

    // Each frame, after the solver: finishes a resume whose scan is in, then saves if due.
    void frame(workflow::Workflow& flow, engine::SessionEngine& engine,
               std::vector<model::Action>& actions);
    // On a clean exit: the last state written; the manifest says the session ended cleanly
    // unless unexported work is left (then the next start offers it).
    void finish(const workflow::Workflow& flow, engine::SessionEngine& engine);

  private:
    void finishResume(workflow::Workflow& flow, engine::SessionEngine& engine);
    [[nodiscard]] bool due(const workflow::Workflow& flow,
                           const engine::SessionEngine& engine) const;
    void save(const workflow::Workflow& flow, engine::SessionEngine& engine);
    void reportWriteError();
    void readAuditLogBeforeItOpens();

    config::AutosaveConfig config_;
    std::filesystem::path auditLog_;
    std::ostream& err_;
    std::unique_ptr<autosave::AutosaveStore> store_;
    std::unique_ptr<autosave::AutosaveWriter> writer_;
    std::optional<autosave::AutosaveStore::Found> offer_;
    bool resuming_ = false;
    bool loadQueued_ = false;
    std::vector<std::string> auditNotes_; // said when a resume starts
    std::uint64_t scansAtResume_ = 0;
    autosave::ScanReference scanReference_; // of the attached scan, taken once per scan
    std::uint64_t referenceScans_ = 0;

    // What the last snapshot saw, to tell when the next one is due.
    std::optional<model::State> savedState_;
    std::uint64_t savedVersion_ = 0;
    model::LevelSetParams savedParams_;
    std::optional<model::Box> savedBox_;
    std::uint64_t savedStructures_ = 0; // Workflow::structuresVersion
    double savedRadius_ = 0.0;
    std::chrono::steady_clock::time_point savedAt_{};
    // The frame thread's share: reading the mask back and encoding its runs.
    int snapshots_ = 0;
    double captureSeconds_ = 0.0;
    double captureMaxSeconds_ = 0.0;
    double readBackSeconds_ = 0.0;
};

} // namespace steerseg::kiosk
