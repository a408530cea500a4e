// SculptApp: the document's pieces: which one is sculpted, their looks, the Pieces panel's
// edits (as jobs where they make fields), and moving one with G, R and S in pieces mode (Tab),
// stopping at contact or pushing the others aside.

#include "core/base/errors.h"
#include "core/field/placed_box.h"
#include "core/pieces/contact.h"
#include "core/pieces/lattice_transfer.h"
#include "core/pieces/piece_edits.h"
#include "core/pieces/push.h"
#include "ui/app/sculpt_app.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace sculpt::ui {

namespace {

using Pieces = std::vector<DocumentPiece>;

Piece asPiece(const DocumentPiece& piece) { return {piece.look, piece.session->field()}; }

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

std::vector<PieceLook> SculptApp::pieceLooks() const
{
    std::vector<PieceLook> looks;
    for (const DocumentPiece& piece : mDocument->pieces()) looks.push_back(piece.look);
    return looks;
}

void SculptApp::selectPiece(std::size_t index)
{
    if (mStroke.active() || mGesture || index >= mDocument->pieces().size()) return;
    mDocument->setActivePiece(index);
    mDialogs.notice = "sculpting '" + mDocument->pieces()[index].look.name + "'";
}

void SculptApp::changeLooks(std::vector<PieceLook> looks, const std::string& label)
{
    if (busy()) return;
    mDocument->setLooks(std::move(looks), label);
    mDialogs.notice = label + " (Ctrl+Z undoes it)";
}

void SculptApp::soloPiece(std::size_t index)
{
    std::vector<PieceLook> looks = pieceLooks();
    const bool soloAlready = std::all_of(
        looks.begin(), looks.end(), [&](const PieceLook& look) { return look.visible == (&look == &looks[index]); });
    for (PieceLook& look : looks) look.visible = soloAlready || &look == &looks[index];
    const std::string label = (soloAlready ? "show all, was solo '" : "solo '") + looks[index].name + "'";
    changeLooks(std::move(looks), label);
}

void SculptApp::deletePiece(std::size_t index)
{
    if (busy()) return;
    if (mDocument->pieces().size() < 2) return showError("a document keeps at least one piece: this is its last");
    const std::string name = mDocument->pieces()[index].look.name;
    mDocument->replacePieces({index}, {}, "delete '" + name + "'");
    mDialogs.notice = "deleted '" + name + "' (Ctrl+Z brings it back)";
}

void SculptApp::startPieceEdit(std::string label, std::vector<std::size_t> replaced,
                               std::function<std::vector<Piece>()> make)
{
    if (busy()) return;
    startJob<Pieces>(
        label,
        [make = std::move(make)](const Progress& progress) {
            std::vector<Piece> made = make();
            Pieces pieces;
            for (std::size_t i = 0; i < made.size(); ++i) {
                pieces.push_back(makeDocumentPiece(std::move(made[i]), scaledProgress(progress, double(i) / made.size(),
                                                                                      double(i + 1) / made.size())));
            }
            return pieces;
        },
        [this, label, replaced](Pieces pieces) {
            const std::size_t count = pieces.size();
            mDocument->replacePieces(replaced, std::move(pieces), label);
            mDialogs.notice =
                label + ": " + std::to_string(count) + " piece" + (count == 1 ? "" : "s") + " (Ctrl+Z undoes it)";
        });
}

void SculptApp::duplicatePiece(std::size_t index)
{
    Piece copy = asPiece(mDocument->pieces()[index]);
    copy.name = mDocument->freeName(copy.name + " copy");
    startPieceEdit("duplicate '" + mDocument->pieces()[index].look.name + "'", {},
                   [copy]() { return std::vector<Piece>{Piece(copy, copy.field.deepCopy())}; });
}

void SculptApp::mergePieces(std::size_t a, std::size_t b)
{
    if (a == b) return;
    const Piece first = asPiece(mDocument->pieces()[std::min(a, b)]),
                second = asPiece(mDocument->pieces()[std::max(a, b)]);
    startPieceEdit("merge '" + first.name + "' and '" + second.name + "'", {std::min(a, b), std::max(a, b)},
                   [first, second]() { return std::vector<Piece>{sculpt::mergePieces(first, second)}; });
}

void SculptApp::splitPiece(std::size_t index)
{
    const Piece piece = asPiece(mDocument->pieces()[index]);
    startPieceEdit("split '" + piece.name + "'", {index}, [piece]() { return sculpt::splitPiece(piece); });
}

void SculptApp::applyPlacement(std::size_t index)
{
    if (busy()) return;
    const Piece piece = asPiece(mDocument->pieces()[index]);
    if (piece.placement == openvdb::Mat4d::identity()) return;
    const std::string label = "apply the placement of '" + piece.name + "'";
    startJob<FieldImage>(
        label,
        [piece](const Progress&) {
            // Resampled into its own lattice where it stands now: its placement becomes the identity.
            return onLatticeOf(piece.field, piece.placement, piece.field, openvdb::Mat4d::identity(),
                               piece.field.halfWidthVoxels());
        },
        [this, index, label](FieldImage placed) {
            std::vector<std::pair<std::size_t, FieldImage>> resampled;
            resampled.emplace_back(index, std::move(placed));
            mDocument->movePiece(index, openvdb::Mat4d::identity(), std::move(resampled), label);
            mDialogs.notice = label + ": its voxels resampled where it stands (Ctrl+Z undoes it)";
        });
}

// ---------------------------------------------------------------------------------------------
// G, R, S

void SculptApp::beginPieceGesture(PieceGesture::Kind kind)
{
    if (mDrag != Drag::None || busy()) return;
    const DocumentPiece& moved = mDocument->pieces()[mDocument->activePiece()];
    const glm::dvec3 view = glm::normalize(mCamera.focalPoint() - mCamera.eye());
    mGesture.emplace(kind, moved.look.placement, centreOf(moved), mViewport, view, mMouseX, mMouseY);
    mGestureShown = moved.look.placement;
    // Pieces it touches already (a label map's neighbours) are not in its way. Their boxes are
    // found once: a pointer event's contact test then costs nothing for the pieces far away.
    mObstacles.clear();
    const auto& pieces = mDocument->pieces();
    mGestureBoxes.clear();
    for (const DocumentPiece& piece : pieces) mGestureBoxes.push_back(leafWorldBox(piece.session->field()));
    const ContactBody start = bodyOf(moved, moved.look.placement, mGestureBoxes[mDocument->activePiece()]);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (i != mDocument->activePiece() && pieces[i].look.visible &&
            !overlap(start, bodyOf(pieces[i], pieces[i].look.placement, mGestureBoxes[i])).any())
            mObstacles.push_back(i);
    }
    mDrag = Drag::Piece;
    mDialogs.notice = mGesture->describe(moved.session->field().units());
}

