// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file slice_views.h
/// @brief View > Slices: the kept scan's axial, coronal and sagittal planes through one cursor,
///        as every scan viewer shows them, with each piece's contour on them (its section from
///        its field) and the cursor's crosshair; a small cross marks the cursor in the 3D view.
///
/// The three views sit in a row at the window's bottom, between the panels' columns. In a view: a left press or drag
/// puts the cursor there (the other two views follow), a right drag sets the window (across) and
/// the level (up and down), the wheel steps through the slices. A click on the model moves the
/// cursor to it (SliceViews::setCursor). Axial and coronal views show the patient's right on the
/// left, as radiologists read them (x of LPS grows to the screen's right); the sagittal view
/// shows the front to the left. A slice is sampled again only when its plane or the scan changes;
/// contours when a piece or the cursor does.

#include "ui/view/cap_display.h"

#include <glm/glm.hpp>
#include <openvdb/openvdb.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

class vtkActor;
class vtkImageActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;

namespace sculpt::ui {

/// Which slice: the plane normal to the patient frame's x (sagittal), y (coronal) or z (axial).
enum class SliceAxis { Sagittal, Coronal, Axial };
inline constexpr const char* kSliceNames[] = {"Sagittal", "Coronal", "Axial"};

/// A rectangle of window pixels, origin top left.
struct PixelRect {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
    bool contains(double px, double py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

class SliceViews {
public:
    /// Its views are drawn into `window` (the 3D view's), the cursor's cross into `overlay`.
    SliceViews(vtkRenderWindow* window, vtkRenderer* overlay);
    ~SliceViews();

    bool shown() const { return mShown; }
    void setShown(bool shown);
    /// The scan shown (a document's kept scan), or none; a new one puts the cursor at its centre.
    void setScan(openvdb::FloatGrid::ConstPtr scan);
    bool hasScan() const { return mScan != nullptr; }

    /// Where the views go in a window of `width` x `height` pixels.
    void layout(int width, int height);
    /// The view under window pixel (x, y), if the views are shown.
    std::optional<SliceAxis> viewAt(double x, double y) const;
    const PixelRect& rect(SliceAxis axis) const { return mViews[std::size_t(axis)].rect; }

    /// The cursor (world): the point the three planes pass through.
    const glm::dvec3& cursor() const { return mCursor; }
    void setCursor(const glm::dvec3& world);
    /// The world point under pixel (x, y) of a view, on its plane.
    glm::dvec3 worldAt(SliceAxis axis, double x, double y) const;
    /// Moves a view's plane by `steps` of the scan's spacing.
    void step(SliceAxis axis, double steps);

    /// Window and level of the samples' grey ramp.
    double window() const { return mWindow; }
    double level() const { return mLevel; }
    void setWindowLevel(double window, double level);
    /// The samples' range: what a drag of the window or level scales by.
    double sampleRange() const { return mRangeHigh - mRangeLow; }

    /// Brings the views up to date: the slices, the pieces' contours, the crosshairs.
    void sync(const std::vector<FieldPiece>& pieces);
    /// Contour segments drawn in each view (the report; a test that contours show).
    std::size_t contourSegments(SliceAxis axis) const { return mViews[std::size_t(axis)].segments; }
    /// The samples of a view's slice as last drawn (tests), x fastest from its bottom left.
    vtkImageData* sliceImage(SliceAxis axis) const;

private:
    struct View {
        SliceAxis axis;
        PixelRect rect;
        vtkSmartPointer<vtkRenderer> renderer;
        vtkSmartPointer<vtkImageActor> image;
        vtkSmartPointer<vtkActor> contours, crosshair;
        double sampledAt = 0.0;  // the plane the image holds
        bool sampled = false;
        std::size_t segments = 0;
    };
    /// The view's screen axes in the world: right and up.
    static std::pair<glm::dvec3, glm::dvec3> screenAxes(SliceAxis axis);
    /// The scan's box on a view's screen axes: its lowest and highest (right, up).
    std::pair<glm::dvec2, glm::dvec2> scanExtent(SliceAxis axis) const;
    void sample(View& view);
    void drawContours(View& view, const std::vector<FieldPiece>& pieces);
    void drawCrosshair(View& view);
    void frameCamera(View& view);
    void placeMarker();

    vtkRenderWindow* mWindow3d;
    vtkRenderer* mOverlay;
    std::array<View, 3> mViews;
    vtkSmartPointer<vtkActor> mMarker;  // the cursor in the 3D view
    openvdb::FloatGrid::ConstPtr mScan;
    openvdb::BBoxd mScanBox;  // world
    double mSpacing = 1.0;    // the scan's finest
    double mRangeLow = 0.0, mRangeHigh = 1.0;
    double mWindow = 1.0, mLevel = 0.5;
    glm::dvec3 mCursor{0.0};
    bool mShown = false;
    std::uint64_t mCursorRevision = 0, mContoursAt = ~std::uint64_t(0);
    std::vector<std::uint64_t> mPieceVersions;  // of the contours drawn
};

}  // namespace sculpt::ui
