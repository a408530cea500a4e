// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file wire_display.h
/// @brief A triangle mesh drawn as its edges over the surface: the morph's tracked mesh, so one
///        sees its triangles keep their places (and where they split, collapse or re-seed).
///
/// The lines are unlit and pulled towards the camera (VTK's coincident-topology offset): the
/// tracked mesh's chords lie a hair inside the marching-cubes surface they are drawn over.

#include "core/mesh/triangle_mesh.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace sculpt::ui {

class WireDisplay {
public:
    explicit WireDisplay(vtkRenderer* renderer);
    ~WireDisplay();
    WireDisplay(const WireDisplay&) = delete;
    WireDisplay& operator=(const WireDisplay&) = delete;

    /// Shows `mesh`'s edges (if shown); null removes them.
    void set(const TriangleMesh* mesh);
    void setShown(bool shown);
    bool shown() const { return mShown; }

private:
    vtkRenderer* mRenderer;
    vtkSmartPointer<vtkActor> mActor;
    bool mShown = true;
};

}  // namespace sculpt::ui
