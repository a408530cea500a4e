// SPDX-License-Identifier: Apache-2.0
#include "ui/view/viewport.h"

#include <glm/gtc/matrix_transform.hpp>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtk_glew.h>  // the OpenGL calls made here, as VTK loads them (no other GL header)

namespace sculpt::ui {

Ray transformedRay(const Ray& ray, const openvdb::Mat4d& m)
{
    const openvdb::Vec3d o = m.transform(openvdb::Vec3d(ray.origin.x, ray.origin.y, ray.origin.z));
    const openvdb::Vec3d d = m.transform3x3(openvdb::Vec3d(ray.direction.x, ray.direction.y, ray.direction.z)).unit();
    return {{o.x(), o.y(), o.z()}, {d.x(), d.y(), d.z()}};
}

namespace {

/// The window's context is GLFW's, always current on the UI thread: tell VTK so when it asks.
void reportCurrent(vtkObject*, unsigned long, void*, void* callData) { *static_cast<bool*>(callData) = true; }

}  // namespace

Viewport::Viewport(int width, int height, bool draws) : mWidth(width), mHeight(height), mDraws(draws)
{
    mWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    if (mDraws) {
        vtkNew<vtkCallbackCommand> isCurrent;
        isCurrent->SetCallback(reportCurrent);
        mWindow->AddObserver(vtkCommand::WindowIsCurrentEvent, isCurrent);
        mWindow->SetIsCurrent(true);
        mWindow->SetOwnContext(false);
        mWindow->InitializeFromCurrentContext();
    }
    mWindow->SetSize(width, height);
    mWindow->SetMultiSamples(0);

    mRenderer = vtkSmartPointer<vtkRenderer>::New();
    mRenderer->GradientBackgroundOn();
    mRenderer->SetBackground(0.16, 0.17, 0.19);   // bottom
    mRenderer->SetBackground2(0.36, 0.38, 0.42);  // top
    mRenderer->SetUseFXAA(false);
    mWindow->AddRenderer(mRenderer);

    mWindow->SetNumberOfLayers(2);
    mOverlay = vtkSmartPointer<vtkRenderer>::New();
    mOverlay->SetLayer(1);
    mOverlay->SetActiveCamera(mRenderer->GetActiveCamera());
    mOverlay->InteractiveOff();
    mWindow->AddRenderer(mOverlay);
}

Viewport::~Viewport()
{
    if (mDraws) mWindow->Finalize();
}

void Viewport::resize(int width, int height)
{
    mWidth = width;
    mHeight = height;
    mWindow->SetSize(width, height);
}

void Viewport::render()
{
    if (!mDraws) return;
    mWindow->GetState()->Reset();  // ImGui changed the GL state VTK caches
    mWindow->Render();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

vtkRenderWindow* Viewport::window() const { return mWindow; }

vtkCamera* Viewport::camera() const { return mRenderer->GetActiveCamera(); }

glm::dmat4 Viewport::worldToNdc() const
{
    vtkMatrix4x4* m = camera()->GetCompositeProjectionTransformMatrix(double(mWidth) / double(mHeight), -1.0, 1.0);
    glm::dmat4 out;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) out[c][r] = m->GetElement(r, c);  // GLM is column-major
    }
    return out;
}

glm::dmat4 Viewport::viewFromWorld() const
{
    const vtkMatrix4x4* m = camera()->GetViewTransformMatrix();
    glm::dmat4 view(1.0);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) view[col][row] = m->GetElement(row, col);
    return view;
}

bool Viewport::perspective() const { return camera()->GetParallelProjection() == 0; }

Ray Viewport::rayThrough(double x, double y) const
{
    const glm::dmat4 inverse = glm::inverse(worldToNdc());
    const double nx = 2.0 * x / mWidth - 1.0;
    const double ny = 1.0 - 2.0 * y / mHeight;
    const glm::dvec4 nearPoint = inverse * glm::dvec4(nx, ny, -1.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w;
    const glm::dvec3 b = glm::dvec3(farPoint) / farPoint.w;
    return {a, glm::normalize(b - a)};
}

glm::dvec3 Viewport::project(const glm::dvec3& world) const
{
    const glm::dvec4 ndc = worldToNdc() * glm::dvec4(world, 1.0);
    const glm::dvec3 p = glm::dvec3(ndc) / ndc.w;
    return {(p.x + 1.0) * 0.5 * mWidth, (1.0 - p.y) * 0.5 * mHeight, p.z};
}

double Viewport::pixelSizeAt(const glm::dvec3& world) const
{
    const glm::dvec3 p = project(world);
    const Ray a = rayThrough(p.x, p.y);
    const Ray b = rayThrough(p.x + 1.0, p.y);
    const double distance = glm::length(world - a.origin);
    return glm::length(a.direction - b.direction) * distance;
}

}  // namespace sculpt::ui
