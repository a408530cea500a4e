// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file undo_history.h
/// @brief Unlimited undo and redo of strokes within a memory budget.
///
/// Each stroke leaves a LeafJournal of the leaves it changed (their state before it). undo()
/// swaps the newest one back into the field, bit for bit, and moves it to the redo stack; redo()
/// swaps it back. A new stroke clears the redo stack. When the journals exceed the budget, the
/// oldest strokes are forgotten first (they can no longer be undone); the newest is always kept.

#include "core/field/leaf_journal.h"

#include <deque>
#include <vector>

namespace sculpt {

class UndoHistory {
public:
    static constexpr std::size_t kDefaultBudgetBytes = std::size_t(1) << 30;  // 1 GiB

    explicit UndoHistory(std::size_t budgetBytes = kDefaultBudgetBytes) : mBudget(budgetBytes) {}

    /// Records a finished stroke (an empty journal, a stroke that changed nothing, is ignored).
    void push(LeafJournal journal);
    /// Restores the field to before the newest stroke; false if there is none.
    bool undo(FieldImage& field);
    /// Re-applies the newest undone stroke; false if there is none.
    bool redo(FieldImage& field);

    std::size_t undoCount() const { return mUndo.size(); }
    std::size_t redoCount() const { return mRedo.size(); }
    /// Bytes held by all journals, undo and redo.
    std::size_t memoryBytes() const { return mBytes; }
    std::size_t budgetBytes() const { return mBudget; }
    /// Strokes forgotten to stay within the budget, since the start.
    std::size_t droppedCount() const { return mDropped; }

private:
    void enforceBudget();

    std::size_t mBudget;
    std::deque<LeafJournal> mUndo;
    std::vector<LeafJournal> mRedo;
    std::size_t mBytes = 0;
    std::size_t mDropped = 0;
};

}  // namespace sculpt
