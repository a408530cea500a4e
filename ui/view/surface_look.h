// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file surface_look.h
/// @brief How the clay looks: matcaps (clay, white, red wax) or lit, smooth or flat, wireframe.
///
/// One vtkProperty and one vtkShaderProperty serve every block of the model: a change here is
/// one shader rebuild, not one per block. A matcap is a colour per view-space normal; ours are
/// evaluated in the fragment shader from a few parameters instead of sampled from an image, so
/// there is no texture to ship and no seam at any zoom. Switching matcaps changes uniforms only.

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPlaneCollection;
class vtkProperty;
class vtkShaderProperty;

namespace sculpt::ui {

enum class Shading { Clay, White, RedWax, Lit };
/// The clay's colour (lit shading); points coloured darker than it (a mask's tint) darken every
/// matcap by the same ratio.
inline constexpr double kClayColour[3] = {0.80, 0.66, 0.55};
inline constexpr const char* kShadingNames[] = {"Clay", "White", "Red wax", "Lit"};

class SurfaceLook {
public:
    SurfaceLook();

    void setShading(Shading shading);
    Shading shading() const { return mShading; }
    void setFlat(bool flat);
    bool flat() const { return mFlat; }
    void setWireframe(bool wireframe);
    bool wireframe() const { return mWireframe; }
    /// See-through clay (Blender's X-ray): what lies inside shows, the skeletons of primitives.
    void setXRay(bool xray);
    bool xray() const { return mXRay; }

    /// The planes every clay actor is clipped by (ClipPlane::planes()); set before apply().
    void setClipping(vtkPlaneCollection* planes);
    /// Gives an actor the shared look (and its mapper the clipping planes).
    void apply(vtkActor* actor) const;

private:
    vtkSmartPointer<vtkProperty> mProperty;
    vtkSmartPointer<vtkShaderProperty> mShader;
    vtkSmartPointer<vtkPlaneCollection> mClipping;
    Shading mShading = Shading::Clay;
    bool mFlat = false;
    bool mWireframe = false;
    bool mXRay = false;
};

}  // namespace sculpt::ui
