#pragma once

// Undo and redo of the operator's edits: sphere edits and restarts as level-set snapshots taken
// before and after each edit, parameter changes as values. The stack owns the snapshots it
// holds and frees them (through the drop callback) when entries fall off its bottom, when a new
// edit clears the redo side, and on clear().
#include "model/action.hpp"
#include "workflow/engine.hpp"

#include <array>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace steerseg::workflow {

// Every parameter the operator sets (indexed by Param) and the preset they came from, and the
// speed: the kind chosen with the classifier's examples, and the kind that runs while Classify
// waits for an example of each kind (the one in force when Classify was chosen).
struct ParamValues {
    std::array<double, model::kParamCount> values{};
    std::string preset;
    SpeedChoice speed;
    model::SpeedKind fallback = model::SpeedKind::Threshold;
    bool operator==(const ParamValues&) const = default;
};

// The level set at one moment: its snapshot (none: empty) and the counts the panel shows.
struct LevelSetMark {
    std::optional<SnapshotId> snapshot;
    int seeds = 0;
    int erasures = 0;
};

struct StructureList; // workflow/structures.hpp

struct UndoEntry {
    std::string what;      // the action that made it: "add_seed", "set_param", "probe", ...
    bool levelSet = false; // a level-set edit; otherwise a parameter change
    ParamValues paramsBefore;
    ParamValues paramsAfter;
    // A parameter change merges into the entry below it when both name the same parameter and
    // nothing (no other edit, no undo or redo) came between: a knob turn is one undo step.
    std::optional<model::Param> coalesce;
    LevelSetMark before;
    LevelSetMark after;
    // A change of the structures: the list on each side (the active one's surface is the marks').
    std::shared_ptr<const StructureList> structuresBefore;
    std::shared_ptr<const StructureList> structuresAfter;
};

class UndoStack {
  public:
    using Drop = std::function<void(SnapshotId)>; // must not throw
    UndoStack(int maxDepth, Drop drop);
    ~UndoStack();
    UndoStack(const UndoStack&) = delete;
    UndoStack& operator=(const UndoStack&) = delete;

    // Records a new edit: clears the redo side and drops the oldest entry past maxDepth. A
    // parameter change that changes nothing is ignored; one that coalesces is merged (and
    // removed when the merged change comes back to where it started).
    void push(UndoEntry entry);

    [[nodiscard]] const UndoEntry* undoTop() const; // nullptr: nothing to undo
    [[nodiscard]] const UndoEntry* redoTop() const;
    // The caller applied undoTop()'s `before` (redoTop()'s `after`): move it across.
    void undone();
    void redone();

    void clear(); // drops every snapshot
    [[nodiscard]] std::size_t undoDepth() const { return undo_.size(); }
    [[nodiscard]] std::size_t redoDepth() const { return redo_.size(); }
    [[nodiscard]] std::size_t snapshotCount() const; // snapshots held, both sides

  private:
    void dropEntry(const UndoEntry& entry);
    void clearRedo();

    std::size_t maxDepth_;
    Drop drop_;
    std::deque<UndoEntry> undo_; // back = most recent
    std::deque<UndoEntry> redo_; // back = next to redo
    bool mergeOpen_ = false;     // the last operation was a push that may be merged into
};

} // namespace steerseg::workflow
