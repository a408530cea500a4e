// SPDX-License-Identifier: Apache-2.0
#include "sculpt/session/undo_history.h"

namespace sculpt {

void UndoHistory::push(LeafJournal journal)
{
    if (journal.empty()) return;
    for (const LeafJournal& undone : mRedo) mBytes -= undone.memoryBytes();
    mRedo.clear();
    mBytes += journal.memoryBytes();
    mUndo.push_back(std::move(journal));
    enforceBudget();
}

bool UndoHistory::undo(FieldImage& field)
{
    if (mUndo.empty()) return false;
    LeafJournal journal = std::move(mUndo.back());
    mUndo.pop_back();
    mBytes -= journal.memoryBytes();
    journal.swap(field);  // now holds the stroke's result
    mBytes += journal.memoryBytes();
    mRedo.push_back(std::move(journal));
    enforceBudget();
    return true;
}

bool UndoHistory::redo(FieldImage& field)
{
    if (mRedo.empty()) return false;
    LeafJournal journal = std::move(mRedo.back());
    mRedo.pop_back();
    mBytes -= journal.memoryBytes();
    journal.swap(field);  // now holds the state before the stroke again
    mBytes += journal.memoryBytes();
    mUndo.push_back(std::move(journal));
    enforceBudget();
    return true;
}

void UndoHistory::enforceBudget()
{
    // Oldest undo first, then the farthest redo (the bottom of the redo stack).
    while (mBytes > mBudget && mUndo.size() + mRedo.size() > 1) {
        if (!mUndo.empty() && (mUndo.size() > 1 || mRedo.empty())) {
            mBytes -= mUndo.front().memoryBytes();
            mUndo.pop_front();
        } else {
            mBytes -= mRedo.front().memoryBytes();
            mRedo.erase(mRedo.begin());
        }
        ++mDropped;
    }
}

}  // namespace sculpt
