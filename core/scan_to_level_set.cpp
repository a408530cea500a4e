#include "scan_to_level_set.h"

#include "errors.h"
#include "memory_budget.h"
#include "text_format.h"

#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <tbb/parallel_for.h>

#include <cmath>
#include <vector>

namespace sculpt {

namespace {

constexpr int kSlabLayers = 8;  // output z layers per slab: one leaf

/// Trilinear samples of the scan for world points, from the slices [k0, k1] held as floats.
class SliceWindow {
public:
    SliceWindow(const ScanVolume& scan) : mScan(scan), mDims(scan.dims()), mWorldToIndex(scan.indexToWorld().inverse())
    {
        mOutside = float(scan.range().first) - 1.0f;
    }

    /// Loads the slices a box of world points can touch.
    void load(const openvdb::BBoxd& world)
    {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (int c = 0; c < 8; ++c) {
            const openvdb::Vec3d corner((c & 1) ? world.max().x() : world.min().x(), (c & 2) ? world.max().y() : world.min().y(),
                                        (c & 4) ? world.max().z() : world.min().z());
            const double k = mWorldToIndex.transform(corner).z();
            lo = std::min(lo, k);
            hi = std::max(hi, k);
        }
        mK0 = std::clamp(int(std::floor(lo)), 0, mDims.z() - 1);
        const int k1 = std::clamp(int(std::ceil(hi)) + 1, 0, mDims.z() - 1);
        const size_t slice = size_t(mDims.x()) * size_t(mDims.y());
        mSlices.resize(slice * size_t(k1 - mK0 + 1));
        for (int k = mK0; k <= k1; ++k) mScan.readSlice(k, mSlices.data() + size_t(k - mK0) * slice);
        mK1 = k1;
    }

    /// The sample at a world point; below every sample outside the scan.
    float operator()(const openvdb::Vec3d& world) const
    {
        const openvdb::Vec3d p = mWorldToIndex.transform(world);
        if (p.x() < 0.0 || p.y() < 0.0 || p.z() < 0.0 || p.x() > mDims.x() - 1 || p.y() > mDims.y() - 1 ||
            p.z() > mDims.z() - 1) {
            return mOutside;
        }
        const int i = std::min(int(p.x()), std::max(mDims.x() - 2, 0)), j = std::min(int(p.y()), std::max(mDims.y() - 2, 0)),
                  k = std::clamp(int(p.z()), mK0, std::max(mK1 - 1, mK0));
        const double fx = p.x() - i, fy = p.y() - j, fz = p.z() - k;
        const auto at = [&](int di, int dj, int dk) {
            const int ii = std::min(i + di, mDims.x() - 1), jj = std::min(j + dj, mDims.y() - 1), kk = std::min(k + dk, mK1);
            return double(mSlices[(size_t(kk - mK0) * size_t(mDims.y()) + size_t(jj)) * size_t(mDims.x()) + size_t(ii)]);
        };
        const double c00 = at(0, 0, 0) * (1 - fx) + at(1, 0, 0) * fx, c10 = at(0, 1, 0) * (1 - fx) + at(1, 1, 0) * fx;
        const double c01 = at(0, 0, 1) * (1 - fx) + at(1, 0, 1) * fx, c11 = at(0, 1, 1) * (1 - fx) + at(1, 1, 1) * fx;
        return float((c00 * (1 - fy) + c10 * fy) * (1 - fz) + (c01 * (1 - fy) + c11 * fy) * fz);
    }

