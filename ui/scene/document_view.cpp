// SPDX-License-Identifier: Apache-2.0
#include "ui/scene/document_view.h"

#include "core/field/placed_box.h"
#include "core/field/pre_edit_field.h"
#include "sculpt/session/document.h"
#include "ui/view/block_polydata.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

namespace sculpt::ui {

namespace {

/// The coarse display stays on this long after the camera last moved.
constexpr double kNavigationSettleSeconds = 0.25;

const openvdb::Mat4d& placementOf(const Document& document)
{
    return document.pieces()[document.activePiece()].look.placement;
}

/// The clay's look, cut by the clip plane.
SurfaceLook lookClippedBy(const ClipPlane& clip)
{
    SurfaceLook look;
    look.setClipping(clip.planes());
    return look;
}

}  // namespace

DocumentView::DocumentView(int width, int height, bool draws, int chunkBlocks)
    : mViewport(width, height, draws), mLook(lookClippedBy(mClip)), mDisplay(mViewport.renderer(), mLook, chunkBlocks),
      mScales(mViewport.renderer()), mGhost(mViewport.renderer(), ShapeStyle::ghost()),
      mPieces(mViewport.renderer(), mClip.planes()), mCursor(mViewport.overlay()), mPlanes(mViewport.renderer()),
      mCamera(mViewport), mCaps(mViewport.renderer()), mSlices(mViewport.window(), mViewport.overlay())
{}

void DocumentView::show(const Document& document, bool frameIt)
{
    mPicker.reset();
    mActiveShown = &document.session();
    mPiecesShown = ~std::uint64_t(0);
    syncPieces(document);
    mDisplay.sync(*document.session().mesher(), document.session().field().voxelSize());
    if (frameIt) frameAll(document);
}

void DocumentView::showPreview(const OpenPreview::Surface& preview)
{
    mDisplay.showPreview(preview.mesh, *preview.xform);
    if (preview.mesh.positions.empty()) return;
    const auto [lo, hi] = boundsOf(preview.mesh.positions.data(), preview.mesh.positions.size());
    mCamera.frame(lo, hi);
}

bool DocumentView::syncPieces(const Document& document)
{
    if (mPiecesShown == document.piecesRevision() && mActiveShown == &document.session()) return false;
    mPiecesShown = document.piecesRevision();
    const bool another = mActiveShown != &document.session();
    if (another) {
        mActiveShown = &document.session();
        mPicker.reset();
    }
    std::vector<DrawnPiece> others;
    const auto& pieces = document.pieces();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const SculptSession& session = *pieces[i].session;
        if (i != document.activePiece())
            others.push_back({&pieces[i].look, session.mesher(), session.field().voxelSize()});
    }
    mPieces.sync(others);
    mDisplay.setPlacement(placementOf(document));
    return another;
}

openvdb::BBoxd DocumentView::worldBox(const Document& document) const
{
    openvdb::BBoxd world = mPieces.worldBox();
    world.expand(placedBox(leafWorldBox(document.session().field()), placementOf(document)));
    return world;
}

void DocumentView::frameAll(const Document& document)
{
    const openvdb::BBoxd world = worldBox(document);
    if (world.empty()) return;
    mCamera.frame({world.min().x(), world.min().y(), world.min().z()},
                  {world.max().x(), world.max().y(), world.max().z()});
}

std::optional<SurfaceHit> DocumentView::pickAt(const Document& document, double x, double y)
{
    if (x < 0 || y < 0 || x >= mViewport.width() || y >= mViewport.height()) return std::nullopt;
    if (mSlices.viewAt(x, y)) return std::nullopt;
    if (const std::optional<SectionPlane> plane = mClip.plane())
        return pickClipped(document, mViewport.rayThrough(x, y), *plane);
    const SculptSession& session = document.session();
    // In the piece's own world: its placement moved the drawing, never the voxels.
    return mPicker.pick(session.field(), session.mesher()->version(),
                        transformedRay(mViewport.rayThrough(x, y), placementOf(document).inverse()),
                        session.strokeJournal());
}

