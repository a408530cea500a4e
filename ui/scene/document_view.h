// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file document_view.h
/// @brief The open document as the 3D view shows it: the viewport and its camera, the look, the
///        sculpted piece drawn at its placement and the other pieces in their colours, the scales,
///        the target's ghost, the brush cursor and the symmetry planes, the print check's tint;
///        and what lies under the pointer, picked on the sculpted piece's level set.
///
/// It draws and picks; it edits nothing. Nothing here walks the whole model per frame: the
/// displays upload what the meshers changed, the hover is picked again only when what it
/// depends on changed (HoverKey).

#include "ui/document/open_preview.h"
#include "ui/input/input_event.h"
#include "ui/scene/slice_mouse.h"
#include "ui/sculpting/brush_options.h"
#include "ui/sculpting/hover_key.h"
#include "ui/sculpting/surface_picker.h"
#include "ui/view/brush_cursor.h"
#include "ui/view/camera_control.h"
#include "ui/view/cap_display.h"
#include "ui/view/clip_plane.h"
#include "ui/view/detail_view.h"
#include "ui/view/model_display.h"
#include "ui/view/pieces_display.h"
#include "ui/view/scales_display.h"
#include "ui/view/shape_display.h"
#include "ui/view/slice_views.h"
#include "ui/view/surface_look.h"
#include "ui/view/surface_tint.h"
#include "ui/view/symmetry_planes.h"
#include "ui/view/viewport.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>

namespace sculpt {
class Document;
class IncrementalMesher;
class SculptSession;
}  // namespace sculpt

namespace sculpt::ui {

class DocumentView {
public:
    /// `draws`: the window has an OpenGL context to draw into (Viewport); `chunkBlocks`: the
    /// display's chunk edge in blocks (0: chosen from the model).
    DocumentView(int width, int height, bool draws, int chunkBlocks);

    Viewport& viewport() { return mViewport; }
    const Viewport& viewport() const { return mViewport; }
    SurfaceLook& look() { return mLook; }
    const SurfaceLook& look() const { return mLook; }
    CameraControl& camera() { return mCamera; }
    const CameraControl& camera() const { return mCamera; }
    ModelDisplay& display() { return mDisplay; }
    const ModelDisplay& display() const { return mDisplay; }
    ScalesDisplay& scales() { return mScales; }
    const ScalesDisplay& scales() const { return mScales; }
    ShapeDisplay& ghost() { return mGhost; }
    const ShapeDisplay& ghost() const { return mGhost; }
    const PiecesDisplay& pieces() const { return mPieces; }
    SurfacePicker& picker() { return mPicker; }
    /// The print check the clay shows (View > Print Check) and its thresholds.
    SurfaceTint& printCheck() { return mCheck; }
    /// View > Clip Plane; its caps follow at the next sync().
    ClipPlane& clip() { return mClip; }
    const ClipPlane& clip() const { return mClip; }
    /// The caps of the clip plane's cut.
    const CapDisplay& caps() const { return mCaps; }
    /// View > Slices: the kept scan's planes through a cursor.
    SliceViews& slices() { return mSlices; }
    const SliceViews& slices() const { return mSlices; }
    /// The mouse for the Slices view (SliceMouse); a left press on the model also moves their
    /// cursor there. @return whether the event was the slices' alone.
    bool sliceMouse(const Document& document, const InputEvent& event, double x, double y);

    /// A new document: what was drawn and picked of the old one goes; `frameIt` fits the camera.
    void show(const Document& document, bool frameIt);
    /// A document being made shows its coarse preview meanwhile, framed by the camera.
    void showPreview(const OpenPreview::Surface& preview);
    /// Brings the drawing of the pieces up to date once they changed: the sculpted one in the
    /// model display at its placement, the others in their colours. @return true if another
    /// piece became the one sculpted (what is measured of it starts again).
    bool syncPieces(const Document& document);
    /// The pieces are drawn again as the document has them at the next syncPieces (a move shown
    /// that did not land goes back).
    void redrawPieces() { mPiecesShown = ~std::uint64_t(0); }
    /// Fits every piece shown in the view.
    void frameAll(const Document& document);
    /// The box of every piece shown, in the world.
    openvdb::BBoxd worldBox(const Document& document) const;

    /// The sculpted piece's surface under the pixel, in its field's world (where edits are made):
    /// with the clip plane on, the cap where the ray meets the plane inside the clay, else the
    /// surface on the side shown; none over the Slices view.
    std::optional<SurfaceHit> pickAt(const Document& document, double x, double y);
    /// A hit of pickAt in the world (the piece's placement applied).
    SurfaceHit inWorld(const Document& document, const SurfaceHit& hit) const;
    /// The surface under the pointer at (x, y), picked again only if its HoverKey changed;
    /// `picking` false, or the pointer off the view: none (the camera or a setting is dragged).
    const std::optional<SurfaceHit>& hover(const Document& document, double x, double y, bool picking);
    /// The surface under the pointer as last picked by hover().
    const std::optional<SurfaceHit>& hovered() const { return mHover; }
    /// The brush cursor at the hover if `shown`, coloured for `tool` (white adds, red takes
    /// away, blue smooths, grey masks), with the brush's radius and mirrors.
    void placeCursor(const Document& document, bool shown, BrushTool tool, const BrushOptions& brush);
    /// Zooms by `factor` towards the surface under the pixel, else towards the focal plane there.
    void zoomAt(const Document& document, double x, double y, double factor);

    /// Once a frame: the shown mesh (the document's, or `modeMesh` a mode shows instead) at its
    /// level of detail, the scales, the tint, which displays are hidden, the symmetry planes.
    /// Far parts are drawn coarse while the camera moves or `stroking`, unless `underBudget`.
    void sync(const Document& document, const IncrementalMesher* modeMesh, bool hideDocument, double now, bool stroking,
              bool underBudget, const BrushOptions& brush, double modelSize);

    /// What the view shows, in the window's report (display, uploads kept elsewhere, scales,
    /// ghost, other pieces, look).
    void report(nlohmann::json& out) const;

private:
    /// pickAt's ray, in the world, against the clip plane.
    std::optional<SurfaceHit> pickClipped(const Document& document, const Ray& ray, const SectionPlane& plane);
    DetailView detailView(double now, bool stroking, bool underBudget, double brushRadius);

    Viewport mViewport;
    ClipPlane mClip;  // before the look and the displays, whose mappers take its planes
    SurfaceLook mLook;
    ModelDisplay mDisplay;
    ScalesDisplay mScales;
    ShapeDisplay mGhost;    // the follow target
    PiecesDisplay mPieces;  // the pieces not being sculpted
    BrushCursor mCursor;
    SymmetryPlanes mPlanes;
    CameraControl mCamera;
    SurfacePicker mPicker;
    SurfaceTint mCheck;
    CapDisplay mCaps;
    SliceViews mSlices;
    SliceMouse mSliceMouse;
    std::uint64_t mPiecesShown = ~std::uint64_t(0);  // the document's piecesRevision drawn
    const SculptSession* mActiveShown = nullptr;     // the session the model display shows
    std::optional<SurfaceHit> mHover;                // the surface under the pointer, picked for mHoverKey
    HoverKey mHoverKey;
    double mLastNavigation = -1.0;  // when the camera last moved (level of detail)
    std::uint64_t mCameraMovesSeen = 0;
};

}  // namespace sculpt::ui