void SculptApp::pointPieceGesture(double x, double y)
{
    mGesture->point(mViewport, x, y);
    const DocumentPiece& moved = mDocument->pieces()[mDocument->activePiece()];
    double free = 1.0;
    if (!mPushPieces) {  // stop at the first contact along the gesture
        const auto along = [this](double t) { return mGesture->placementAt(t); };
        const ContactBody start = bodyOf(moved, moved.look.placement, mGestureBoxes[mDocument->activePiece()]);
        for (std::size_t i : mObstacles) {
            const DocumentPiece& other = mDocument->pieces()[i];
            free = std::min(free, freeFraction(start, bodyOf(other, other.look.placement, mGestureBoxes[i]), along));
        }
    }
    mGestureShown = mGesture->placementAt(free);
    mDisplay.setPlacement(mGestureShown);
    mDialogs.notice = mGesture->describe(moved.session->field().units()) + (free < 1.0 ? " - stopped at contact" : "");
}

void SculptApp::keyPieceGesture(int key)
{
    if (mGesture->key(key)) pointPieceGesture(mMouseX, mMouseY);
}

void SculptApp::endPieceGesture(bool keep)
{
    const std::size_t index = mDocument->activePiece();
    const DocumentPiece& moved = mDocument->pieces()[index];
    const char* verb = mGesture->kind() == PieceGesture::Kind::Move     ? "move '"
                       : mGesture->kind() == PieceGesture::Kind::Rotate ? "rotate '"
                                                                        : "scale '";
    const std::string label = verb + moved.look.name + "'";
    mGesture.reset();
    mDrag = Drag::None;
    if (!keep || mGestureShown == moved.look.placement) {
        mDisplay.setPlacement(moved.look.placement);
        mDialogs.notice = keep ? "" : "move dropped";
        return;
    }
    std::vector<std::size_t> pushed;
    if (mPushPieces) {
        const auto& pieces = mDocument->pieces();
        for (std::size_t i = 0; i < pieces.size(); ++i)
            if (i != index && pieces[i].look.visible &&
                overlap(bodyOf(moved, mGestureShown), bodyOf(pieces[i], pieces[i].look.placement)).any())
                pushed.push_back(i);
    }
    if (pushed.empty()) {
        mDocument->movePiece(index, mGestureShown, {}, label);
        mDialogs.notice = label + " (Ctrl+Z undoes it)";
        return;
    }
    startPushJob(index, mGestureShown, pushed, label);
}

void SculptApp::startPushJob(std::size_t index, const openvdb::Mat4d& placement, std::vector<std::size_t> pushed,
                             const std::string& label)
{
    using Dents = std::vector<std::pair<std::size_t, FieldImage>>;
    const auto& pieces = mDocument->pieces();
    const FieldImage pusher = pieces[index].session->field();
    std::vector<std::pair<Piece, std::size_t>> others;
    for (std::size_t i : pushed) others.push_back({asPiece(pieces[i]), i});
    startJob<Dents>(
        label + ", pushing " + std::to_string(pushed.size()),
        [pusher, placement, others](const Progress& progress) {
            Dents dents;
            for (std::size_t k = 0; k < others.size(); ++k) {
                FieldImage dented = others[k].first.field.deepCopy();
                pushAside(dented, others[k].first.placement, pusher, placement);
                dents.emplace_back(others[k].second, std::move(dented));
                report(progress, double(k + 1) / double(others.size()));
            }
            return dents;
        },
        [this, index, placement, label](Dents dents) {
            mDocument->movePiece(index, placement, std::move(dents), label);
            mDialogs.notice = label + ", the pieces in its way pushed aside (Ctrl+Z undoes both)";
        });
}

bool SculptApp::selectPieceAt(double x, double y)
{
    const Ray ray = mViewport.rayThrough(x, y);
    const auto& pieces = mDocument->pieces();
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
    selectPiece(chosen);
    return true;
}

}  // namespace sculpt::ui
