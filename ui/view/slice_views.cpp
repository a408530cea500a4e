// SPDX-License-Identifier: Apache-2.0
#include "ui/view/slice_views.h"

#include "core/scan/kept_scan.h"
#include "core/solids/cross_section.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/ValueTransformer.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkImageProperty.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sculpt::ui {

namespace {

/// The most samples a slice is drawn with along a side: finer scans are drawn coarser.
constexpr int kMostSamples = 1024;
/// The crosshair's colour, and the 3D marker's.
const openvdb::Vec3f kCrosshair{0.35f, 0.95f, 0.35f};
/// The sculpted piece's contour: a yellow that stands out on grey samples (the clay's colour
/// does not); the other pieces' are their colours at full brightness.
const openvdb::Vec3f kSculptedContour{1.0f, 0.85f, 0.1f};
/// Pixels between the views and around them; the status bar's height below; the panels' columns
/// kept clear on either side (the brush palette and a mode's panel, History and Pieces).
constexpr double kGap = 4.0, kStatusBar = 24.0, kSideColumns = 250.0;

openvdb::Vec3d vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

/// An actor drawing the lines of `poly` (cell colours when it has them), above the slice.
vtkSmartPointer<vtkActor> lineActor(double width)
{
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetLineWidth(float(width));
    actor->GetProperty()->SetLighting(false);
    actor->SetPickable(false);
    return actor;
}

/// Where a view's lines lie: just above its slice (z 0).
constexpr double kAboveSlice = 0.1;

/// Lines from pairs of points (a view's own coordinates, or the world's for the 3D marker), each
/// in its colour.
class Lines {
public:
    void add(const glm::dvec3& p, const glm::dvec3& q, const openvdb::Vec3f& colour)
    {
        const vtkIdType a = mPoints->InsertNextPoint(p.x, p.y, p.z), b = mPoints->InsertNextPoint(q.x, q.y, q.z);
        const vtkIdType ids[2] = {a, b};
        mLines->InsertNextCell(2, ids);
        const unsigned char rgb[3] = {(unsigned char)(255.0f * std::clamp(colour[0], 0.0f, 1.0f)),
                                      (unsigned char)(255.0f * std::clamp(colour[1], 0.0f, 1.0f)),
                                      (unsigned char)(255.0f * std::clamp(colour[2], 0.0f, 1.0f))};
        mColours->InsertNextTypedTuple(rgb);
    }
    void drawInto(vtkActor* actor)
    {
        auto poly = vtkSmartPointer<vtkPolyData>::New();
        poly->SetPoints(mPoints);
        poly->SetLines(mLines);
        poly->GetCellData()->SetScalars(mColours);
        vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(poly);
    }

private:
    vtkNew<vtkPoints> mPoints;
    vtkNew<vtkCellArray> mLines;
    vtkSmartPointer<vtkUnsignedCharArray> mColours = [] {
        auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
        colours->SetNumberOfComponents(3);
        return colours;
    }();
};

/// The world box a kept scan's samples span.
openvdb::BBoxd worldBoxOf(const KeptScanRecord& record)
{
    openvdb::BBoxd box;
    const openvdb::Coord& d = record.lattice.dims;
    for (int c = 0; c < 8; ++c) {
        const openvdb::Vec3d corner((c & 1) ? d.x() - 0.5 : -0.5, (c & 2) ? d.y() - 0.5 : -0.5,
                                    (c & 4) ? d.z() - 0.5 : -0.5);
        box.expand(record.lattice.worldFromIndex.transform(corner));
    }
    return box;
}

}  // namespace

