#include "brush_tools.h"

#include "csg_combine.h"
#include "leaf_journal.h"
#include "level_set_evolution.h"
#include "local_patch.h"
#include "primitive_rasterizer.h"

#include <openvdb/math/Mat3.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tree/LeafManager.h>

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace sculpt {

namespace {

using LeafT = openvdb::FloatTree::LeafNodeType;
using ConstAccessor = openvdb::FloatGrid::ConstAccessor;
using openvdb::Coord;
using openvdb::Vec3d;

constexpr double kInflateFraction = 0.1;  // of the radius, per stamp at full strength and pressure
constexpr double kPinchFraction = 0.5;    // of the distance to the stroke line, per stamp
constexpr double kSmoothChunk = 0.5;      // beta t / h^2 between renormalisations

/// Sub-steps needed so that no part of the surface moves more than a voxel at a time: the
/// renormalisation between them rebuilds the band one voxel deep.
int substeps(double motionWorld, double h)
{
    return std::max(1, int(std::ceil(std::abs(motionWorld) / h - 1e-9)));
}

/// Closest surface point to voxel ijk: x - phi grad/|grad| (central differences), world space.
Vec3d footPoint(const ConstAccessor& acc, const Coord& ijk, const openvdb::math::Transform& xform)
{
    const float phi = acc.getValue(ijk);
    const Vec3d grad(acc.getValue(ijk.offsetBy(1, 0, 0)) - acc.getValue(ijk.offsetBy(-1, 0, 0)),
                     acc.getValue(ijk.offsetBy(0, 1, 0)) - acc.getValue(ijk.offsetBy(0, -1, 0)),
                     acc.getValue(ijk.offsetBy(0, 0, 1)) - acc.getValue(ijk.offsetBy(0, 0, -1)));
    const double length = grad.length();
    const Vec3d world = xform.indexToWorld(ijk);
    return length > 0.0 ? world - grad * (phi / length) : world;
}

/// Sets every active voxel of the patch inside `region` to value(ijk, frozen), where `frozen`
/// reads the values before the pass; results are clamped to the band.
template <typename ValueFn>
void remapActive(LocalPatch& patch, const Capsule& region, const ValueFn& value)
{
    openvdb::FloatGrid& grid = patch.field().mutableGrid();
    const openvdb::FloatGrid::Ptr frozen = grid.deepCopy();
    const Capsule indexRegion = region.inIndexSpace(grid.transform());
    const float background = grid.background();
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(grid.tree());
    leaves.foreach([&](LeafT& leaf, size_t) {
        const ConstAccessor acc = frozen->getConstAccessor();
        for (auto it = leaf.beginValueOn(); it; ++it) {
            if (!indexRegion.contains(it.getCoord().asVec3d())) continue;
            it.setValue(std::clamp(float(value(it.getCoord(), acc)), -background, background));
        }
    });
}

/// Sets every voxel inside `region` (active or not) to combine(world, phi), activating the ones
/// that enter the band and deactivating the ones that leave it. Values in parallel, then the
/// tree's structure in one thread. Tiles of value `keptTile` are skipped: combine never changes
/// them (the inside, for a union).
template <typename CombineFn>
void combineVoxels(LocalPatch& patch, const Capsule& region, float keptTile, const CombineFn& combine)
{
    openvdb::FloatGrid& grid = patch.field().mutableGrid();
    const auto& xform = grid.transform();
    const float background = grid.background();
    const std::vector<Coord> origins = leavesMeeting(grid, region);
    const Capsule indexRegion = region.inIndexSpace(xform);
    std::vector<std::array<float, LeafT::SIZE>> values(origins.size());
    std::vector<char> changed(origins.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size()), [&](const auto& range) {
        const ConstAccessor acc = grid.getConstAccessor();
        for (size_t i = range.begin(); i < range.end(); ++i) {
            if (!acc.probeConstLeaf(origins[i]) && acc.getValue(origins[i]) == keptTile) continue;
            for (auto ijk = openvdb::CoordBBox::createCube(origins[i], LeafT::DIM).begin(); ijk; ++ijk) {
                const float old = acc.getValue(*ijk);
                const float value = indexRegion.contains((*ijk).asVec3d())
                                        ? std::clamp(float(combine(xform.indexToWorld(*ijk), old)), -background, background)
                                        : old;
                values[i][LeafT::coordToOffset(*ijk)] = value;
                changed[i] |= value != old;
            }
        }
    });
    auto acc = grid.getAccessor();
    for (size_t i = 0; i < origins.size(); ++i) {
        if (!changed[i]) continue;
        LeafT* leaf = acc.touchLeaf(origins[i]);
        for (openvdb::Index k = 0; k < LeafT::SIZE; ++k) {
            const float value = values[i][k];
            if (value == leaf->getValue(k)) continue;
            if (std::abs(value) < background) {
                leaf->setValueOn(k, value);
            } else {
                leaf->setValueOff(k, value);
            }
        }
    }
}

/// Moves the surface inside `ball` along its normal by amount x falloff at each voxel's closest
/// surface point (a velocity extended along normals keeps the band a distance field).
void offsetUnder(LocalPatch& patch, const FalloffBall& ball, double amountWorld)
{
    const auto& xform = patch.field().grid().transform();
    remapActive(patch, Capsule::ball(ball.centreWorld, ball.radiusWorld), [&](const Coord& ijk, const ConstAccessor& acc) {
        return acc.getValue(ijk) - amountWorld * ball.weightAt(footPoint(acc, ijk, xform));
    });
}

/// Offsets in sub-steps of at most a voxel, renormalising after each.
void offsetInSubsteps(LocalPatch& patch, const FalloffBall& ball, double amountWorld)
{
    const int n = substeps(amountWorld, patch.field().voxelSize());
    for (int i = 0; i < n; ++i) {
        offsetUnder(patch, ball, amountWorld / n);
        patch.renormalise();
    }
}

/// Semi-Lagrangian advection: phi(x) <- phi(x - displacement(x)), trilinear, inside `region`.
template <typename DisplacementFn>
void advect(LocalPatch& patch, const Capsule& region, const DisplacementFn& displacement)
{
    const auto& xform = patch.field().grid().transform();
    remapActive(patch, region, [&](const Coord& ijk, const ConstAccessor& acc) {
        const Vec3d world = xform.indexToWorld(ijk);
        return openvdb::tools::BoxSampler::sample(acc, xform.worldToIndex(world - displacement(world)));
    });
}

/// Polynomial smooth minimum: min(a, b) with a fillet of width k where they meet (k = 0: min).
double smoothMin(double a, double b, double k)
{
    if (k <= 0.0) return std::min(a, b);
    const double t = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - t * t * k * 0.25;
}

/// Fillet width of add / carve, as a fraction of the ball's radius.
double filletFraction(Falloff falloff)
{
    switch (falloff) {
    case Falloff::Smooth: return 0.5;
    case Falloff::Sphere: return 0.25;
    case Falloff::Sharp: return 0.1;
    case Falloff::Constant: return 0.0;
    }
    return 0.0;
}

/// Largest q w(q) over q in [0, 1]: how far, in radii, a pull towards the centre can move a point.
double peakPull(Falloff falloff)
{
    double peak = 0.0;
    for (int i = 0; i <= 64; ++i) peak = std::max(peak, i / 64.0 * falloffWeight(falloff, i / 64.0));
    return peak;
}

/// Volume inside the surface within `region` and the area weighted by the ball's falloff, from
/// smeared Heaviside and delta functions of phi (1.5 voxels wide). One thread, voxel order:
/// deterministic.
std::pair<double, double> volumeAndWeightedArea(const openvdb::FloatGrid& grid, const Capsule& region,
                                                const FalloffBall& ball)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0], epsilon = 1.5 * h, cell = h * h * h;
    const Vec3d reach(region.radius);
    const openvdb::CoordBBox box(xform.worldToIndexCellCentered(region.from - reach),
                                 xform.worldToIndexCellCentered(region.from + reach));
    const ConstAccessor acc = grid.getConstAccessor();
    double volume = 0.0, area = 0.0;
    for (auto ijk = box.begin(); ijk; ++ijk) {
        const Vec3d world = xform.indexToWorld(*ijk);
        if (!region.contains(world)) continue;
        const double phi = acc.getValue(*ijk);
        if (phi <= -epsilon) {
            volume += cell;
        } else if (phi < epsilon) {
            const double t = -phi / epsilon;
            volume += cell * 0.5 * (1.0 + t + std::sin(M_PI * t) / M_PI);
            area += cell * ball.weightAt(world) * (1.0 + std::cos(M_PI * t)) / (2.0 * epsilon);
        }
    }
    return {volume, area};
}

