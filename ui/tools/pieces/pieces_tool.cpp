// SPDX-License-Identifier: Apache-2.0
#include "ui/tools/pieces/pieces_tool.h"

#include "core/base/errors.h"
#include "core/field/placed_box.h"
#include "core/field/placement_check.h"
#include "core/pieces/contact.h"
#include "sculpt/session/document.h"
#include "sculpt/session/piece_changes.h"
#include "ui/commands/command_registry.h"
#include "ui/input/input_event.h"
#include "ui/tools/tool_box.h"
#include "ui/tools/tool_host.h"

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>

namespace sculpt::ui {

namespace {

/// A piece as contact sees it; `box` its leafWorldBox if known (a gesture keeps them).
ContactBody bodyOf(const DocumentPiece& piece, const openvdb::Mat4d& placement, const openvdb::BBoxd& box = {})
{
    return {piece.session->field(), *piece.session->mesher(), placement, box};
}

/// The world centre of a piece's surface: what it turns and scales about.
glm::dvec3 centreOf(const DocumentPiece& piece)
{
    const openvdb::BBoxd box = leafWorldBox(piece.session->field());
    if (box.empty()) return glm::dvec3(0.0);
    const openvdb::Vec3d c = piece.look.placement.transform(box.getCenter());
    return {c.x(), c.y(), c.z()};
}

}  // namespace

void PiecesTool::addCommands(CommandRegistry& registry, ToolBox& box)
{
    const auto active = [this] { return mHost.document().activePiece(); };
    const auto idle = [this] { return mHost.waitReason(); };
    // A rule: why an edit must wait, else what `rule` says.
    const auto idleAnd = [this](auto rule) {
        return [this, rule] {
            const std::string wait = mHost.waitReason();
            return wait.empty() ? rule() : wait;
        };
    };
    const auto inPiecesMode = idleAnd([this, &box] {
        return box.isCurrent(*this) ? std::string() : std::string("Tab first: G, R and S move pieces in pieces mode");
    });
    const auto several = [this, idleAnd](const char* why) {
        return idleAnd([this, why] { return mHost.document().pieces().size() > 1 ? std::string() : std::string(why); });
    };
    registry.add({Command::PiecesMode,
                  "Pieces Mode",
                  "Tab: a click picks the piece to sculpt, G/R/S move, turn and scale it (X/Y/Z: an axis; type a "
                  "value); Tab again: back to sculpting",
                  {{GLFW_KEY_TAB}},
                  {},
                  [this, &box] {
                      box.toggle(*this);
                      const Document& document = mHost.document();
                      mHost.notify(box.isCurrent(*this)
                                       ? "pieces mode: click a piece, G move, R rotate, S scale; Tab: sculpt"
                                       : "sculpting '" + document.pieces()[document.activePiece()].look.name + "'");
                  }});
    const struct {
        Command command;
        PieceGesture::Kind kind;
        const char* label;
        const char* help;
        int key;
    } gestures[] = {
        {Command::MovePiece, PieceGesture::Kind::Move, "Move Piece",
         "Moves the piece with the pointer; stops at the pieces it meets unless Push is on", GLFW_KEY_G},
        {Command::RotatePiece, PieceGesture::Kind::Rotate, "Rotate Piece",
         "Turns the piece about its centre, in the view's plane (X/Y/Z: about that axis)", GLFW_KEY_R},
        {Command::ScalePiece, PieceGesture::Kind::Scale, "Scale Piece",
         "Scales the piece about its centre (its voxels with it: the field is not resampled)", GLFW_KEY_S},
    };
    for (const auto& g : gestures) {
        registry.add({g.command,
                      g.label,
                      g.help,
                      {{g.key}},
                      inPiecesMode,
                      [this, kind = g.kind] { beginGesture(kind); },
                      Scope::Pieces});
    }
    registry.add({Command::TogglePush,
                  "Push",
                  "A piece moved into another dents it, keeping its volume, instead of stopping at it",
                  {{GLFW_KEY_P}},
                  {},
                  [this] {
                      mPush = !mPush;
                      mHost.notify(mPush ? "push: a moved piece dents the pieces it meets"
                                         : "a moved piece stops at the pieces it meets");
                  },
                  Scope::Pieces});
    registry.add({Command::ApplyPlacement,
                  "Apply Move",
                  "Resamples the piece's voxels where it stands (a job): its placement becomes the identity",
                  {{GLFW_KEY_A, kControl}},
                  idleAnd([this] {
                      const Document& document = mHost.document();
                      return document.pieces()[document.activePiece()].look.placement == openvdb::Mat4d::identity()
                                 ? std::string("the piece has not been moved: nothing to apply")
                                 : std::string();
                  }),
                  [this, active] { applyPlacement(active()); },
                  Scope::Pieces});
    registry.add(
        {Command::SoloPiece, "Solo", "Shows this piece alone; again: shows them all", {}, idle, [this, active] {
             solo(active());
         }});
    // Blender's object-mode keys where they are free here (P is push).
    registry.add({Command::DuplicatePiece,
                  "Duplicate",
                  "A copy of this piece, in the same place (a job)",
                  {{GLFW_KEY_D, kShift}},
                  idle,
                  [this, active] { duplicate(active()); },
                  Scope::Pieces});
    registry.add({Command::DeletePiece,
                  "Delete",
                  "Deletes this piece (Ctrl+Z brings it back)",
                  {{GLFW_KEY_DELETE}},
                  several("a document keeps at least one piece: this is its last"),
                  [this, active] { remove(active()); },
                  Scope::Pieces});
    registry.add({Command::SplitPiece,
                  "Split shells",
                  "A piece per closed shell of this one (a job)",
                  {{GLFW_KEY_P, kAlt}},
                  idle,
                  [this, active] { split(active()); },
                  Scope::Pieces});
    registry.add({Command::MergePieces,
                  "Merge",
                  "One piece of this and the one chosen beside the button (CSG union, a job)",
                  {{GLFW_KEY_J, kControl}},
                  several("only one piece: nothing to merge with"),
                  [this, active] { merge(active(), mergePartner()); },
                  Scope::Pieces});
}

bool PiecesTool::press(const InputEvent& event)
{
    if (mGesture) {
        endGesture(event.button == kLeftButton);  // right drops it
        return true;
    }
    const glm::dvec2 at = mHost.pointer();
    return selectAt(at.x, at.y);
}

void PiecesTool::drag(const InputEvent& event) { point(event.x, event.y); }

bool PiecesTool::key(const InputEvent& event)
{
    if (event.key == GLFW_KEY_ENTER || event.key == GLFW_KEY_KP_ENTER || event.key == GLFW_KEY_ESCAPE) {
        endGesture(event.key != GLFW_KEY_ESCAPE);
        return true;
    }
    const glm::dvec2 at = mHost.pointer();
    if (mGesture->key(event.key)) point(at.x, at.y);
    return true;
}

std::size_t PiecesTool::mergePartner()
{
    const Document& document = mHost.document();
    if (mMergeWith >= document.pieces().size() || mMergeWith == document.activePiece())
        mMergeWith = document.activePiece() == 0 ? 1 : 0;
    return mMergeWith;
}

void PiecesTool::finish()
{
    if (mGesture) endGesture(false);
}

std::string PiecesTool::waitReason() const
{
    return mGesture ? "the piece is moving: a click or Enter keeps it, Esc drops it" : std::string();
}

std::optional<Scope> PiecesTool::keyScope() const { return Scope::Pieces; }

void PiecesTool::report(nlohmann::json& out) const { out["pieces_tool"] = {{"push", mPush}, {"moving", holding()}}; }

std::vector<PieceLook> PiecesTool::looks() const
{
    std::vector<PieceLook> looks;
    for (const DocumentPiece& piece : mHost.document().pieces()) looks.push_back(piece.look);
    return looks;
}

void PiecesTool::select(std::size_t index)
{
    Document& document = mHost.document();
    if (mGesture || index >= document.pieces().size()) return;
    document.setActivePiece(index);
    mHost.notify("sculpting '" + document.pieces()[index].look.name + "'");
}

void PiecesTool::changeLooks(std::vector<PieceLook> looks, const std::string& label)
{
    if (mHost.busy()) return;
    mHost.document().setLooks(std::move(looks), label);
    mHost.workspace().landed(label);
}

void PiecesTool::solo(std::size_t index)
{
    std::vector<PieceLook> all = looks();
    const bool soloAlready = std::all_of(all.begin(), all.end(),
                                         [&](const PieceLook& look) { return look.visible == (&look == &all[index]); });
    for (PieceLook& look : all) look.visible = soloAlready || &look == &all[index];
    const std::string label = (soloAlready ? "show all, was solo '" : "solo '") + all[index].name + "'";
    changeLooks(std::move(all), label);
}

void PiecesTool::remove(std::size_t index) { replace(script::DeletePieceEvent{index}); }
void PiecesTool::duplicate(std::size_t index) { replace(script::DuplicatePieceEvent{index}); }
void PiecesTool::split(std::size_t index) { replace(script::SplitPieceEvent{index}); }
void PiecesTool::merge(std::size_t a, std::size_t b)
{
    if (a != b) replace(script::MergePiecesEvent{a, b});
}

void PiecesTool::applyPlacement(std::size_t index)
{
    const Document& document = mHost.document();
    if (index < document.pieces().size() && document.pieces()[index].look.placement != openvdb::Mat4d::identity())
        move(script::ApplyPlacementEvent{index}, "its voxels resampled where it stands");
}

void PiecesTool::replace(const ScriptEvent& event)
{
    if (mHost.busy()) return;
    using Pieces = std::vector<DocumentPiece>;
    PieceReplacement replacement;
    try {
        replacement = replacementOf(mHost.document(), event);
    } catch (const InputError& e) {
        return mHost.showError(e.what());
    }
    mHost.workspace().startUndoable<Pieces>(
        replacement.label,
        [work = std::move(replacement.work)](const Progress& progress) {
            std::vector<Piece> made = work(scaledProgress(progress, 0.0, 0.5));
            Pieces pieces;  // meshed here, off the UI thread
            for (std::size_t i = 0; i < made.size(); ++i) {
                const double from = 0.5 + 0.5 * double(i) / double(made.size());
                pieces.push_back(makeDocumentPiece(std::move(made[i]),
                                                   scaledProgress(progress, from, from + 0.5 / double(made.size()))));
            }
            return pieces;
        },
        [this, event, label = replacement.label, replaced = replacement.replaced](Pieces pieces) {
            const std::size_t count = pieces.size();
            mHost.document().replacePieces(replaced, std::move(pieces), label, event);
            return count == 0 ? std::string() : std::to_string(count) + " piece" + (count == 1 ? "" : "s");
        });
}

void PiecesTool::move(const ScriptEvent& event, const std::string& what)
{
    if (mHost.busy()) return;
    PieceMove change = moveOf(mHost.document(), event);
    mHost.workspace().startUndoable<PieceFields>(
        change.label, std::move(change.work), [this, event, change, what](PieceFields fields) {
            mHost.document().movePiece(change.piece, change.placement, std::move(fields), change.label, event);
            return what;
        });
}

// ---------------------------------------------------------------------------------------------
// G, R, S

void PiecesTool::beginGesture(PieceGesture::Kind kind)
{
    if (mGesture || mHost.busy()) return;
    const Document& document = mHost.document();
    const std::size_t active = document.activePiece();
    const DocumentPiece& moved = document.pieces()[active];
    const glm::dvec3 view = glm::normalize(mHost.camera().focalPoint() - mHost.camera().eye());
    const glm::dvec2 at = mHost.pointer();
    mGesture.emplace(kind, moved.look.placement, centreOf(moved), mHost.viewport(), view, at.x, at.y);
    mShown = moved.look.placement;
    // Pieces it touches already (a label map's neighbours) are not in its way. Their boxes are
    // found once: a pointer event's contact test then costs nothing for the pieces far away.
    mObstacles.clear();
    const auto& pieces = document.pieces();
    mBoxes.clear();
    for (const DocumentPiece& piece : pieces) mBoxes.push_back(leafWorldBox(piece.session->field()));
    const ContactBody start = bodyOf(moved, moved.look.placement, mBoxes[active]);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (i != active && pieces[i].look.visible &&
            !overlap(start, bodyOf(pieces[i], pieces[i].look.placement, mBoxes[i])).any())
            mObstacles.push_back(i);
    }
    mHost.notify(mGesture->describe(moved.session->field().units()));
}