std::optional<SurfaceHit> DocumentView::pickClipped(const Document& document, const Ray& ray, const SectionPlane& plane)
{
    const SculptSession& session = document.session();
    const openvdb::Mat4d fieldFromWorld = placementOf(document).inverse();
    const glm::dvec3 n(plane.normal.x(), plane.normal.y(), plane.normal.z());
    const glm::dvec3 o(plane.origin.x(), plane.origin.y(), plane.origin.z());
    const double side = glm::dot(ray.origin - o, n), along = glm::dot(ray.direction, n);
    const auto inField = [&](const glm::dvec3& p) { return fieldFromWorld.transform(openvdb::Vec3d(p.x, p.y, p.z)); };
    Ray shown = ray;
    if (side > 0.0) {  // the eye on the hidden side: the ray shows nothing before the plane
        if (along >= 0.0) return std::nullopt;
        shown.origin = ray.origin + ray.direction * (-side / along);
        const openvdb::Vec3d at = inField(shown.origin);
        const PreEditField before(session.field(), session.strokeJournal());  // as the stroke began, as pick()
        if (before.sample(session.field().grid().transform().worldToIndex(at)) <
            0.0) {  // the plane in the clay: the cap
            const openvdb::Vec3d normal = fieldFromWorld.transform3x3(plane.normal).unit();
            return SurfaceHit{{at.x(), at.y(), at.z()}, {normal.x(), normal.y(), normal.z()}};
        }
    }
    const std::optional<SurfaceHit> hit = mPicker.pick(session.field(), session.mesher()->version(),
                                                       transformedRay(shown, fieldFromWorld), session.strokeJournal());
    if (hit && mClip.hides(inWorld(document, *hit).position)) return std::nullopt;
    return hit;
}

bool DocumentView::sliceMouse(const Document& document, const InputEvent& event, double x, double y)
{
    const bool onModel = event.type == EventType::MouseButton && event.press && event.button == kLeftButton &&
                         mSlices.shown() && mSlices.hasScan() && !mSlices.viewAt(x, y);
    if (onModel) {
        if (const std::optional<SurfaceHit> hit = pickAt(document, x, y))
            mSlices.setCursor(inWorld(document, *hit).position);
        return false;  // the tool takes the press too
    }
    return mSliceMouse.handle(mSlices, event, x, y);
}

SurfaceHit DocumentView::inWorld(const Document& document, const SurfaceHit& hit) const
{
    const openvdb::Mat4d& placement = placementOf(document);
    const openvdb::Vec3d p = placement.transform(openvdb::Vec3d(hit.position.x, hit.position.y, hit.position.z));
    // Rigid moves and uniform scales: the normal turns as a direction does.
    const openvdb::Vec3d n = placement.transform3x3(openvdb::Vec3d(hit.normal.x, hit.normal.y, hit.normal.z)).unit();
    return {{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}};
}

const std::optional<SurfaceHit>& DocumentView::hover(const Document& document, double x, double y, bool picking)
{
    const SculptSession& session = document.session();
    const bool inView = x >= 0 && y >= 0 && x < mViewport.width() && y < mViewport.height();
    const HoverKey key{mViewport.rayThrough(x, y),  session.field().id(), session.mesher()->id(),
                       session.mesher()->version(), mClip.revision(),     inView && picking};
    if (key != mHoverKey) {
        mHover = key.picking ? pickAt(document, x, y) : std::nullopt;
        mHoverKey = key;
    }
    return mHover;
}

void DocumentView::placeCursor(const Document& document, bool shown, BrushTool tool, const BrushOptions& brush)
{
    if (tool == BrushTool::Carve || tool == BrushTool::Deflate) mCursor.setColour(1.0, 0.55, 0.5);
    else if (tool == BrushTool::Smooth) mCursor.setColour(0.6, 0.8, 1.0);
    else if (tool == BrushTool::Mask || tool == BrushTool::Unmask) mCursor.setColour(0.45, 0.45, 0.5);
    else mCursor.setColour(1.0, 1.0, 1.0);
    if (shown && mHover) {
        const SurfaceHit at = inWorld(document, *mHover);
        mCursor.place(true, at.position, at.normal, brush.radius, brush.symmetry);
    } else mCursor.place(false, {}, {}, 0.0, {});
}

void DocumentView::zoomAt(const Document& document, double x, double y, double factor)
{
    const std::optional<SurfaceHit> hit = pickAt(document, x, y);
    const Ray ray = mViewport.rayThrough(x, y);
    const double focalDistance = glm::length(mCamera.focalPoint() - ray.origin);
    mCamera.zoomTowards(hit ? inWorld(document, *hit).position : ray.origin + ray.direction * focalDistance, factor);
}

