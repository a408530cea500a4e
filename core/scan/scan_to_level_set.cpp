// SPDX-License-Identifier: Apache-2.0
#include "core/scan/scan_to_level_set.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/text_format.h"
#include "core/scan/fast_marching.h"

#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace sculpt {

namespace {

using Leaf = openvdb::FloatGrid::TreeType::LeafNodeType;
using LeafList = std::vector<std::unique_ptr<Leaf>>;

constexpr int kBlock = 8;                            // scan samples per edge of a range block
const openvdb::Coord kTile(32, 32, 16);              // output voxels per tile: 4 x 4 x 2 leaves
constexpr int kHalo = 5;                             // tile margin: the band (3), marching slack (1), gradient (1)
constexpr double kMaxDefaultAnisotropy = 16.0;       // coarsest spacing / default voxel size, at most
constexpr double kMaxBoxVoxels = double(1LL << 37);  // about 5000^3: beyond, ask for a larger voxel size

/// The bounds of an index box's corners mapped by an affine transform (all it reaches).
openvdb::BBoxd transformedBounds(const openvdb::Mat4d& transform, const openvdb::CoordBBox& box)
{
    openvdb::BBoxd bounds;
    for (int c = 0; c < 8; ++c) {
        const openvdb::Coord corner((c & 1) ? box.max().x() : box.min().x(), (c & 2) ? box.max().y() : box.min().y(),
                                    (c & 4) ? box.max().z() : box.min().z());
        bounds.expand(transform.transform(corner.asVec3d()));
    }
    return bounds;
}

/// The smallest and largest sample of every 8^3 block of the scan: a tile whose samples all lie
/// on one side of the iso-value holds no surface and is not sampled at all.
class BlockRanges {
public:
    explicit BlockRanges(const ScanVolume& scan) : mDims(scan.dims())
    {
        for (int a = 0; a < 3; ++a) mBlocks[a] = (mDims[a] + kBlock - 1) / kBlock;
        mRanges.assign(size_t(mBlocks.x()) * mBlocks.y() * mBlocks.z(),
                       {std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()});
        tbb::parallel_for(0, mBlocks.z(), [&](int bz) {  // each task owns one layer of blocks
            std::vector<float> slice(size_t(mDims.x()) * size_t(mDims.y()));
            for (int k = bz * kBlock; k < std::min((bz + 1) * kBlock, mDims.z()); ++k) {
                scan.readSlice(k, slice.data());
                for (int j = 0; j < mDims.y(); ++j) {
                    const float* row = slice.data() + size_t(j) * size_t(mDims.x());
                    for (int bx = 0; bx < mBlocks.x(); ++bx) {
                        const float* first = row + bx * kBlock;
                        const auto [lo, hi] = std::minmax_element(first, row + std::min((bx + 1) * kBlock, mDims.x()));
                        auto& r = mRanges[index(bx, j / kBlock, bz)];
                        r = {std::min(r.first, *lo), std::max(r.second, *hi)};
                    }
                }
            }
        });
    }

    /// The range of the samples trilinear interpolation reads for index-space points in `box`,
    /// widened to `outside` if the box reaches off the lattice.
    std::pair<float, float> range(const openvdb::BBoxd& box, float outside) const
    {
        std::pair<float, float> r{std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()};
        openvdb::Coord lo, hi;
        for (int a = 0; a < 3; ++a) {
            if (box.max()[a] < 0.0 || box.min()[a] > mDims[a] - 1) return {outside, outside};
            if (box.min()[a] < 0.0 || box.max()[a] > mDims[a] - 1) r.first = outside;
            lo[a] = std::max(int(std::floor(box.min()[a])), 0) / kBlock;
            hi[a] = std::min(int(std::ceil(box.max()[a])), mDims[a] - 1) / kBlock;
        }
        for (int bz = lo.z(); bz <= hi.z(); ++bz) {
            for (int by = lo.y(); by <= hi.y(); ++by) {
                for (int bx = lo.x(); bx <= hi.x(); ++bx) {
                    const auto& b = mRanges[index(bx, by, bz)];
                    r = {std::min(r.first, b.first), std::max(r.second, b.second)};
                }
            }
        }
        return r;
    }

private:
    size_t index(int bx, int by, int bz) const
    {
        return (size_t(bz) * mBlocks.y() + size_t(by)) * mBlocks.x() + size_t(bx);
    }

