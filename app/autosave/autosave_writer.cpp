#include "autosave/autosave_writer.hpp"

#include <exception>
#include <utility>

namespace steerseg::autosave {

AutosaveWriter::AutosaveWriter(AutosaveStore& store) : store_(store), thread_([this] { run(); }) {}

AutosaveWriter::~AutosaveWriter() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void AutosaveWriter::submit(AutosaveSnapshot snapshot) {
    {
        const std::lock_guard lock(mutex_);
        queued_ = std::move(snapshot);
        cleanQueued_ = false; // new work: the session is open again
    }
    wake_.notify_all();
}

void AutosaveWriter::markClean() {
    {
        const std::lock_guard lock(mutex_);
        cleanQueued_ = true;
    }
    wake_.notify_all();
}

void AutosaveWriter::flush() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return !busy_ && !queued_ && !cleanQueued_; });
}

std::optional<std::string> AutosaveWriter::takeError() {
    const std::lock_guard lock(mutex_);
    if (error_.empty()) {
        return std::nullopt;
    }
    return std::exchange(error_, {});
}

std::uint64_t AutosaveWriter::written() const {
    const std::lock_guard lock(mutex_);
    return written_;
}

void AutosaveWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stopping_ || queued_ || cleanQueued_; });
        if (!queued_ && !cleanQueued_) {
            return; // stopping, and everything handed over is written
        }
        std::optional<AutosaveSnapshot> snapshot = std::exchange(queued_, std::nullopt);
        const bool clean = std::exchange(cleanQueued_, false);
        busy_ = true;
        lock.unlock();
        std::string failure;
        try {
            if (snapshot) {
                store_.save(std::move(*snapshot));
            }
            if (clean) {
                store_.markClean();
            }
        } catch (const std::exception& e) {
            failure = e.what();
        }
        lock.lock();
        busy_ = false;
        if (snapshot && failure.empty()) {
            ++written_;
        }
        if (!failure.empty() && error_.empty()) {
            error_ = "autosave: " + failure;
        }
        idle_.notify_all();
    }
}

} // namespace steerseg::autosave