SliceViews::SliceViews(vtkRenderWindow* window, vtkRenderer* overlay) : mWindow3d(window), mOverlay(overlay)
{
    for (int a = 0; a < 3; ++a) {
        View& view = mViews[std::size_t(a)];
        view.axis = SliceAxis(a);
        view.renderer = vtkSmartPointer<vtkRenderer>::New();
        view.renderer->SetBackground(0.0, 0.0, 0.0);
        view.renderer->InteractiveOff();
        view.renderer->DrawOff();
        view.renderer->GetActiveCamera()->ParallelProjectionOn();
        view.image = vtkSmartPointer<vtkImageActor>::New();
        view.image->GetProperty()->SetInterpolationTypeToLinear();
        view.image->SetPickable(false);
        view.renderer->AddActor(view.image);
        view.contours = lineActor(2.0);
        view.crosshair = lineActor(1.0);
        view.renderer->AddActor(view.contours);
        view.renderer->AddActor(view.crosshair);
        mWindow3d->AddRenderer(view.renderer);
    }
    mMarker = lineActor(2.0);
    mMarker->VisibilityOff();
    mOverlay->AddActor(mMarker);
}

SliceViews::~SliceViews()
{
    for (View& view : mViews) mWindow3d->RemoveRenderer(view.renderer);
    mOverlay->RemoveActor(mMarker);
}

void SliceViews::setShown(bool shown)
{
    mShown = shown;
    const bool draws = mShown && mScan;
    for (View& view : mViews) view.renderer->SetDraw(draws);
    mMarker->SetVisibility(draws);
}

void SliceViews::setScan(openvdb::FloatGrid::ConstPtr scan)
{
    if (scan == mScan) return;
    mScan = std::move(scan);
    for (View& view : mViews) view.sampled = false;
    ++mCursorRevision;
    mContoursAt = ~std::uint64_t(0);
    setShown(mShown);
    if (!mScan) return;
    const KeptScanRecord record = keptScanRecord(*mScan);
    mScanBox = worldBoxOf(record);
    const openvdb::Mat3d linear = record.lattice.worldFromIndex.getMat3();
    mSpacing = std::min({linear.row(0).length(), linear.row(1).length(), linear.row(2).length()});
    const openvdb::math::MinMax<float> extrema = openvdb::tools::minMax(mScan->tree());
    mRangeLow = std::min(double(extrema.min()), double(mScan->background()));
    mRangeHigh = std::max({double(extrema.max()), double(mScan->background()), mRangeLow + 1e-6});
    setWindowLevel(mRangeHigh - mRangeLow, 0.5 * (mRangeLow + mRangeHigh));
    const openvdb::Vec3d centre = mScanBox.getCenter();
    setCursor({centre.x(), centre.y(), centre.z()});
    for (View& view : mViews) frameCamera(view);
}

void SliceViews::layout(int width, int height)
{
    const double free = std::max(width - 2.0 * kSideColumns, 0.45 * width);  // a narrow window overlaps them
    const double side = std::floor(std::min((free - 4.0 * kGap) / 3.0, 0.32 * height));
    const double left = 0.5 * (width - 3.0 * side - 2.0 * kGap);
    for (int a = 0; a < 3; ++a) {
        // Left to right: axial, coronal, sagittal, as viewers lay them out.
        const int column = 2 - a;
        PixelRect& r = mViews[std::size_t(a)].rect;
        r = {left + column * (side + kGap), height - kStatusBar - side - kGap, side, side};
        mViews[std::size_t(a)].renderer->SetViewport(r.x / width, 1.0 - (r.y + r.height) / height,
                                                     (r.x + r.width) / width, 1.0 - r.y / height);
    }
}

std::optional<SliceAxis> SliceViews::viewAt(double x, double y) const
{
    if (!mShown || !mScan) return std::nullopt;
    for (const View& view : mViews)
        if (view.rect.contains(x, y)) return view.axis;
    return std::nullopt;
}

void SliceViews::setCursor(const glm::dvec3& world)
{
    mCursor = world;
    ++mCursorRevision;
    placeMarker();
}

std::pair<glm::dvec2, glm::dvec2> SliceViews::scanExtent(SliceAxis axis) const
{
    const auto [right, up] = screenAxes(axis);
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner((c & 1) ? mScanBox.max().x() : mScanBox.min().x(),
                                (c & 2) ? mScanBox.max().y() : mScanBox.min().y(),
                                (c & 4) ? mScanBox.max().z() : mScanBox.min().z());
        const glm::dvec2 uv(glm::dot(corner, right), glm::dot(corner, up));
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
    }
    return {lo, hi};
}

