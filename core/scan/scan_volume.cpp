// SPDX-License-Identifier: Apache-2.0
#include "core/scan/scan_volume.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/scan/vtk_image_scan.h"

#include <vtkDataArray.h>
#include <vtkExtractVOI.h>
#include <vtkImageCast.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

namespace sculpt {

namespace {

template <typename T>
void copyRow(const void* src, size_t count, float* out)
{
    const T* p = static_cast<const T*>(src);
    for (size_t i = 0; i < count; ++i) out[i] = float(p[i]);
}

/// Trilinear interpolation in the samples of a dims-sized lattice; an axis of one sample has
/// stride 0, so its single layer is read for both corners.
template <typename T>
void sampleTrilinear(const void* src, const openvdb::Coord& dims, const openvdb::Vec3d* points, size_t count,
                     float outside, float* out)
{
    const T* data = static_cast<const T*>(src);
    const size_t step[3] = {1, size_t(dims.x()), size_t(dims.x()) * size_t(dims.y())};
    size_t stride[3];
    for (int a = 0; a < 3; ++a) stride[a] = dims[a] > 1 ? step[a] : 0;
    for (size_t n = 0; n < count; ++n) {
        const openvdb::Vec3d& p = points[n];
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && p[a] >= 0.0 && p[a] <= dims[a] - 1;
        if (!inside) {
            out[n] = outside;
            continue;
        }
        size_t base = 0;
        double f[3];
        for (int a = 0; a < 3; ++a) {
            const int i = std::min(int(p[a]), std::max(dims[a] - 2, 0));
            f[a] = p[a] - i;
            base += size_t(i) * step[a];
        }
        const auto at = [&](int dx, int dy, int dz) {
            return double(data[base + dx * stride[0] + dy * stride[1] + dz * stride[2]]);
        };
        const double c00 = at(0, 0, 0) + f[0] * (at(1, 0, 0) - at(0, 0, 0)),
                     c10 = at(0, 1, 0) + f[0] * (at(1, 1, 0) - at(0, 1, 0));
        const double c01 = at(0, 0, 1) + f[0] * (at(1, 0, 1) - at(0, 0, 1)),
                     c11 = at(0, 1, 1) + f[0] * (at(1, 1, 1) - at(0, 1, 1));
        const double c0 = c00 + f[1] * (c10 - c00), c1 = c01 + f[1] * (c11 - c01);
        out[n] = float(c0 + f[2] * (c1 - c0));
    }
}

}  // namespace

ScanVolume::ScanVolume(std::shared_ptr<const Impl> impl) : mImpl(std::move(impl)) {}

openvdb::Coord ScanVolume::dims() const
{
    int d[3];
    mImpl->image->GetDimensions(d);
    return openvdb::Coord(d[0], d[1], d[2]);
}

const openvdb::Mat4d& ScanVolume::worldFromIndex() const { return mImpl->worldFromIndex; }

std::pair<double, double> ScanVolume::range() const
{
    double r[2];
    mImpl->image->GetPointData()->GetScalars()->GetRange(r);
    return {r[0], r[1]};
}

std::size_t ScanVolume::denseBytes() const
{
    return std::size_t(mImpl->image->GetNumberOfPoints()) * std::size_t(mImpl->image->GetScalarSize());
}

const std::string& ScanVolume::source() const { return mImpl->source; }

const std::vector<std::string>& ScanVolume::warnings() const { return mImpl->warnings; }

void ScanVolume::readSlice(int k, float* out) const
{
    const openvdb::Coord d = dims();
    const size_t count = size_t(d.x()) * size_t(d.y());
    const void* src = static_cast<const char*>(mImpl->image->GetScalarPointer()) +
                      size_t(k) * count * size_t(mImpl->image->GetScalarSize());
    switch (mImpl->image->GetScalarType()) {
        vtkTemplateMacro(copyRow<VTK_TT>(src, count, out));
    default: throw InputError(source() + ": unsupported sample type");
    }
}

void ScanVolume::sample(const openvdb::Vec3d* points, std::size_t count, float outside, float* out) const
{
    const void* src = mImpl->image->GetScalarPointer();
    switch (mImpl->image->GetScalarType()) {
        vtkTemplateMacro(sampleTrilinear<VTK_TT>(src, dims(), points, count, outside, out));
    default: throw InputError(source() + ": unsupported sample type");
    }
}

ScanVolume ScanVolume::cropped(const openvdb::CoordBBox& box) const
{
    const openvdb::Coord d = dims();
    openvdb::CoordBBox clipped = box;
    clipped.intersect(openvdb::CoordBBox(openvdb::Coord(0), d.offsetBy(-1)));
    if (clipped.empty()) {
        throw InputError(source() + ": the crop box " + std::to_string(box.min().x()) + "," +
                         std::to_string(box.min().y()) + "," + std::to_string(box.min().z()) + " .. " +
                         std::to_string(box.max().x()) + "," + std::to_string(box.max().y()) + "," +
                         std::to_string(box.max().z()) + " misses the scan (0,0,0 .. " + std::to_string(d.x() - 1) +
                         "," + std::to_string(d.y() - 1) + "," + std::to_string(d.z() - 1) + ")");
    }
    vtkNew<vtkExtractVOI> extract;
    extract->SetInputData(mImpl->image);
    extract->SetVOI(clipped.min().x(), clipped.max().x(), clipped.min().y(), clipped.max().y(), clipped.min().z(),
                    clipped.max().z());
    extract->Update();
    vtkSmartPointer<vtkImageData> image = extract->GetOutput();
    return makeScan(image, mImpl->worldFromIndex, source(), warnings());
}

ScanVolume ScanVolume::smoothed(double sigmaWorld) const
{
    if (!(sigmaWorld > 0.0) || !std::isfinite(sigmaWorld)) {
        throw InputError("smoothing sigma must be a positive number (got " + formatNumber(sigmaWorld) + ")");
    }
    openvdb::Vec3d sigmaVoxels;
    for (int a = 0; a < 3; ++a) sigmaVoxels[a] = sigmaWorld / spacing(a);
    return gaussian(sigmaVoxels);
}

std::optional<ScanVolume> ScanVolume::antiAliased(double voxelSizeWorld) const
{
    openvdb::Vec3d sigmaVoxels(0.0);
    for (int a = 0; a < 3; ++a) {
        const double s = spacing(a);
        if (dims()[a] > 1 && voxelSizeWorld > s)
            sigmaVoxels[a] = 0.5 * std::sqrt(voxelSizeWorld * voxelSizeWorld - s * s) / s;
    }
    if (sigmaVoxels.x() < kMinSigmaVoxels && sigmaVoxels.y() < kMinSigmaVoxels && sigmaVoxels.z() < kMinSigmaVoxels)
        return std::nullopt;
    return gaussian(sigmaVoxels);
}

double ScanVolume::spacing(int axis) const
{
    const auto& m = mImpl->worldFromIndex;
    return openvdb::Vec3d(m[axis][0], m[axis][1], m[axis][2]).length();  // the length of the placement's row
}

ScanVolume ScanVolume::gaussian(const openvdb::Vec3d& sigmaVoxels) const
{
    // VTK sizes its kernel in an int from sigma and never checks it: a spacing far from the
    // voxel size (a fuzzed sform) crashed it. A kernel wider than the image adds nothing.
    openvdb::Vec3d sigma;
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(sigmaVoxels[a]) || sigmaVoxels[a] < 0.0)
            throw std::invalid_argument("ScanVolume::gaussian: sigma must be finite and not negative");
        sigma[a] = std::min(sigmaVoxels[a], double(dims()[a]));
    }
    // In the samples' own type an integer scan rounds every blurred sample: a 0/1 mask
    // smoothed by 0.7 voxel eroded by 3 voxels, by 1 voxel it vanished. Blur in floating point.
    vtkNew<vtkImageCast> toFloat;
    toFloat->SetInputData(mImpl->image);
    toFloat->SetOutputScalarTypeToFloat();
    vtkNew<vtkImageGaussianSmooth> smooth;
    const int type = mImpl->image->GetScalarType();
    if (type == VTK_FLOAT || type == VTK_DOUBLE) smooth->SetInputData(mImpl->image);
    else smooth->SetInputConnection(toFloat->GetOutputPort());
    smooth->SetDimensionality(3);
    smooth->SetStandardDeviations(sigma.x(), sigma.y(), sigma.z());
    smooth->SetRadiusFactors(3.0, 3.0, 3.0);
    smooth->Update();
    auto impl = std::make_shared<Impl>(*mImpl);
    impl->image = smooth->GetOutput();
    return ScanVolume(impl);
}