/// Gives back, with an inflate of the brush's falloff, the volume the patch lost inside `region`.
void restoreVolume(LocalPatch& patch, const FalloffBall& ball, const Capsule& region, double targetVolume)
{
    for (int pass = 0; pass < 2; ++pass) {  // the second pass corrects the first's discretisation
        const auto [volume, weightedArea] = volumeAndWeightedArea(patch.field().grid(), region, ball);
        if (!(weightedArea > 0.0)) return;
        offsetInSubsteps(patch, ball, (targetVolume - volume) / weightedArea);
    }
}

struct Plane {
    Vec3d point, normal;  ///< normal points out of the surface
    double distance(const Vec3d& p) const { return normal.dot(p - point); }
};

/// Least-squares plane through the closest surface points of the voxels next to the surface
/// (|phi| < h) under the ball, weighted by the falloff; also the largest distance to it.
std::optional<std::pair<Plane, double>> fitPlane(const openvdb::FloatGrid& grid, const FalloffBall& ball)
{
    const auto& xform = grid.transform();
    const double h = xform.voxelSize()[0];
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    const ConstAccessor acc = grid.getConstAccessor();
    std::vector<std::pair<Vec3d, double>> samples;
    Vec3d outward(0.0);
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
        for (auto it = leaf->cbeginValueOn(); it; ++it) {
            if (std::abs(*it) >= h || !region.contains(xform.indexToWorld(it.getCoord()))) continue;
            const Vec3d foot = footPoint(acc, it.getCoord(), xform);
            const double weight = ball.weightAt(foot) * (1.0 - std::abs(*it) / h);
            if (weight <= 0.0) continue;
            samples.emplace_back(foot, weight);
            outward += (xform.indexToWorld(it.getCoord()) - foot) * (weight * (*it >= 0.0f ? 1.0 : -1.0));
        }
    }
    double total = 0.0;
    Vec3d centroid(0.0);
    for (const auto& [p, w] : samples) { total += w; centroid += p * w; }
    if (samples.size() < 3 || !(total > 0.0)) return std::nullopt;
    centroid /= total;
    openvdb::Mat3d covariance = openvdb::Mat3d::zero();
    for (const auto& [p, w] : samples) {
        const Vec3d d = p - centroid;
        for (int r = 0; r < 3; ++r) for (int c = 0; c < 3; ++c) covariance(r, c) += w * d[r] * d[c];
    }
    openvdb::Mat3d vectors;
    Vec3d values;
    if (!openvdb::math::diagonalizeSymmetricMatrix(covariance, vectors, values)) return std::nullopt;
    int smallest = 0;
    for (int k = 1; k < 3; ++k) if (values[k] < values[smallest]) smallest = k;
    Vec3d normal = vectors.col(smallest);
    if (normal.dot(outward) < 0.0) normal = -normal;
    Plane plane{centroid, normal};
    double farthest = 0.0;
    for (const auto& sample : samples) farthest = std::max(farthest, std::abs(plane.distance(sample.first)));
    return std::make_pair(plane, farthest);
}

} // namespace