std::pair<glm::dvec3, glm::dvec3> SliceViews::screenAxes(SliceAxis axis)
{
    switch (axis) {
    case SliceAxis::Sagittal: return {{0, 1, 0}, {0, 0, 1}};  // the front to the left
    case SliceAxis::Coronal: return {{1, 0, 0}, {0, 0, 1}};   // the patient's right to the left
    case SliceAxis::Axial: break;
    }
    return {{1, 0, 0}, {0, -1, 0}};  // the patient's right to the left, the front up
}

glm::dvec3 SliceViews::worldAt(SliceAxis axis, double x, double y) const
{
    const View& view = mViews[std::size_t(axis)];
    const auto [right, up] = screenAxes(axis);
    vtkCamera* camera = view.renderer->GetActiveCamera();
    const double perPixel = 2.0 * camera->GetParallelScale() / view.rect.height;
    const double* focal = camera->GetFocalPoint();
    const double u = focal[0] + (x - view.rect.x - 0.5 * view.rect.width) * perPixel;
    const double v = focal[1] - (y - view.rect.y - 0.5 * view.rect.height) * perPixel;
    glm::dvec3 world = right * u + up * v;
    world[int(axis)] = mCursor[int(axis)];
    return world;
}

void SliceViews::step(SliceAxis axis, double steps)
{
    glm::dvec3 at = mCursor;
    const int a = int(axis);
    at[a] = std::clamp(at[a] + steps * mSpacing, mScanBox.min()[a], mScanBox.max()[a]);
    setCursor(at);
}

void SliceViews::setWindowLevel(double window, double level)
{
    mWindow = std::max(window, 1e-6 * (mRangeHigh - mRangeLow));
    mLevel = level;
    for (View& view : mViews) {
        view.image->GetProperty()->SetColorWindow(mWindow);
        view.image->GetProperty()->SetColorLevel(mLevel);
    }
}

vtkImageData* SliceViews::sliceImage(SliceAxis axis) const
{
    return mViews[std::size_t(axis)].image->GetMapper()->GetInput();
}

void SliceViews::sample(View& view)
{
    // Plain copies: the rows' lambda below takes them (C++17 lambdas cannot take structured bindings).
    const std::pair<glm::dvec3, glm::dvec3> axes = screenAxes(view.axis);
    const glm::dvec3 right = axes.first, up = axes.second;
    const std::pair<glm::dvec2, glm::dvec2> extent = scanExtent(view.axis);
    const glm::dvec2 lo = extent.first, hi = extent.second;
    const double step = std::max(mSpacing, std::max(hi[0] - lo[0], hi[1] - lo[1]) / kMostSamples);
    const int nu = int(std::ceil((hi[0] - lo[0]) / step)) + 1, nv = int(std::ceil((hi[1] - lo[1]) / step)) + 1;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(nu, nv, 1);
    image->SetOrigin(lo[0], lo[1], 0.0);
    image->SetSpacing(step, step, 1.0);
    image->AllocateScalars(VTK_FLOAT, 1);
    auto* samples = static_cast<float*>(image->GetScalarPointer());
    const int a = int(view.axis);
    const double plane = mCursor[a];
    tbb::parallel_for(tbb::blocked_range<int>(0, nv), [&](const tbb::blocked_range<int>& rows) {
        const auto accessor = mScan->getConstAccessor();
        for (int j = rows.begin(); j < rows.end(); ++j)
            for (int i = 0; i < nu; ++i) {
                glm::dvec3 world = right * (lo[0] + i * step) + up * (lo[1] + j * step);
                world[a] = plane;
                float value = 0.0f;
                openvdb::tools::BoxSampler::sample(accessor, mScan->transform().worldToIndex(vec(world)), value);
                samples[std::size_t(j) * std::size_t(nu) + std::size_t(i)] = value;
            }
    });
    view.image->GetMapper()->SetInputData(image);
    view.sampledAt = plane;
    view.sampled = true;
}

