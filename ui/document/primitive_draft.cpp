// SPDX-License-Identifier: Apache-2.0
#include "ui/document/primitive_draft.h"

#include "core/base/errors.h"
#include "core/primitives/primitive_rasterizer.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

namespace {

/// The draft's fields as written in a scene file, valid or not: what change detection compares.
std::string fingerprint(const std::vector<Primitive>& primitives, double iso, CsgOperation operation)
{
    nlohmann::json j = {{"iso", iso}, {"operation", int(operation)}};
    for (const Primitive& p : primitives) {
        nlohmann::json one = {
            {"type", int(p.skeleton.type)},
            {"kernel", int(p.kernel.type)},
            {"radius", p.kernel.radius},
            {"strength", p.kernel.strength},
            {"neighbours", p.neighbours},
            {"half", {p.skeleton.halfExtents.x(), p.skeleton.halfExtents.y(), p.skeleton.halfExtents.z()}}};
        for (const auto& q : p.skeleton.points) one["points"].push_back({q.x(), q.y(), q.z()});
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) one["rotation"].push_back(p.skeleton.worldFromBox(r, c));
        j["primitives"].push_back(one);
    }
    return j.dump();
}

}  // namespace

openvdb::Vec3d skeletonCentre(const Skeleton& s)
{
    switch (s.type) {
    case SkeletonType::Point:
    case SkeletonType::Box: return s.points[0];
    case SkeletonType::Segment: return 0.5 * (s.points[0] + s.points[1]);
    case SkeletonType::Triangle: return (s.points[0] + s.points[1] + s.points[2]) / 3.0;
    }
    return s.points[0];
}

PrimitiveDraft::PrimitiveDraft(openvdb::math::Transform::ConstPtr voxels) : mVoxels(std::move(voxels)) {}

void PrimitiveDraft::add(SkeletonType type, const openvdb::Vec3d& at, double reach)
{
    Primitive p;
    p.skeleton.type = type;
    p.kernel.radius = reach;
    const double arm = 0.5 * reach;  // the skeleton's size: the blob then reads as its type
    switch (type) {
    case SkeletonType::Point: break;
    case SkeletonType::Segment: p.skeleton.points = {openvdb::Vec3d(-arm, 0, 0), openvdb::Vec3d(arm, 0, 0)}; break;
    case SkeletonType::Triangle:
        p.skeleton.points = {openvdb::Vec3d(-arm, -0.6 * arm, 0), openvdb::Vec3d(arm, -0.6 * arm, 0),
                             openvdb::Vec3d(0, arm, 0)};
        break;
    case SkeletonType::Box: p.skeleton.halfExtents = openvdb::Vec3d(0.5 * arm); break;
    }
    primitives.push_back(p);
    selected = int(primitives.size()) - 1;
    moveSelectedTo(at);
}

void PrimitiveDraft::removeSelected()
{
    if (selected < 0 || selected >= int(primitives.size())) return;
    primitives.erase(primitives.begin() + selected);
    for (Primitive& p : primitives) {  // neighbours point at indices: drop the removed, shift the rest
        std::vector<int> kept;
        for (int n : p.neighbours)
            if (n != selected) kept.push_back(n > selected ? n - 1 : n);
        p.neighbours = kept;
    }
    selected = primitives.empty() ? -1 : std::min(selected, int(primitives.size()) - 1);
}

void PrimitiveDraft::moveSelectedTo(const openvdb::Vec3d& at)
{
    if (selected < 0 || selected >= int(primitives.size())) return;
    Skeleton& s = primitives[size_t(selected)].skeleton;
    const openvdb::Vec3d offset = at - skeletonCentre(s);
    for (openvdb::Vec3d& q : s.points) q += offset;
}

void PrimitiveDraft::load(const Scene& scene)
{
    primitives = scene.primitives.primitives();
    iso = scene.primitives.iso();
    operation = scene.operation;
    selected = primitives.empty() ? -1 : 0;
}

Scene PrimitiveDraft::scene() const
{
    bool graph = false;
    for (const Primitive& p : primitives) graph |= !p.neighbours.empty();
    return Scene{PrimitiveSet(primitives, iso, graph), operation, std::nullopt};
}

bool PrimitiveDraft::refresh()
{
    const std::string now = fingerprint(primitives, iso, operation);
    if (mEver && now == mPreviewed) return false;
    mEver = true;
    mPreviewed = now;
    mPreview.reset();
    mProblem.clear();
    if (primitives.empty()) return true;
    try {
        mPreview = rasterizePrimitives(scene().primitives, *mVoxels);
    } catch (const InputError& e) {
        mProblem = e.what();
    }
    return true;
}

}  // namespace sculpt::ui
