// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file pieces_tool.h
/// @brief Pieces mode (Tab): a click picks the piece to sculpt; G, R and S move, turn and scale
///        it (Blender's keys), stopping at the pieces it meets or, with Push on, denting them
///        aside as one undo step. And the Pieces panel's edits of the document's pieces: looks,
///        solo, delete, duplicate, merge, split, applying a placement (jobs where they make fields).

#include "core/field/piece.h"
#include "sculpt/session/script_event.h"
#include "ui/tools/pieces/piece_gesture.h"
#include "ui/tools/tool.h"

#include <openvdb/Types.h>
#include <openvdb/math/BBox.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sculpt::ui {

class CommandRegistry;
class ToolBox;
class ToolHost;

class PiecesTool final : public Tool {
public:
    explicit PiecesTool(ToolHost& host) : mHost(host) {}
    /// Pieces mode (Tab); in it G, R, S, P and Ctrl+A; the Pieces panel's buttons.
    void addCommands(CommandRegistry& registry, ToolBox& box);

    const char* name() const override { return "pieces"; }
    /// Left: picks the piece under the pointer; while a gesture runs, left keeps it, right drops it.
    bool press(const InputEvent& event) override;
    void drag(const InputEvent& event) override;
    /// While a gesture runs: Enter keeps it, Esc drops it, X/Y/Z and typed values shape it.
    bool key(const InputEvent& event) override;
    bool holding() const override { return mGesture.has_value(); }
    /// Drops the move under way: the piece stays where it was.
    void finish() override;
    std::string waitReason() const override;
    std::optional<Scope> keyScope() const override;
    bool yieldsToMode() const override { return false; }
    void report(nlohmann::json& out) const override;

    /// G, R or S: the sculpted piece follows the pointer from here.
    void beginGesture(PieceGesture::Kind kind);
    /// A moved piece dents the pieces it meets (keeping their volumes) instead of stopping.
    bool& push() { return mPush; }
    /// The piece Merge merges the sculpted one with (the Pieces panel chooses it): another one.
    std::size_t mergePartner();
    void setMergePartner(std::size_t index) { mMergeWith = index; }

    /// The Pieces panel's edits, each one undo step (a job where fields are made).
    void select(std::size_t index);
    std::vector<PieceLook> looks() const;
    void changeLooks(std::vector<PieceLook> looks, const std::string& label);
    /// Shows only piece `index`; again, shows them all.
    void solo(std::size_t index);
    void remove(std::size_t index);
    void duplicate(std::size_t index);
    void merge(std::size_t a, std::size_t b);
    void split(std::size_t index);
    /// Resamples the piece where its placement puts it; its placement becomes the identity.
    void applyPlacement(std::size_t index);

private:
    void point(double x, double y);
    void endGesture(bool keep);
    /// Makes the piece under the pixel the one sculpted; false if none is there.
    bool selectAt(double x, double y);
    /// A duplicate, delete, split or merge, made as a job, landing as one undo step.
    void replace(const ScriptEvent& event);
    /// A move that pushes pieces aside or a placement applied, made as a job landing as one undo
    /// step; `what` says what it did in the notice.
    void move(const ScriptEvent& event, const std::string& what);

    ToolHost& mHost;
    bool mPush = false;
    std::size_t mMergeWith = 0;
    std::optional<PieceGesture> mGesture;  // G, R or S under way
    openvdb::Mat4d mShown;                 // the placement it shows (stopped at contact)
    std::vector<std::size_t> mObstacles;   // the pieces it stops at
    std::vector<openvdb::BBoxd> mBoxes;    // every piece's surface box (field world), at its start
};

}  // namespace sculpt::ui
