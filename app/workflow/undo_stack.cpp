#include "workflow/undo_stack.hpp"

#include <algorithm>
#include <utility>

namespace steerseg::workflow {

UndoStack::UndoStack(int maxDepth, Drop drop)
    : maxDepth_(static_cast<std::size_t>(std::max(1, maxDepth))), drop_(std::move(drop)) {}

UndoStack::~UndoStack() {
    clear();
}

void UndoStack::dropEntry(const UndoEntry& entry) {
    for (const LevelSetMark* mark : {&entry.before, &entry.after}) {
        if (mark->snapshot && drop_) {
            drop_(*mark->snapshot);
        }
    }
}

void UndoStack::clearRedo() {
    for (const UndoEntry& e : redo_) {
        dropEntry(e);
    }
    redo_.clear();
}

void UndoStack::push(UndoEntry entry) {
    if (!entry.levelSet) {
        if (entry.paramsBefore == entry.paramsAfter && !entry.structuresAfter) {
            return;
        }
        if (mergeOpen_ && entry.coalesce && !undo_.empty() && !undo_.back().levelSet &&
            undo_.back().coalesce == entry.coalesce) {
            UndoEntry& top = undo_.back();
            top.paramsAfter = std::move(entry.paramsAfter);
            if (top.paramsBefore == top.paramsAfter) {
                undo_.pop_back();
                mergeOpen_ = false;
            }
            return;
        }
    }
    clearRedo();
    undo_.push_back(std::move(entry));
    while (undo_.size() > maxDepth_) {
        dropEntry(undo_.front());
        undo_.pop_front();
    }
    mergeOpen_ = !undo_.back().levelSet && undo_.back().coalesce.has_value();
}

const UndoEntry* UndoStack::undoTop() const {
    return undo_.empty() ? nullptr : &undo_.back();
}

const UndoEntry* UndoStack::redoTop() const {
    return redo_.empty() ? nullptr : &redo_.back();
}

void UndoStack::undone() {
    if (!undo_.empty()) {
        redo_.push_back(std::move(undo_.back()));
        undo_.pop_back();
    }
    mergeOpen_ = false;
}

void UndoStack::redone() {
    if (!redo_.empty()) {
        undo_.push_back(std::move(redo_.back()));
        redo_.pop_back();
    }
    mergeOpen_ = false;
}

void UndoStack::clear() {
    for (const UndoEntry& e : undo_) {
        dropEntry(e);
    }
    undo_.clear();
    clearRedo();
    mergeOpen_ = false;
}

std::size_t UndoStack::snapshotCount() const {
    std::size_t n = 0;
    for (const auto* side : {&undo_, &redo_}) {
        for (const UndoEntry& e : *side) {
            n += (e.before.snapshot ? 1U : 0U) + (e.after.snapshot ? 1U : 0U);
        }
    }
    return n;
}

} // namespace steerseg::workflow