double ScanVolume::worldExtent() const
{
    const openvdb::Coord d = dims();
    openvdb::BBoxd box;
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d ijk(corner & 1 ? d.x() - 1 : 0, corner & 2 ? d.y() - 1 : 0, corner & 4 ? d.z() - 1 : 0);
        box.expand(worldFromIndex().transform(ijk));
    }
    return box.extents()[box.maxExtent()];
}

std::optional<std::set<double>> ScanVolume::distinctValues(std::size_t most) const
{
    vtkDataArray* samples = mImpl->image->GetPointData()->GetScalars();
    std::set<double> found;
    const vtkIdType count = samples->GetNumberOfTuples();
    for (vtkIdType i = 0; i < count; ++i)
        if (found.insert(samples->GetComponent(i, 0)).second && found.size() > most) return std::nullopt;
    return found;
}

bool ScanVolume::twoValued() const
{
    const auto values = distinctValues(2);
    return values && values->size() == 2;
}

std::vector<int> ScanVolume::labels() const
{
    const auto values = distinctValues(kMaxLabels);
    if (!values) return {};
    std::vector<int> labels;
    for (const double v : *values) {
        if (v != std::floor(v) || std::abs(v) > double(std::numeric_limits<int>::max())) return {};
        labels.push_back(int(v));
    }
    return labels;
}

