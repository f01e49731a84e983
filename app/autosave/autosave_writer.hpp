#pragma once

// Writes autosaves off the frame loop: the frame thread hands over a snapshot it took (a copy,
// so the solver runs on), a worker thread encodes it and writes it through the store. One slot:
// a snapshot that arrives while an older one still waits replaces it, so a slow disk costs
// autosaves, never frames or memory.
#include "autosave/autosave_store.hpp"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace steerseg::autosave {

class AutosaveWriter {
  public:
    // The store is the writer's alone from here on and must outlive it.
    explicit AutosaveWriter(AutosaveStore& store);
    // Writes what is queued (and the clean mark), then joins.
    ~AutosaveWriter();
    AutosaveWriter(const AutosaveWriter&) = delete;
    AutosaveWriter& operator=(const AutosaveWriter&) = delete;

    void submit(AutosaveSnapshot snapshot);
    // After the queued snapshot: the manifest marks the session as ended cleanly.
    void markClean();
    // Waits until everything handed over is on disk (or failed).
    void flush();
    // The first write failure not yet reported (one line), else nullopt.
    std::optional<std::string> takeError();
    // Snapshots written so far.
    [[nodiscard]] std::uint64_t written() const;

  private:
    void run();

    AutosaveStore& store_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable idle_;
    std::optional<AutosaveSnapshot> queued_;
    bool cleanQueued_ = false;
    bool busy_ = false;
    bool stopping_ = false;
    std::string error_;
    std::uint64_t written_ = 0;
    std::thread thread_; // last: starts once the rest is set up
};

} // namespace steerseg::autosave