    float outside() const { return mOutside; }

private:
    const ScanVolume& mScan;
    openvdb::Coord mDims;
    openvdb::Mat4d mWorldToIndex;
    std::vector<float> mSlices;
    int mK0 = 0, mK1 = 0;
    float mOutside = 0.0f;
};

/// The output lattice: the scan's world box, one voxel of outside around it.
openvdb::CoordBBox outputBox(const ScanVolume& scan, double h)
{
    openvdb::BBoxd world;
    const openvdb::Coord d = scan.dims();
    for (int c = 0; c < 8; ++c) {
        const openvdb::Vec3d corner((c & 1) ? d.x() - 1 : 0, (c & 2) ? d.y() - 1 : 0, (c & 4) ? d.z() - 1 : 0);
        world.expand(scan.indexToWorld().transform(corner));
    }
    openvdb::CoordBBox box;
    for (int a = 0; a < 3; ++a) {
        box.min()[a] = int(std::floor(world.min()[a] / h)) - 2;
        box.max()[a] = int(std::ceil(world.max()[a] / h)) + 2;
    }
    return box;
}

/// The voxels next to a crossing of the iso-value, holding their first-order distance
/// (iso - f) / |grad f| (negative inside), sampled one slab of output layers at a time.
openvdb::FloatGrid::Ptr seedCrossings(const ScanVolume& scan, double iso, double h, const openvdb::CoordBBox& box,
                                      const Progress& progress)
{
    const double halfWidth = FieldImage::kDefaultHalfWidthVoxels;
    auto seeds = openvdb::FloatGrid::create(float((halfWidth + 2.0) * h));
    seeds->setTransform(openvdb::math::Transform::createLinearTransform(h));
    const auto& xform = seeds->transform();
    SliceWindow window(scan);
    const int nx = box.dim().x(), ny = box.dim().y();
    std::vector<float> slab, distance;  // one slab plus a layer each side (for the gradient), x fastest
    auto acc = seeds->getAccessor();
    for (int z0 = box.min().z(); z0 <= box.max().z(); z0 += kSlabLayers) {
        const int z1 = std::min(z0 + kSlabLayers - 1, box.max().z());
        const int layers = z1 - z0 + 3;
        const auto index = [&](int x, int y, int l) { return (size_t(l) * ny + size_t(y)) * nx + size_t(x); };
        const auto coord = [&](int x, int y, int l) { return openvdb::Coord(box.min().x() + x, box.min().y() + y, z0 - 1 + l); };
        window.load(openvdb::BBoxd(xform.indexToWorld(coord(0, 0, 0)), xform.indexToWorld(coord(nx - 1, ny - 1, layers - 1))));
        slab.assign(size_t(nx) * ny * layers, window.outside());
        tbb::parallel_for(0, layers, [&](int l) {
            for (int y = 0; y < ny; ++y) {
                for (int x = 0; x < nx; ++x) slab[index(x, y, l)] = window(xform.indexToWorld(coord(x, y, l)));
            }
        });
        distance.assign(slab.size(), std::numeric_limits<float>::quiet_NaN());  // NaN: not a seed
        tbb::parallel_for(1, layers - 1, [&](int l) {
            for (int y = 1; y < ny - 1; ++y) {
                for (int x = 1; x < nx - 1; ++x) {
                    const float f = slab[index(x, y, l)];
                    const float n[6] = {slab[index(x - 1, y, l)], slab[index(x + 1, y, l)], slab[index(x, y - 1, l)],
                                        slab[index(x, y + 1, l)], slab[index(x, y, l - 1)], slab[index(x, y, l + 1)]};
                    bool crossing = false;
                    for (float v : n) crossing = crossing || ((v > iso) != (f > iso));
                    if (!crossing) continue;
                    const double gradient = std::sqrt(double(n[1] - n[0]) * (n[1] - n[0]) + double(n[3] - n[2]) * (n[3] - n[2]) +
                                                      double(n[5] - n[4]) * (n[5] - n[4])) / (2.0 * h);
                    // A crossing voxel is within a voxel of the surface whatever the estimate says.
                    distance[index(x, y, l)] = float(std::clamp((iso - f) / gradient, -h, h));
                }
            }
        });
        for (int l = 1; l < layers - 1; ++l) {
            for (int y = 1; y < ny - 1; ++y) {
                for (int x = 1; x < nx - 1; ++x) {
                    const float d = distance[index(x, y, l)];
                    if (!std::isnan(d)) acc.setValueOn(coord(x, y, l), d);
                }
            }
        }
        report(progress, 0.8 * double(z1 - box.min().z() + 1) / box.dim().z());
    }
    return seeds;
}

/// The narrow band around the seeds: signs everywhere (signed flood fill), the band's voxels
/// (dilation), their distances by fast sweeping from the crossings (sdfToSdf), then the seeds'
/// own values back: the mesher finds the crossings where the scan has them (as FlyingEdges
/// does), where the sweep's distance to a plane through them would round voxel-scale detail off
/// (4% of a brain's area). The sweep's grid becomes the result, trimmed in place.
openvdb::FloatGrid::Ptr sweepBand(openvdb::FloatGrid& seeds, double halfWidth)
{
    const double h = seeds.voxelSize()[0];
    // Seeds whose estimate is within a voxel; the others (a steep or flat f) keep the sweep's.
    const openvdb::MaskGrid::Ptr seedMask = openvdb::MaskGrid::create();
    auto mask = seedMask->getAccessor();
    for (auto it = seeds.cbeginValueOn(); it; ++it) {
        if (std::abs(*it) < h) mask.setValueOn(it.getCoord());
    }
    openvdb::tools::signedFloodFill(seeds.tree());
    openvdb::tools::dilateActiveValues(seeds.tree(), int(halfWidth), openvdb::tools::NN_FACE_EDGE, openvdb::tools::IGNORE_TILES);
    openvdb::FloatGrid::Ptr band = openvdb::tools::sdfToSdf(seeds, 0.0f);
    auto out = band->getAccessor();
    const auto seedValues = seeds.getConstAccessor();
    for (auto it = seedMask->cbeginValueOn(); it; ++it) out.setValueOn(it.getCoord(), seedValues.getValue(it.getCoord()));
    const float background = float(halfWidth * h);
    for (auto leaf = band->tree().beginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->beginValueOn(); it; ++it) {
            if (std::abs(*it) < background) continue;
            it.setValue(*it < 0.0f ? -background : background);
            it.setValueOff();
        }
    }
    openvdb::tools::changeLevelSetBackground(band->tree(), background);
    band->setGridClass(openvdb::GRID_LEVEL_SET);
    openvdb::tools::signedFloodFill(band->tree());
    openvdb::tools::pruneLevelSet(band->tree());
    return band;
}

} // namespace

