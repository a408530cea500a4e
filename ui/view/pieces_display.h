// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file pieces_display.h
/// @brief The document's pieces besides the one being sculpted, each drawn from its own live
///        mesh in its colour and placement, and re-drawn only when its mesh or look changed.

#include "core/field/piece.h"
#include "core/mesh/incremental_mesher.h"
#include "ui/view/shape_display.h"

#include <memory>
#include <vector>

class vtkPlaneCollection;
class vtkRenderer;

namespace sculpt::ui {

/// A piece to draw: its look and its live mesh, in a field of `voxelSize`.
struct DrawnPiece {
    const PieceLook* look;
    const IncrementalMesher* mesher;
    double voxelSize;
};

class PiecesDisplay {
public:
    /// `clipping`: the clip plane's planes, which the pieces are cut by as the model is.
    PiecesDisplay(vtkRenderer* renderer, vtkPlaneCollection* clipping) : mRenderer(renderer), mClipping(clipping) {}

    /// Draws `pieces` (in place of what it drew); a mesh drawn before is not drawn again. Called
    /// when the pieces changed, not per frame.
    void sync(const std::vector<DrawnPiece>& pieces);
    /// Hides them all (the scales view, a mode's preview), or shows the visible ones.
    void setHidden(bool hidden);

    std::size_t count() const { return mDrawn.size(); }
    /// Triangles of the pieces shown.
    std::size_t trianglesShown() const;
    /// The world box of the pieces shown (empty if none): framing shows them too.
    const openvdb::BBoxd& worldBox() const { return mBox; }

private:
    struct Drawn {
        std::uint64_t mesherId = 0, version = 0;
        PieceLook look;
        std::unique_ptr<ShapeDisplay> display;
    };

    vtkRenderer* mRenderer;
    vtkPlaneCollection* mClipping;
    std::vector<Drawn> mDrawn;
    openvdb::BBoxd mBox;
    bool mHidden = false;
};

}  // namespace sculpt::ui