DetailView DocumentView::detailView(double now, bool stroking, bool underBudget, double brushRadius)
{
    if (mCamera.moves() != mCameraMovesSeen) {
        mCameraMovesSeen = mCamera.moves();
        mLastNavigation = now;
    }
    const bool moving = mLastNavigation >= 0.0 && now - mLastNavigation < kNavigationSettleSeconds;
    DetailView view;
    view.still = !(moving || stroking) || underBudget;
    view.eye = mCamera.eye();
    view.pixelSizeAt = [this](const glm::dvec3& p) { return mViewport.pixelSizeAt(p); };
    if (mHover) {
        view.brushCentre = mHover->position;
        view.brushRadius = brushRadius;
    }
    view.triangleBudget = std::size_t(mViewport.width()) * std::size_t(mViewport.height());
    return view;
}

void DocumentView::sync(const Document& document, const IncrementalMesher* modeMesh, bool hideDocument, double now,
                        bool stroking, bool underBudget, const BrushOptions& brush, double modelSize)
{
    const SculptSession& session = document.session();
    const IncrementalMesher& shown = modeMesh ? *modeMesh : *session.mesher();
    SurfaceTint tint = mCheck;
    tint.mask = session.field().mask();
    tint.surface = &session.field().grid();
    mDisplay.sync(shown, session.field().voxelSize(), detailView(now, stroking, underBudget, brush.radius), tint);
    mScales.sync(shown, session.field().voxelSize());
    mDisplay.setHidden(mScales.shown() || hideDocument);
    mPieces.setHidden(mScales.shown() || hideDocument);
    mPlanes.show(brush.symmetry, 0.6 * modelSize);
    std::vector<FieldPiece> cut;
    const openvdb::Vec3f clay{float(kClayColour[0]), float(kClayColour[1]), float(kClayColour[2])};
    for (const DocumentPiece& piece : document.pieces()) {
        const bool sculpted = piece.session.get() == &document.session();
        cut.push_back({&piece.look, sculpted ? clay : piece.look.colour, sculpted, &piece.session->field(),
                       piece.session->mesher(), piece.session->mesher()->version()});
    }
    const bool hidden = mScales.shown() || hideDocument;
    mCaps.sync(cut, hidden ? std::nullopt : mClip.plane(), mClip.revision());
    mSlices.setScan(document.keptScan());
    mSlices.layout(mViewport.width(), mViewport.height());
    mSlices.sync(cut);
}

void DocumentView::report(nlohmann::json& out) const
{
    out["blocks"] = mDisplay.blockCount();
    out["mesh_bytes"] = mDisplay.meshBytes();
    out["display_pending_chunks"] = mDisplay.pendingChunks();  // still drawn from a preview
    out["scales"] = mScales.shown() ? mScales.scaleCount() : 0;
    out["ghost_triangles"] = mGhost.shown() ? mGhost.triangleCount() : 0;
    out["other_pieces"] = mPieces.count();
    out["other_pieces_triangles"] = mPieces.trianglesShown();
    out["xray"] = mLook.xray();
    out["coarse"] = mDisplay.coarseChunks() > 0;  // this frame, some chunks drawn coarse
    out["coarse_chunks"] = mDisplay.coarseChunks();
    out["chunks"] = mDisplay.chunkCount();
    out["chunk_blocks"] = mDisplay.chunkBlocks();
    out["actors"] = mDisplay.actorCount();
    out["triangles_drawn"] = mDisplay.trianglesDrawn();
    out["clip"] = kClipAxisNames[int(mClip.axis())];
    out["clip_offset"] = mClip.offset();
    out["cap_area"] = mCaps.area();
    out["cap_triangles"] = mCaps.triangleCount();
    out["cap_remakes"] = mCaps.remakes();
    nlohmann::json slices = {{"shown", mSlices.shown() && mSlices.hasScan()},
                             {"cursor", {mSlices.cursor().x, mSlices.cursor().y, mSlices.cursor().z}},
                             {"window", mSlices.window()},
                             {"level", mSlices.level()}};
    for (int a = 0; a < 3; ++a) slices[kSliceNames[a]] = mSlices.contourSegments(SliceAxis(a));
    out["slices"] = slices;
}

}  // namespace sculpt::ui