void SliceViews::frameCamera(View& view)
{
    const auto [lo, hi] = scanExtent(view.axis);
    vtkCamera* camera = view.renderer->GetActiveCamera();
    const double cu = 0.5 * (lo[0] + hi[0]), cv = 0.5 * (lo[1] + hi[1]);
    camera->SetFocalPoint(cu, cv, 0.0);
    camera->SetPosition(cu, cv, 1000.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.5 * 1.02 * std::max(hi[0] - lo[0], hi[1] - lo[1]));
    camera->SetClippingRange(1.0, 2000.0);  // the slice at z 0, its lines at 0.1
}

void SliceViews::drawContours(View& view, const std::vector<FieldPiece>& pieces)
{
    const auto [right, up] = screenAxes(view.axis);
    glm::dvec3 normal(0.0);
    normal[int(view.axis)] = 1.0;
    const SectionPlane plane{vec(mCursor), vec(normal)};
    Lines lines;
    view.segments = 0;
    for (const FieldPiece& piece : pieces) {
        if (!piece.look->visible) continue;
        const CrossSection section =
            placedCrossSection(*piece.field, piece.look->placement, plane, SectionParts::Outline);
        const float brightest = std::max({piece.colour[0], piece.colour[1], piece.colour[2], 1e-3f});
        const openvdb::Vec3f colour = piece.sculpted ? kSculptedContour : piece.colour / brightest;
        for (const auto& [p, q] : section.outline) {
            const glm::dvec3 a(p.x(), p.y(), p.z()), b(q.x(), q.y(), q.z());
            lines.add({glm::dot(a, right), glm::dot(a, up), kAboveSlice},
                      {glm::dot(b, right), glm::dot(b, up), kAboveSlice}, colour);
        }
        view.segments += section.outline.size();
    }
    lines.drawInto(view.contours);
}

void SliceViews::drawCrosshair(View& view)
{
    const auto [right, up] = screenAxes(view.axis);
    const double u = glm::dot(mCursor, right), v = glm::dot(mCursor, up);
    const double reach = (mScanBox.max() - mScanBox.min()).length();
    Lines lines;
    lines.add({u - reach, v, kAboveSlice}, {u + reach, v, kAboveSlice}, kCrosshair);
    lines.add({u, v - reach, kAboveSlice}, {u, v + reach, kAboveSlice}, kCrosshair);
    lines.drawInto(view.crosshair);
}

void SliceViews::placeMarker()
{
    const double arm = 0.03 * (mScanBox.empty() ? 10.0 : (mScanBox.max() - mScanBox.min()).length());
    Lines lines;
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 d(0.0);
        d[a] = arm;
        lines.add(mCursor - d, mCursor + d, kCrosshair);
    }
    lines.drawInto(mMarker);
}

void SliceViews::sync(const std::vector<FieldPiece>& pieces)
{
    if (!mShown || !mScan) return;
    std::vector<std::uint64_t> versions;
    for (const FieldPiece& piece : pieces) {
        versions.push_back(piece.field->id());
        versions.push_back(piece.version);
        versions.push_back(piece.look->visible);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                std::uint64_t bits = 0;
                std::memcpy(&bits, &piece.look->placement[r][c], sizeof bits);
                versions.push_back(bits);
            }
    }
    const bool cursorMoved = mContoursAt != mCursorRevision;
    const bool contoursStale = cursorMoved || versions != mPieceVersions;
    for (View& view : mViews) {
        if (!view.sampled || view.sampledAt != mCursor[int(view.axis)]) sample(view);
        if (contoursStale) drawContours(view, pieces);
        if (cursorMoved) drawCrosshair(view);
    }
    mContoursAt = mCursorRevision;
    mPieceVersions = std::move(versions);
}

}  // namespace sculpt::ui