double ScanVolume::sameNeighbourFraction() const
{
    vtkDataArray* samples = mImpl->image->GetPointData()->GetScalars();
    const openvdb::Coord d = dims();
    std::size_t pairs = 0, same = 0;
    std::vector<double> row(std::size_t(d.x()));
    for (vtkIdType start = 0; start < samples->GetNumberOfTuples(); start += d.x()) {
        for (int x = 0; x < d.x(); ++x) row[std::size_t(x)] = samples->GetComponent(start + x, 0);
        for (std::size_t x = 1; x < row.size(); ++x) {
            if (row[x] == 0.0 && row[x - 1] == 0.0) continue;
            ++pairs;
            same += row[x] == row[x - 1];
        }
    }
    return pairs > 0 ? double(same) / double(pairs) : 1.0;
}

std::map<int, ScanVolume::LabelExtent> ScanVolume::labelExtents() const
{
    vtkDataArray* samples = mImpl->image->GetPointData()->GetScalars();
    const openvdb::Coord d = dims();
    std::map<int, LabelExtent> extents;
    vtkIdType i = 0;
    for (int z = 0; z < d.z(); ++z)
        for (int y = 0; y < d.y(); ++y)
            for (int x = 0; x < d.x(); ++x, ++i) {
                LabelExtent& extent = extents[int(samples->GetComponent(i, 0))];
                extent.box.expand(openvdb::Coord(x, y, z));
                ++extent.samples;
            }
    return extents;
}

ScanVolume ScanVolume::labelMask(int label) const
{
    vtkDataArray* samples = mImpl->image->GetPointData()->GetScalars();
    vtkNew<vtkImageData> mask;
    mask->SetDimensions(mImpl->image->GetDimensions());
    mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    auto* out = static_cast<unsigned char*>(mask->GetScalarPointer());
    const vtkIdType count = samples->GetNumberOfTuples();
    for (vtkIdType i = 0; i < count; ++i) out[i] = samples->GetComponent(i, 0) == double(label) ? 1 : 0;
    auto impl = std::make_shared<Impl>(*mImpl);
    impl->image = mask;
    return ScanVolume(impl);
}

std::vector<double> ScanVolume::histogram(int bins) const
{
    const auto [lo, hi] = range();
    std::vector<double> counts(size_t(std::max(bins, 1)), 0.0);
    const double scale = hi > lo ? bins / (hi - lo) : 0.0;
    const openvdb::Coord d = dims();
    std::vector<float> slice(size_t(d.x()) * size_t(d.y()));
    for (int k = 0; k < d.z(); ++k) {
        readSlice(k, slice.data());
        for (float v : slice) counts[size_t(std::clamp(int((v - lo) * scale), 0, bins - 1))] += 1.0;
    }
    return counts;
}

double ScanVolume::otsuThreshold() const
{
    const auto [lo, hi] = range();
    if (!(hi > lo))
        throw InputError(source() + ": every sample is " + formatNumber(lo) + ": there is no surface to find");
    constexpr int kBins = 256;
    const std::vector<double> histogram = this->histogram(kBins);
    double total = 0.0, sumAll = 0.0;
    for (int i = 0; i < kBins; ++i) {
        total += histogram[size_t(i)];
        sumAll += i * histogram[size_t(i)];
    }
    double weightBelow = 0.0, sumBelow = 0.0, best = -1.0;
    int bestBin = 0, bestLast = 0;         // the best split, and the last bin of its plateau
    for (int i = 0; i < kBins - 1; ++i) {  // class "below" is bins 0..i
        weightBelow += histogram[size_t(i)];
        sumBelow += i * histogram[size_t(i)];
        const double weightAbove = total - weightBelow;
        if (weightBelow == 0.0 || weightAbove == 0.0) continue;
        const double meanBelow = sumBelow / weightBelow, meanAbove = (sumAll - sumBelow) / weightAbove;
        const double between = weightBelow * weightAbove * (meanBelow - meanAbove) * (meanBelow - meanAbove);
        if (between > best) {
            best = between;
            bestBin = bestLast = i;
        } else if (between == best && bestLast == i - 1) {
            bestLast = i;  // an empty bin: the same split
        }
    }
    // Every split across empty bins is as good: the middle of the gap, not its lower edge (a
    // mask of 0 and 1 splits at 0.5, where its surface is, not at 0.004).
    return lo + (hi - lo) * (0.5 * (bestBin + bestLast) + 1.0) / kBins;
}

}  // namespace sculpt
