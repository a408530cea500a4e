// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file viewport.h
/// @brief The 3D view: a VTK renderer drawing into the window's current OpenGL context, its
///        camera, and the maths between window pixels and world space (GLM).

#include <glm/glm.hpp>
#include <openvdb/Types.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

class vtkCamera;
class vtkGenericOpenGLRenderWindow;
class vtkRenderWindow;

namespace sculpt::ui {

/// A ray in world space.
struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  ///< unit
};

/// `ray` carried by `m` (row vectors, as OpenVDB's placements), its direction kept unit: a world
/// ray in a piece's own world, with the inverse of its placement.
Ray transformedRay(const Ray& ray, const openvdb::Mat4d& m);

class Viewport {
public:
    /// `draws`: the window's OpenGL context is current and render() draws into it; false: a
    /// view with no context (headless), whose cameras and rays work and which draws nothing.
    Viewport(int width, int height, bool draws = true);
    ~Viewport();

    void resize(int width, int height);
    /// Draws the scene into the current framebuffer (the window's back buffer), if it draws.
    void render();

    vtkRenderer* renderer() const { return mRenderer; }
    /// The render window the scene's renderers draw in (insets such as the slice views join it).
    vtkRenderWindow* window() const;
    /// A renderer layered over the scene, sharing its camera: what must never hide (the cursor).
    vtkRenderer* overlay() const { return mOverlay; }
    vtkCamera* camera() const;
    int width() const { return mWidth; }
    int height() const { return mHeight; }

    /// View from world (column vectors, as GLM's): the camera's frame, looking down its -z.
    glm::dmat4 viewFromWorld() const;
    /// Whether rays leave one eye (else the projection is parallel).
    bool perspective() const;
    /// The ray from the eye through window pixel (x, y) (origin top left).
    Ray rayThrough(double x, double y) const;
    /// Window pixel of a world point; z in [-1, 1] is its depth (NDC).
    glm::dvec3 project(const glm::dvec3& world) const;
    /// World length of one pixel at `world`'s depth.
    double pixelSizeAt(const glm::dvec3& world) const;

private:
    glm::dmat4 worldToNdc() const;

    vtkSmartPointer<vtkGenericOpenGLRenderWindow> mWindow;
    vtkSmartPointer<vtkRenderer> mRenderer;
    vtkSmartPointer<vtkRenderer> mOverlay;
    int mWidth, mHeight;
    bool mDraws;
};

}  // namespace sculpt::ui