void PiecesTool::point(double x, double y)
{
    mGesture->point(mHost.viewport(), x, y);
    const Document& document = mHost.document();
    const DocumentPiece& moved = document.pieces()[document.activePiece()];
    double free = 1.0;
    if (!mPush) {  // stop at the first contact along the gesture
        const auto along = [this](double t) { return mGesture->placementAt(t); };
        const ContactBody start = bodyOf(moved, moved.look.placement, mBoxes[document.activePiece()]);
        for (std::size_t i : mObstacles) {
            const DocumentPiece& other = document.pieces()[i];
            free = std::min(free, freeFraction(start, bodyOf(other, other.look.placement, mBoxes[i]), along));
        }
    }
    mShown = mGesture->placementAt(free);
    mHost.showPlacement(mShown);
    mHost.notify(mGesture->describe(moved.session->field().units()) + (free < 1.0 ? " - stopped at contact" : ""));
}

void PiecesTool::endGesture(bool keep)
{
    Document& document = mHost.document();
    const std::size_t index = document.activePiece();
    const DocumentPiece& moved = document.pieces()[index];
    const char* verb = mGesture->kind() == PieceGesture::Kind::Move     ? "move '"
                       : mGesture->kind() == PieceGesture::Kind::Rotate ? "rotate '"
                                                                        : "scale '";
    const std::string label = verb + moved.look.name + "'";
    mGesture.reset();
    const std::string problem = placementProblem(mShown);  // a scale typed as 0, say
    if (!keep || mShown == moved.look.placement || !problem.empty()) {
        mHost.showPlacement(moved.look.placement);
        mHost.notify(!keep ? "move dropped" : problem.empty() ? "" : label + " dropped: " + problem);
        return;
    }
    std::vector<std::size_t> pushed;
    if (mPush) {
        const auto& pieces = document.pieces();
        for (std::size_t i = 0; i < pieces.size(); ++i)
            if (i != index && pieces[i].look.visible &&
                overlap(bodyOf(moved, mShown), bodyOf(pieces[i], pieces[i].look.placement)).any())
                pushed.push_back(i);
    }
    if (pushed.empty()) {
        document.movePiece(index, mShown, {}, label);
        mHost.workspace().landed(label);
        return;
    }
    move(script::MovePieceEvent{index, mShown, pushed}, "the pieces in its way pushed aside, one undo step");
}

bool PiecesTool::selectAt(double x, double y)
{
    const Ray ray = mHost.viewport().rayThrough(x, y);
    const auto& pieces = mHost.document().pieces();
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t chosen = pieces.size();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (!pieces[i].look.visible) continue;
        const openvdb::Mat4d& placement = pieces[i].look.placement;
        SurfacePicker picker;
        const SculptSession& session = *pieces[i].session;
        const auto hit =
            picker.pick(session.field(), session.mesher()->version(), transformedRay(ray, placement.inverse()));
        if (!hit) continue;
        const openvdb::Vec3d p = placement.transform(openvdb::Vec3d(hit->position.x, hit->position.y, hit->position.z));
        const double distance = (p - openvdb::Vec3d(ray.origin.x, ray.origin.y, ray.origin.z)).length();
        if (distance < nearest) nearest = distance, chosen = i;
    }
    if (chosen == pieces.size()) return false;
    select(chosen);
    return true;
}

}  // namespace sculpt::ui