double nativeVoxelSize(const ScanVolume& scan)
{
    double h = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (scan.dims()[a] < 2) continue;
        const auto& m = scan.indexToWorld();
        h = std::min(h, openvdb::Vec3d(m[a][0], m[a][1], m[a][2]).length());
    }
    return std::isfinite(h) ? h : 1.0;
}

FieldImage scanToLevelSet(const ScanVolume& scan, double iso, double h, const Progress& progress)
{
    const auto [lo, hi] = scan.range();
    if (!(iso > lo && iso < hi)) {
        throw InputError(scan.source() + ": iso-value " + formatNumber(iso) + " is outside the samples' range (" +
                         formatNumber(lo) + " .. " + formatNumber(hi) + "): nothing would be inside");
    }
    if (!(h > 0.0) || !std::isfinite(h)) throw InputError("voxel size must be a positive number (got " + formatNumber(h) + ")");
    const openvdb::CoordBBox box = outputBox(scan, h);
    const double halfWidth = FieldImage::kDefaultHalfWidthVoxels;
    const openvdb::Coord dim = box.dim();
    // The band is at most a few layers of the box's faces' worth per slice; refuse absurd boxes.
    requireMemory(double(dim.x()) * dim.y() * (kSlabLayers + 2) * 4.0 * 2.0, "the resampled scan at voxel size " + formatNumber(h));
    if (double(dim.x()) * dim.y() * dim.z() > double(1LL << 40)) {
        throw InputError(scan.source() + ": voxel size " + formatNumber(h) + " would give " + std::to_string(dim.x()) + " x " +
                         std::to_string(dim.y()) + " x " + std::to_string(dim.z()) + " voxels");
    }

    auto seeds = seedCrossings(scan, iso, h, box, progress);
    if (seeds->activeVoxelCount() == 0) throw InputError(scan.source() + ": no surface at iso-value " + formatNumber(iso));
    FieldImage field(sweepBand(*seeds, halfWidth));
    report(progress, 1.0);
    return field;
}

std::size_t keepLargestComponent(FieldImage& field)
{
    std::vector<openvdb::FloatGrid::Ptr> pieces;
    openvdb::tools::segmentSDF(field.grid(), pieces);
    if (pieces.size() < 2) return 0;
    // The piece with the most band voxels: the largest surface, which for scans' islands and
    // the organ they surround is also the largest volume.
    size_t best = 0;
    for (size_t i = 1; i < pieces.size(); ++i) {
        if (pieces[i]->activeVoxelCount() > pieces[best]->activeVoxelCount()) best = i;
    }
    const std::string units = field.units();
    field = FieldImage(pieces[best], units);
    field.markDirty(field.allLeaves());
    return pieces.size() - 1;
}

} // namespace sculpt