    openvdb::Coord mDims, mBlocks;
    std::vector<std::pair<float, float>> mRanges;
};

/// Turns one tile of the output lattice into the band's leaves: samples the scan on the tile
/// and a margin, seeds the voxels next to a crossing with their distance to it, marches
/// distances out to the band's width and keeps the leaves the band touches. One per thread:
/// it owns the scratch buffers.
class TileConverter {
public:
    TileConverter(const ScanVolume& scan, const BlockRanges& ranges, double iso, double h)
        : mScan(scan), mRanges(ranges), mIso(float(iso)), mH(float(h)),
          mBackground(float(FieldImage::kDefaultHalfWidthVoxels * h)), mOutside(float(scan.range().first) - 1.0f)
    {
        mScanFromOutput = openvdb::Mat4d::identity();
        mScanFromOutput.preScale(openvdb::Vec3d(h));
        mScanFromOutput = mScanFromOutput * scan.worldFromIndex().inverse();
        mDims = kTile + openvdb::Coord(2 * kHalo);
        mStep = {1, size_t(mDims.x()), size_t(mDims.x()) * size_t(mDims.y())};
    }

    /// Appends the leaves of the tile whose first voxel is `origin` (output index space).
    void convert(const openvdb::Coord& origin, LeafList& leaves)
    {
        mLow = origin - openvdb::Coord(kHalo);
        if (!mayCross()) return;
        sample();
        if (!seed()) return;
        mMarching.run(mDims, mH, mBackground, mDistance);
        for (int z = 0; z < kTile.z(); z += int(Leaf::DIM)) {
            for (int y = 0; y < kTile.y(); y += int(Leaf::DIM)) {
                for (int x = 0; x < kTile.x(); x += int(Leaf::DIM)) emitLeaf(origin + openvdb::Coord(x, y, z), leaves);
            }
        }
    }

private:
    size_t index(const openvdb::Coord& local) const
    {
        return (size_t(local.z()) * size_t(mDims.y()) + size_t(local.y())) * size_t(mDims.x()) + size_t(local.x());
    }

    /// False if every sample the window's interpolation reads is on one side of the iso-value.
    bool mayCross() const
    {
        const auto [lo, hi] = range(openvdb::CoordBBox(openvdb::Coord(0), mDims.offsetBy(-1)));
        return lo <= mIso && hi > mIso;
    }

    /// The window's samples, chunk by chunk: a chunk with no crossing within two voxels of it
    /// (so its values serve only as a side, never in a seed's estimate) is filled with one value
    /// from the right side instead of being interpolated.
    void sample()
    {
        mSamples.resize(size_t(mDims.x()) * mDims.y() * mDims.z());
        constexpr int kChunk = 8, kReach = 2;
        for (int z0 = 0; z0 < mDims.z(); z0 += kChunk) {
            for (int y0 = 0; y0 < mDims.y(); y0 += kChunk) {
                for (int x0 = 0; x0 < mDims.x(); x0 += kChunk) {
                    const openvdb::CoordBBox chunk(
                        openvdb::Coord(x0, y0, z0),
                        openvdb::Coord::minComponent(openvdb::Coord(x0, y0, z0).offsetBy(kChunk - 1),
                                                     mDims.offsetBy(-1)));
                    const auto [lo, hi] =
                        range(openvdb::CoordBBox(chunk.min().offsetBy(-kReach), chunk.max().offsetBy(kReach)));
                    if (lo > mIso || hi <= mIso) {
                        fill(chunk, lo > mIso ? lo : hi);
                    } else {
                        interpolate(chunk);
                    }
                }
            }
        }
    }

    /// The range of the samples interpolation reads for a box of window voxels.
    std::pair<float, float> range(const openvdb::CoordBBox& local) const
    {
        const openvdb::CoordBBox box(local.min() + mLow, local.max() + mLow);
        return mRanges.range(transformedBounds(mScanFromOutput, box), mOutside);
    }

    void fill(const openvdb::CoordBBox& chunk, float value)
    {
        for (int z = chunk.min().z(); z <= chunk.max().z(); ++z) {
            for (int y = chunk.min().y(); y <= chunk.max().y(); ++y) {
                const size_t row = index(openvdb::Coord(chunk.min().x(), y, z));
                std::fill_n(&mSamples[row], chunk.dim().x(), value);
            }
        }
    }

