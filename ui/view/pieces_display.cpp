// SPDX-License-Identifier: Apache-2.0
#include "ui/view/pieces_display.h"

#include <algorithm>

namespace sculpt::ui {

void PiecesDisplay::sync(const std::vector<DrawnPiece>& pieces)
{
    std::vector<Drawn> drawn;
    mBox = openvdb::BBoxd();
    for (const DrawnPiece& piece : pieces) {
        // The same mesh drawn before is kept (a piece's place in the list may change).
        auto kept = std::find_if(mDrawn.begin(), mDrawn.end(), [&](const Drawn& d) {
            return d.display && d.mesherId == piece.mesher->id() && d.version == piece.mesher->version();
        });
        Drawn entry;
        if (kept != mDrawn.end()) {
            entry = std::move(*kept);
        } else {
            entry.display = std::make_unique<ShapeDisplay>(mRenderer, ShapeStyle{1.0, 1.0, 1.0, 1.0, 0.0, mClipping});
            entry.display->set(*piece.mesher, piece.voxelSize);
            entry.mesherId = piece.mesher->id();
            entry.version = piece.mesher->version();
        }
        entry.look = *piece.look;
        entry.display->setColour(entry.look.colour[0], entry.look.colour[1], entry.look.colour[2]);
        entry.display->setPlacement(entry.look.placement);
        entry.display->setShown(entry.look.visible && !mHidden);
        if (entry.look.visible) mBox.expand(entry.display->worldBox());
        drawn.push_back(std::move(entry));
    }
    mDrawn = std::move(drawn);  // the pieces gone (deleted, now active) leave the renderer here
}

void PiecesDisplay::setHidden(bool hidden)
{
    if (hidden == mHidden) return;
    mHidden = hidden;
    for (Drawn& d : mDrawn) d.display->setShown(d.look.visible && !hidden);
}

std::size_t PiecesDisplay::trianglesShown() const
{
    std::size_t triangles = 0;
    for (const Drawn& d : mDrawn) triangles += d.display->shown() ? d.display->triangleCount() : 0;
    return triangles;
}

}  // namespace sculpt::ui