DirtyRegion sweepBall(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, CsgMode mode,
                      LeafJournal* journal)
{
    const double h = field.voxelSize(), background = field.grid().background();
    const double radius = brush.radiusWorld * brush.strength * stamp.pressure;
    // The fillet reads phi up to its width away from the surface: no wider than the band.
    const double fillet = std::min(filletFraction(brush.falloff) * radius, background - h);
    const Capsule ball{stamp.previousWorld, stamp.centreWorld, radius};
    LocalPatch patch(field, ball.grownBy(fillet + background + h));
    const float keptTile = float(mode == CsgMode::Add ? -background : background);
    combineVoxels(patch, patch.region(), keptTile, [&](const Vec3d& world, float phi) {
        const double d = ball.axisDistance(world) - radius;
        return mode == CsgMode::Add ? smoothMin(phi, d, fillet) : -smoothMin(-phi, d, fillet);
    });
    patch.renormalise();
    return patch.commit(field, journal);
}

DirtyRegion inflate(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, double direction,
                    LeafJournal* journal)
{
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    LocalPatch patch(field, Capsule::ball(ball.centreWorld, ball.radiusWorld));
    offsetInSubsteps(patch, ball, direction * kInflateFraction * brush.radiusWorld * brush.strength * stamp.pressure);
    return patch.commit(field, journal);
}

