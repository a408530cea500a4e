// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file shape_display.h
/// @brief A whole shape other than the document, meshed once when it is set and drawn as one
///        actor: the target as a translucent ghost (what the follow brush and a morph go
///        towards), an import's preview.
///
/// The ghost's vertices are clustered to 2-voxel cells (a ghost needs the shape, not the detail,
/// and translucency costs pixels on Mesa); it shows front faces only, so it reads as one shell.

#include "core/field/field_image.h"

#include <vtkSmartPointer.h>

class vtkActor;

namespace sculpt {
class IncrementalMesher;
}
class vtkPlaneCollection;
class vtkRenderer;

namespace sculpt::ui {

struct ShapeStyle {
    double red = 1.0, green = 1.0, blue = 1.0;
    double opacity = 1.0;
    double clusterVoxels = 0.0;              ///< 0: full detail
    vtkPlaneCollection* clipping = nullptr;  ///< the clip plane's (clay: the other pieces)
    static ShapeStyle ghost() { return {0.45, 0.7, 1.0, 0.3, 2.0}; }
    static ShapeStyle preview() { return {0.93, 0.89, 0.8, 1.0, 0.0}; }     // bone
    static ShapeStyle primitives() { return {0.55, 0.9, 0.6, 0.55, 0.0}; }  // what a bake adds
};

class ShapeDisplay {
public:
    ShapeDisplay(vtkRenderer* renderer, ShapeStyle style);
    ~ShapeDisplay();

    /// Meshes `shape` and shows it (if shown); null removes it.
    void set(const FieldImage* shape);
    /// Shows what `mesher` holds now (a piece's live mesh), in a field of `voxelSize`.
    void set(const IncrementalMesher& mesher, double voxelSize);
    /// The look's colour.
    void setColour(double red, double green, double blue);
    void setShown(bool shown);
    /// Where the shape is drawn: world from its field's world (a piece's placement, row vectors).
    void setPlacement(const openvdb::Mat4d& placement);
    bool shown() const { return mShown; }
    std::size_t triangleCount() const { return mTriangles; }
    /// Where the shape is drawn, world (its placement applied); empty if nothing is set.
    openvdb::BBoxd worldBox() const;

private:
    vtkRenderer* mRenderer;
    ShapeStyle mStyle;
    vtkSmartPointer<vtkActor> mActor;
    bool mShown = true;
    std::size_t mTriangles = 0;
    openvdb::BBoxd mBox;  // the mesh's, in its field's world
    openvdb::Mat4d mPlacement = openvdb::Mat4d::identity();
};

}  // namespace sculpt::ui
