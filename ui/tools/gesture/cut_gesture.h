// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file cut_gesture.h
/// @brief A cut drawn on the screen: a box (two corners), a lasso (the pointer's path) or a line
///        (two points: what lies to the right of its direction, as seen, is cut), and the prism
///        along the view it makes (core/solids/prism_cut.h).

#include "core/solids/prism_cut.h"
#include "sculpt/session/stroke.h"
#include "ui/view/viewport.h"

#include <glm/vec2.hpp>

#include <optional>
#include <vector>

namespace sculpt::ui {

class CutGesture {
public:
    enum class Shape { Lasso, Box, Line };

    void begin(Shape shape, double x, double y);
    /// The pointer moved: a lasso adds the point (a few pixels from the last), a box or a line
    /// moves its second corner.
    void extend(double x, double y);
    void clear() { mPoints.clear(); }
    bool active() const { return !mPoints.empty(); }
    Shape shape() const { return mShape; }
    /// What to draw, in window pixels: the box's four corners, the lasso's path, the line's ends.
    std::vector<glm::dvec2> outline() const;
    /// The prism the gesture sweeps in `view`, between depths `nearDepth` and `farDepth`, mirrored
    /// by `symmetry`; none for a gesture too small to cut anything (a click).
    std::optional<ViewPrism> prism(const Viewport& view, double nearDepth, double farDepth,
                                   const Symmetry& symmetry) const;

private:
    Shape mShape = Shape::Lasso;
    std::vector<glm::dvec2> mPoints;
};

}  // namespace sculpt::ui
