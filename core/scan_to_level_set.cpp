#include "scan_to_level_set.h"

#include "errors.h"
#include "memory_budget.h"
#include "text_format.h"

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Morphology.h>
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

    // The band holds iso - f (negative inside, like a distance); every voxel off the band must
    // say which side it is on too, or fast sweeping sees a false surface at the band's edge.
    auto fog = openvdb::FloatGrid::create(float(hi - lo) + 1.0f);
    fog->setTransform(openvdb::math::Transform::createLinearTransform(h));
    const auto& xform = fog->transform();
    SliceWindow window(scan);
    // Samples of one slab plus one layer each side (for the gradient), x fastest.
    const int nx = dim.x(), ny = dim.y();
    std::vector<float> slab;
    auto acc = fog->getAccessor();
    std::vector<unsigned char> inBand;
    std::vector<float> crossingDistance;
    auto interface = openvdb::FloatGrid::create(0.0f);  // first-order distances at the seeds
    auto interfaceAcc = interface->getAccessor();
    for (int z0 = box.min().z(); z0 <= box.max().z(); z0 += kSlabLayers) {
        const int z1 = std::min(z0 + kSlabLayers - 1, box.max().z());
        const int layers = z1 - z0 + 3;
        window.load(openvdb::BBoxd(xform.indexToWorld(openvdb::Coord(box.min().x(), box.min().y(), z0 - 1)),
                                   xform.indexToWorld(openvdb::Coord(box.max().x(), box.max().y(), z1 + 1))));
        slab.assign(size_t(nx) * ny * layers, window.outside());
        const auto index = [&](int x, int y, int l) { return (size_t(l) * ny + size_t(y)) * nx + size_t(x); };
        tbb::parallel_for(0, layers, [&](int l) {
            for (int y = 0; y < ny; ++y) {
                for (int x = 0; x < nx; ++x) {
                    slab[index(x, y, l)] = window(xform.indexToWorld(box.min().offsetBy(x, y, 0) + openvdb::Coord(0, 0, z0 - 1 + l - box.min().z())));
                }
            }
        });
        // Seeds: the voxels next to a crossing of the iso-value.
        inBand.assign(size_t(nx) * ny * layers, 0);
        crossingDistance.assign(size_t(nx) * ny * layers, 0.0f);
        tbb::parallel_for(1, layers - 1, [&](int l) {
            for (int y = 1; y < ny - 1; ++y) {
                for (int x = 1; x < nx - 1; ++x) {
                    const bool inside = slab[index(x, y, l)] > iso;
                    const size_t neighbours[6] = {index(x - 1, y, l), index(x + 1, y, l), index(x, y - 1, l),
                                                  index(x, y + 1, l), index(x, y, l - 1), index(x, y, l + 1)};
                    bool crossing = false;
                    for (size_t n : neighbours) crossing = crossing || ((slab[n] > iso) != inside);
                    inBand[index(x, y, l)] = crossing;
                    if (crossing) {
                        const double gx = slab[neighbours[1]] - slab[neighbours[0]], gy = slab[neighbours[3]] - slab[neighbours[2]],
                                     gz = slab[neighbours[5]] - slab[neighbours[4]];
                        const double gradient = std::sqrt(gx * gx + gy * gy + gz * gz) / (2.0 * h);
                        crossingDistance[index(x, y, l)] = float((iso - slab[index(x, y, l)]) / gradient);
                    }
                }
            }
        });
        for (int l = 1; l < layers - 1; ++l) {
            for (int y = 1; y < ny - 1; ++y) {
                for (int x = 1; x < nx - 1; ++x) {
                    if (!inBand[index(x, y, l)]) continue;
                    const openvdb::Coord ijk = box.min().offsetBy(x, y, z0 - 1 + l - box.min().z());
                    acc.setValueOn(ijk, float(iso) - slab[index(x, y, l)]);
                    interfaceAcc.setValueOn(ijk, crossingDistance[index(x, y, l)]);
                }
            }
        }
        report(progress, 0.8 * double(z1 - box.min().z() + 1) / dim.z());
    }
    if (fog->activeVoxelCount() == 0) throw InputError(scan.source() + ": no surface at iso-value " + formatNumber(iso));
    slab = {};
    inBand = {};

    // Signs everywhere, then the band around the seeds, whose distances fast sweeping computes.
    openvdb::tools::signedFloodFill(fog->tree());
    openvdb::tools::dilateActiveValues(fog->tree(), int(halfWidth) + 1, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                       openvdb::tools::IGNORE_TILES);
    openvdb::FloatGrid::Ptr sdf = openvdb::tools::sdfToSdf(*fog, 0.0f);
    fog.reset();
    report(progress, 0.95);
    // Copy the band into a clean level set, then give the inside its sign.
    const float background = float(halfWidth * h);
    auto band = openvdb::FloatGrid::create(background);
    band->setTransform(sdf->transform().copy());
    band->setGridClass(openvdb::GRID_LEVEL_SET);
    auto out = band->getAccessor();
    for (auto it = sdf->cbeginValueOn(); it; ++it) {
        if (std::abs(*it) < background) out.setValueOn(it.getCoord(), *it);
    }
    sdf.reset();
    // Voxels next to a crossing take (iso - f) / |grad f| instead of the sweep's distance to a
    // plane through the crossings: the mesher then finds the crossings where the scan has them
    // (as FlyingEdges does) instead of smoothing voxel-scale detail away (4% of a brain's area).
    for (auto it = interface->cbeginValueOn(); it; ++it) {
        if (std::isfinite(*it) && std::abs(*it) < h) out.setValueOn(it.getCoord(), *it);
    }
    openvdb::tools::signedFloodFill(band->tree());
    report(progress, 1.0);
    return FieldImage(band);
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
