#pragma once
/// @file ghost_display.h
/// @brief A target shape (what the follow brush and a morph go towards) drawn as a translucent
///        ghost over the sculpt: meshed once when it is set, its vertices clustered to 2-voxel
///        cells (a ghost needs the shape, not the detail, and translucency costs pixels on Mesa),
///        front faces only so it reads as one shell.

#include "core/field/field_image.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class GhostDisplay {
public:
    explicit GhostDisplay(vtkRenderer* renderer);
    ~GhostDisplay();

    /// Meshes `shape` and shows it (if shown); null removes the ghost.
    void set(const FieldImage* shape);
    void setShown(bool shown);
    bool shown() const { return mShown; }
    std::size_t triangleCount() const { return mTriangles; }

private:
    vtkRenderer* mRenderer;
    vtkSmartPointer<vtkActor> mActor;
    bool mShown = true;
    std::size_t mTriangles = 0;
};

}  // namespace sculpt::ui
