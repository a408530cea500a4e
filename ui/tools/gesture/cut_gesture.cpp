// SPDX-License-Identifier: Apache-2.0
#include "ui/tools/gesture/cut_gesture.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>

namespace sculpt::ui {

namespace {

constexpr double kLassoStepPixels = 3.0;  // a lasso point per this many pixels moved
constexpr double kSmallestPixels = 4.0;   // a gesture smaller than this is a click

}  // namespace

void CutGesture::begin(Shape shape, double x, double y)
{
    mShape = shape;
    mPoints = {{x, y}};
    if (shape != Shape::Lasso) mPoints.push_back({x, y});
}

void CutGesture::extend(double x, double y)
{
    if (mPoints.empty()) return;
    if (mShape != Shape::Lasso) {
        mPoints.back() = {x, y};
    } else if (glm::length(glm::dvec2(x, y) - mPoints.back()) >= kLassoStepPixels) {
        mPoints.push_back({x, y});
    }
}

std::vector<glm::dvec2> CutGesture::outline() const
{
    if (mShape != Shape::Box || mPoints.size() < 2) return mPoints;
    const glm::dvec2 a = mPoints.front(), b = mPoints.back();
    return {a, {b.x, a.y}, b, {a.x, b.y}};
}

std::optional<ViewPrism> CutGesture::prism(const Viewport& view, double nearDepth, double farDepth,
                                           const Symmetry& symmetry) const
{
    const std::vector<glm::dvec2> outlined = outline();
    if (outlined.size() < 2 || glm::length(outlined.back() - outlined.front()) < kSmallestPixels) {
        if (mShape != Shape::Lasso || outlined.size() < 3) return std::nullopt;
    }
    ViewPrism prism;
    const glm::dmat4 v = view.viewFromWorld();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) prism.viewFromWorld(i, j) = v[i][j];  // GLM's columns are OpenVDB's rows
    prism.perspective = view.perspective();
    // Each pixel as the view plane's coordinates of its ray: tangents (perspective) or world units.
    std::vector<openvdb::Vec2d> points;
    for (const glm::dvec2& pixel : outlined) {
        const Ray ray = view.rayThrough(pixel.x, pixel.y);
        if (prism.perspective) {
            const glm::dvec3 d = glm::dmat3(v) * ray.direction;
            points.emplace_back(d.x / -d.z, d.y / -d.z);
        } else {
            const glm::dvec4 o = v * glm::dvec4(ray.origin, 1.0);
            points.emplace_back(o.x, o.y);
        }
    }
    if (mShape == Shape::Line) {
        // Far beyond the view: the half-plane's polygon must hold every ray that sees the model.
        points = halfPlanePolygon(points[0], points[1], prism.perspective ? 1e3 : 1e6);
    }
    prism.polygon = std::move(points);
    prism.nearDepth = nearDepth;
    prism.farDepth = farDepth;
    prism.mirror = {symmetry.x, symmetry.y, symmetry.z};
    return prism;
}

}  // namespace sculpt::ui