    void interpolate(const openvdb::CoordBBox& chunk)
    {
        mPoints.resize(size_t(chunk.dim().x()));
        for (int z = chunk.min().z(); z <= chunk.max().z(); ++z) {
            for (int y = chunk.min().y(); y <= chunk.max().y(); ++y) {
                for (int x = 0; x < chunk.dim().x(); ++x) {
                    mPoints[size_t(x)] =
                        mScanFromOutput.transform((mLow + openvdb::Coord(chunk.min().x() + x, y, z)).asVec3d());
                }
                mScan.sample(mPoints.data(), mPoints.size(), mOutside,
                             &mSamples[index(openvdb::Coord(chunk.min().x(), y, z))]);
            }
        }
    }

    /// Gives the voxels next to a crossing their distance to it; false if there is none. The
    /// estimate |iso - f| / |grad f| keeps the surface's voxel-scale detail (the mesher then finds
    /// the crossings where the scan has them, as FlyingEdges does); where it exceeds a voxel (a
    /// gradient that central differences flatten) the distance to the plane through the voxel's
    /// edge crossings is used instead, as fast sweeping's initialisation does.
    bool seed()
    {
        mDistance.assign(mSamples.size(), std::numeric_limits<float>::infinity());
        bool any = false;
        for (int z = 1; z < mDims.z() - 1; ++z) {
            for (int y = 1; y < mDims.y() - 1; ++y) {
                for (int x = 1; x < mDims.x() - 1; ++x) {
                    const size_t i = index(openvdb::Coord(x, y, z));
                    if (!crossing(i)) continue;
                    mDistance[i] = distanceToCrossing(i);
                    any = true;
                }
            }
        }
        return any;
    }

    bool crossing(size_t i) const
    {
        const bool inside = mSamples[i] > mIso;
        bool crosses = false;
        for (const size_t step : mStep)
            crosses |= (mSamples[i - step] > mIso) != inside || (mSamples[i + step] > mIso) != inside;
        return crosses;
    }

    float distanceToCrossing(size_t i) const
    {
        const double f = mSamples[i];
        double gradient2 = 0.0, inverseEdge2 = 0.0;  // sum over axes of 1 / (crossing distance along it)^2
        for (const size_t step : mStep) {
            const double below = mSamples[i - step], above = mSamples[i + step];
            gradient2 += (above - below) * (above - below);
            double nearest = std::numeric_limits<double>::infinity();  // in voxels
            for (const double n : {below, above}) {
                if ((n > mIso) != (f > mIso)) nearest = std::min(nearest, (mIso - f) / (n - f));
            }
            inverseEdge2 += 1.0 / (nearest * nearest);
        }
        const double estimate = std::abs(mIso - f) / (std::sqrt(gradient2) / (2.0 * mH));
        return float(estimate < mH ? estimate : mH / std::sqrt(inverseEdge2));
    }

    /// The leaf at `origin` if the band reaches it: distances signed by the samples (negative
    /// where they exceed the iso-value), active within the band, +-background elsewhere.
    void emitLeaf(const openvdb::Coord& origin, LeafList& leaves) const
    {
        const auto at = [&](openvdb::Index n) { return index(Leaf::offsetToLocalCoord(n) + origin - mLow); };
        openvdb::Index first = 0;
        while (first < Leaf::SIZE && !(mDistance[at(first)] < mBackground)) ++first;
        if (first == Leaf::SIZE) return;
        auto leaf = std::make_unique<Leaf>(origin, mBackground, false);
        for (openvdb::Index n = 0; n < Leaf::SIZE; ++n) {
            const size_t i = at(n);
            const float sign = mSamples[i] > mIso ? -1.0f : 1.0f;
            const bool band = mDistance[i] < mBackground;
            leaf->setValueOnly(n, sign * (band ? mDistance[i] : mBackground));
            leaf->setActiveState(n, band);
        }
        leaves.push_back(std::move(leaf));
    }