DirtyRegion smoothUnder(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const double h = field.voxelSize();
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    LocalPatch patch(field, Capsule::ball(ball.centreWorld, ball.radiusWorld));
    const Capsule measured = Capsule::ball(ball.centreWorld, ball.radiusWorld + field.grid().background());
    const double volumeBefore = brush.keepVolume ? volumeAndWeightedArea(patch.field().grid(), measured, ball).first : 0.0;
    MotionTerms terms;
    terms.smooth = SmoothTerm{h * h, ball};
    // Curvature flow carries the band edge's error inwards by sqrt(2 beta t): renormalise the
    // patch (cheaply, locally) every beta t = h^2 / 2 instead of the evolution's whole-grid tracker.
    EvolutionOptions options;
    options.trackDistanceVoxels = options.trackDiffusionVoxels2 = std::numeric_limits<double>::infinity();
    options.firstOrderTime = true;
    const double duration = brush.strength * stamp.pressure;
    const int chunks = std::max(1, int(std::ceil(duration / kSmoothChunk - 1e-9)));
    for (int i = 0; i < chunks; ++i) {
        LevelSetEvolution(patch.field(), terms, options).advance(duration / chunks);
        patch.renormalise();
    }
    if (brush.keepVolume) restoreVolume(patch, ball, measured, volumeBefore);
    return patch.commit(field, journal);
}

DirtyRegion flatten(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    LocalPatch patch(field, region);
    const auto fit = fitPlane(patch.field().grid(), ball);
    if (!fit) return {};  // no surface under the brush
    const auto& [plane, farthest] = *fit;
    const double fraction = brush.strength * stamp.pressure;
    const int n = substeps(fraction * farthest, field.voxelSize());
    const auto& xform = patch.field().grid().transform();
    for (int i = 0; i < n; ++i) {
        // Step i takes the share of what is left that ends, after n steps, at 1 - fraction.
        const double before = 1.0 - fraction * i / n, after = 1.0 - fraction * (i + 1) / n;
        const double share = 1.0 - after / before;
        remapActive(patch, region, [&](const Coord& ijk, const ConstAccessor& acc) {
            const Vec3d foot = footPoint(acc, ijk, xform);
            return acc.getValue(ijk) + share * ball.weightAt(foot) * plane.distance(foot);
        });
        patch.renormalise();
    }
    return patch.commit(field, journal);
}

DirtyRegion grab(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    const Vec3d drag = (stamp.centreWorld - stamp.previousWorld) * brush.strength;
    const int n = substeps(drag.length(), field.voxelSize());
    LocalPatch patch(field, Capsule{stamp.previousWorld, stamp.previousWorld + drag, brush.radiusWorld});
    if (drag.lengthSqr() == 0.0) return {};
    for (int i = 0; i < n; ++i) {
        // The grabbed region travels with the drag.
        const FalloffBall ball{stamp.previousWorld + drag * (double(i) / n), brush.radiusWorld, brush.falloff};
        advect(patch, Capsule::ball(ball.centreWorld, ball.radiusWorld),
               [&](const Vec3d& world) { return drag * (ball.weightAt(world) / n); });
        patch.renormalise();
    }
    return patch.commit(field, journal);
}

DirtyRegion pinch(FieldImage& field, const BrushSettings& brush, const BrushStamp& stamp, LeafJournal* journal)
{
    Vec3d axis = stamp.centreWorld - stamp.previousWorld;
    if (axis.length() < 1e-9 * brush.radiusWorld) axis = stamp.viewDirection;
    if (!(axis.length() > 0.0)) axis = Vec3d(0.0, 0.0, 1.0);
    axis.normalize();
    const FalloffBall ball{stamp.centreWorld, brush.radiusWorld, brush.falloff};
    const Capsule region = Capsule::ball(ball.centreWorld, ball.radiusWorld);
    const double total = kPinchFraction * brush.strength * stamp.pressure;
    const int n = substeps(total * peakPull(brush.falloff) * brush.radiusWorld, field.voxelSize());
    const double share = 1.0 - std::pow(1.0 - total, 1.0 / n);
    LocalPatch patch(field, region);
    for (int i = 0; i < n; ++i) {
        advect(patch, region, [&](const Vec3d& world) {
            const Vec3d onLine = ball.centreWorld + axis * (world - ball.centreWorld).dot(axis);
            return (onLine - world) * (share * ball.weightAt(world));
        });
        patch.renormalise();
    }
    return patch.commit(field, journal);
}

DirtyRegion stampPrimitives(FieldImage& field, const PrimitiveStamp& primitive, const BrushStamp& stamp,
                            LeafJournal* journal)
{
    const PrimitiveSet placed = primitive.primitives.translated(stamp.centreWorld);
    const openvdb::BBoxd box = placed.influence();
    const double reach = 0.5 * box.extents().length() + field.grid().background() + field.voxelSize();
    LocalPatch patch(field, Capsule::ball(box.getCenter(), reach));
    const FieldImage shape = rasterizePrimitives(placed, field.grid().transform(), field.halfWidthVoxels());
    combine(patch.field(), shape, primitive.operation);
    return patch.commit(field, journal);
}

} // namespace sculpt
