// SPDX-License-Identifier: Apache-2.0
#include "core/scan/label_map.h"

#include "core/base/errors.h"
#include "core/base/memory_budget.h"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

namespace sculpt {

namespace {

/// Each piece's label: its own (PieceLook::label) unless an earlier piece took it, else the
/// smallest value no piece keeps.
std::vector<int> labelValues(const std::vector<Piece>& pieces)
{
    std::set<int> taken;
    std::vector<int> values(pieces.size(), 0);
    for (std::size_t p = 0; p < pieces.size(); ++p)
        if (pieces[p].label > 0 && taken.insert(pieces[p].label).second) values[p] = pieces[p].label;
    int next = 1;
    for (int& value : values) {
        if (value > 0) continue;
        while (taken.count(next)) ++next;
        if (next > kMaxPieceLabel)
            throw InputError("more pieces than a 16-bit label map holds (" + std::to_string(kMaxPieceLabel) + ")");
        taken.insert(value = next);
    }
    return values;
}

/// A piece's signed distance at world points, through its placement.
class PlacedDistance {
public:
    explicit PlacedDistance(const Piece& piece)
        : mGrid(piece.field.grid()), mAccessor(mGrid.getConstAccessor()), mFieldFromWorld(piece.placement.inverse())
    {}
    float at(const openvdb::Vec3d& world)
    {
        const openvdb::Vec3d index = mGrid.transform().worldToIndex(mFieldFromWorld.transform(world));
        float phi = 0.0f;
        openvdb::tools::BoxSampler::sample(mAccessor, index, phi);
        return phi;
    }

private:
    const openvdb::FloatGrid& mGrid;
    openvdb::FloatGrid::ConstAccessor mAccessor;
    openvdb::Mat4d mFieldFromWorld;
};

/// The lattice samples a piece's band can hold: its active box, placed, in the lattice's index
/// space, a sample wider, clipped to the lattice.
openvdb::CoordBBox samplesNear(const Piece& piece, const ScanLattice& lattice)
{
    const openvdb::FloatGrid& grid = piece.field.grid();
    const openvdb::CoordBBox active = grid.evalActiveVoxelBoundingBox();
    openvdb::CoordBBox box;
    if (active.empty()) return box;
    const openvdb::Mat4d indexFromWorld = lattice.worldFromIndex.inverse();
    openvdb::Vec3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const openvdb::Vec3d c((corner & 1) ? active.max().x() : active.min().x(),
                               (corner & 2) ? active.max().y() : active.min().y(),
                               (corner & 4) ? active.max().z() : active.min().z());
        const openvdb::Vec3d at = indexFromWorld.transform(piece.placement.transform(grid.transform().indexToWorld(c)));
        lo = openvdb::math::minComponent(lo, at);
        hi = openvdb::math::maxComponent(hi, at);
    }
    const openvdb::Vec3d limit(lattice.dims.asVec3d());
    for (int a = 0; a < 3; ++a) {  // clamped in doubles first: a far piece must not overflow an int
        lo[a] = std::clamp(std::floor(lo[a]) - 1.0, -1.0, limit[a]);
        hi[a] = std::clamp(std::ceil(hi[a]) + 1.0, -1.0, limit[a]);
    }
    box = openvdb::CoordBBox(openvdb::Coord(int(lo[0]), int(lo[1]), int(lo[2])),
                             openvdb::Coord(int(hi[0]), int(hi[1]), int(hi[2])));
    box.intersect(lattice.indexBox());
    return box;
}

/// Gives the samples of `box` inside piece `p` its label, unless a piece earlier in `pieces`
/// holds them deeper.
void claimSamples(LabelMap& map, const std::vector<Piece>& pieces, const std::vector<int>& pieceOfLabel, std::size_t p,
                  const openvdb::CoordBBox& box)
{
    const std::uint16_t label = std::uint16_t(map.segments[p].label);
    const openvdb::Coord d = map.lattice.dims;
    tbb::parallel_for(tbb::blocked_range<int>(box.min().z(), box.max().z() + 1), [&](const tbb::blocked_range<int>& r) {
        PlacedDistance mine(pieces[p]);
        std::vector<std::unique_ptr<PlacedDistance>> others(pieces.size());
        for (int k = r.begin(); k < r.end(); ++k)
            for (int j = box.min().y(); j <= box.max().y(); ++j)
                for (int i = box.min().x(); i <= box.max().x(); ++i) {
                    const openvdb::Vec3d world = map.lattice.worldFromIndex.transform(openvdb::Vec3d(i, j, k));
                    const float phi = mine.at(world);
                    if (phi >= 0.0f) continue;
                    std::uint16_t& sample = map.labels[(std::size_t(k) * d.y() + j) * d.x() + i];
                    if (sample != 0) {
                        const std::size_t owner = std::size_t(pieceOfLabel[sample]);
                        if (!others[owner]) others[owner] = std::make_unique<PlacedDistance>(pieces[owner]);
                        if (others[owner]->at(world) <= phi) continue;
                    }
                    sample = label;
                }
    });
}

/// Each segment's sample count and index box.
void measureSegments(LabelMap& map, const std::vector<int>& segmentOfLabel)
{
    const openvdb::Coord d = map.lattice.dims;
    std::size_t n = 0;
    for (int k = 0; k < d.z(); ++k)
        for (int j = 0; j < d.y(); ++j)
            for (int i = 0; i < d.x(); ++i, ++n) {
                if (map.labels[n] == 0) continue;
                LabelSegment& segment = map.segments[std::size_t(segmentOfLabel[map.labels[n]])];
                ++segment.samples;
                segment.extent.expand(openvdb::Coord(i, j, k));
            }
}

}  // namespace

int LabelMap::largestLabel() const
{
    // The samples say, not the segments (which a map made by hand may lack).
    return labels.empty() ? 0 : int(*std::max_element(labels.begin(), labels.end()));
}

LabelMap labelMapOf(const std::vector<Piece>& pieces, const ScanLattice& lattice, const Progress& progress)
{
    requireMemory(lattice.samples() * sizeof(std::uint16_t), "the label map");
    LabelMap map{lattice, std::vector<std::uint16_t>(std::size_t(lattice.samples()), 0), {}};
    const std::vector<int> values = labelValues(pieces);
    std::vector<int> pieceOfLabel(std::size_t(*std::max_element(values.begin(), values.end()) + 1), -1);
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        map.segments.push_back({values[p], pieces[p].name, pieces[p].colour, {}, 0});
        pieceOfLabel[std::size_t(values[p])] = int(p);
    }
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const openvdb::CoordBBox box = samplesNear(pieces[p], lattice);
        if (!box.empty()) claimSamples(map, pieces, pieceOfLabel, p, box);
        report(progress, 0.9 * double(p + 1) / double(pieces.size()));
    }
    measureSegments(map, pieceOfLabel);
    return map;
}

}  // namespace sculpt