    const ScanVolume& mScan;
    const BlockRanges& mRanges;
    float mIso, mH, mBackground, mOutside;
    openvdb::Mat4d mScanFromOutput;  // scan sample index from output voxel index
    openvdb::Coord mDims, mLow;      // the window: the tile and its margin
    std::array<size_t, 3> mStep;     // index offsets of a voxel's neighbours along x, y, z
    std::vector<openvdb::Vec3d> mPoints;
    std::vector<float> mSamples, mDistance;
    FastMarching mMarching;
};

/// The output lattice: the scan's world box, two voxels of outside around it.
openvdb::CoordBBox outputBox(const ScanVolume& scan, double h)
{
    const openvdb::BBoxd world =
        transformedBounds(scan.worldFromIndex(), openvdb::CoordBBox(openvdb::Coord(0), scan.dims().offsetBy(-1)));
    requireWithinModelExtent(world, h, scan.source());  // before the conversion to int could overflow
    openvdb::CoordBBox box;
    for (int a = 0; a < 3; ++a) {
        box.min()[a] = int(std::floor(world.min()[a] / h)) - 2;
        box.max()[a] = int(std::ceil(world.max()[a] / h)) + 2;
    }
    return box;
}

/// The tiles' first voxels in one layer of tiles (z fixed), x fastest.
std::vector<openvdb::Coord> tileLayer(const openvdb::CoordBBox& box, int z)
{
    std::vector<openvdb::Coord> origins;
    for (int y = box.min().y(); y <= box.max().y(); y += kTile.y()) {
        for (int x = box.min().x(); x <= box.max().x(); x += kTile.x()) origins.emplace_back(x, y, z);
    }
    return origins;
}

}  // namespace

double nativeVoxelSize(const ScanVolume& scan)
{
    double finest = std::numeric_limits<double>::infinity(), coarsest = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (scan.dims()[a] < 2) continue;
        finest = std::min(finest, scan.spacing(a));
        coarsest = std::max(coarsest, scan.spacing(a));
    }
    if (!std::isfinite(finest)) return 1.0;
    // Finer than that only resamples the coarse axes many times over what they hold, and the
    // work grows as the cube: a slab spacing of 1/256 would make a 16^3 scan 4096 x 16 x 4096.
    return std::max(finest, coarsest / kMaxDefaultAnisotropy);
}

FieldImage scanToLevelSet(const ScanVolume& scan, double iso, double h, const Progress& progress)
{
    const auto [lo, hi] = scan.range();
    if (!(iso > lo && iso < hi)) {
        throw InputError(scan.source() + ": iso-value " + formatNumber(iso) + " is outside the samples' range (" +
                         formatNumber(lo) + " .. " + formatNumber(hi) + "): nothing would be inside");
    }
    if (!(h > 0.0) || !std::isfinite(h))
        throw InputError("voxel size must be a positive number (got " + formatNumber(h) + ")");
    openvdb::CoordBBox box = outputBox(scan, h);
    const openvdb::Coord dim = box.dim();
    if (double(dim.x()) * dim.y() * dim.z() > kMaxBoxVoxels) {
        throw InputError(scan.source() + ": voxel size " + formatNumber(h) + " would give " + std::to_string(dim.x()) +
                             " x " + std::to_string(dim.y()) + " x " + std::to_string(dim.z()) +
                             " voxels; choose a coarser voxel size",
                         Remedy::CoarserVoxelSize);
    }
    for (int a = 0; a < 3; ++a) box.min()[a] &= ~(kTile[a] - 1);  // tiles on leaf boundaries (kTile: powers of two)

    const BlockRanges ranges(scan);
    report(progress, 0.05);
    auto grid = makeLevelSetGrid(h, FieldImage::kDefaultHalfWidthVoxels);
    tbb::enumerable_thread_specific<TileConverter> converters(TileConverter(scan, ranges, iso, h));
    for (int z = box.min().z(); z <= box.max().z(); z += kTile.z()) {
        const std::vector<openvdb::Coord> tiles = tileLayer(box, z);
        std::vector<LeafList> leaves(tiles.size());
        tbb::parallel_for(size_t(0), tiles.size(), [&](size_t t) { converters.local().convert(tiles[t], leaves[t]); });
        for (auto& list : leaves) {
            for (auto& leaf : list) grid->tree().addLeaf(leaf.release());
        }
        // The band grows with the surface, which the header cannot tell: stop before it outgrows memory.
        requireMemory(2.0 * double(grid->tree().leafCount()) * (sizeof(Leaf) + Leaf::SIZE * sizeof(float)),
                      scan.source() + "'s surface at voxel size " + formatNumber(h));
        report(progress, 0.05 + 0.95 * std::min(1.0, double(z + kTile.z() - box.min().z()) / box.dim().z()));
    }
    if (grid->tree().leafCount() == 0)
        throw InputError(scan.source() + ": no surface at iso-value " + formatNumber(iso));
    openvdb::tools::signedFloodFill(grid->tree());
    report(progress, 1.0);
    return FieldImage(grid);
}

}  // namespace sculpt
