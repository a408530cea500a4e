// SPDX-License-Identifier: Apache-2.0
#include "core/motion/surface_flows.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/local/speck_removal.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"

#include <openvdb/tree/LeafManager.h>

#include <algorithm>
#include <cmath>

namespace sculpt {

void smooth(FieldImage& field, int iterations, bool keepVolume, const Progress& progress)
{
    if (iterations < 0) throw InputError("iterations must be >= 0 (got " + std::to_string(iterations) + ")");
    MotionTerms terms;
    terms.smooth = SmoothTerm{1.0, std::nullopt};
    if (keepVolume) terms.volume = VolumeTerm{meshVolumeArea(field).volume, 1.0};
    LevelSetEvolution evolution(field, terms);
    for (int i = 0; i < iterations; ++i) {
        evolution.step();
        report(progress, double(i + 1) / double(iterations));
    }
    if (iterations > 0) {
        evolution.redistance();
        removeSpecks(field);
        evolution.settleVolume();
    }
}

namespace {

/// Clamps every active value of `field` that `start` holds too within `slack` of it.
void holdNear(openvdb::FloatGrid& field, const openvdb::FloatGrid& start, float slack)
{
    openvdb::tree::LeafManager<openvdb::FloatTree> leaves(field.tree());
    leaves.foreach ([&](openvdb::FloatTree::LeafNodeType& leaf, std::size_t) {
        const openvdb::FloatTree::LeafNodeType* before = start.tree().probeConstLeaf(leaf.origin());
        if (!before) return;
        for (auto v = leaf.beginValueOn(); v; ++v) {
            if (!before->isValueOn(v.pos())) continue;
            const float was = before->getValue(v.pos());
            v.setValue(std::clamp(*v, was - slack, was + slack));
        }
    });
}

}  // namespace

void antiAlias(FieldImage& field, int iterations, const Progress& progress)
{
    if (iterations < 0) throw InputError("iterations must be >= 0 (got " + std::to_string(iterations) + ")");
    if (iterations == 0) return;
    const openvdb::FloatGrid::ConstPtr start = field.grid().deepCopy();
    const auto slack = float(0.5 * field.voxelSize());
    MotionTerms terms;
    terms.smooth = SmoothTerm{1.0, std::nullopt};
    terms.volume = VolumeTerm{meshVolumeArea(field).volume, 1.0};
    LevelSetEvolution evolution(field, terms);
    for (int i = 0; i < iterations; ++i) {
        evolution.step();
        holdNear(field.mutableGrid(), *start, slack);
        report(progress, double(i + 1) / double(iterations));
    }
    evolution.redistance();
}

void offset(FieldImage& field, double distanceWorld, const Progress& progress)
{
    if (!std::isfinite(distanceWorld)) throw InputError("offset distance must be finite");
    if (distanceWorld == 0.0) return;
    MotionTerms terms;
    terms.uniform = UniformTerm{distanceWorld > 0.0 ? 1.0 : -1.0};
    LevelSetEvolution evolution(field, terms);
    const double duration = std::abs(distanceWorld);
    while (evolution.time() < duration) {
        evolution.step(duration - evolution.time());
        report(progress, evolution.time() / duration);
    }
    evolution.redistance();
    removeSpecks(field);
}

}  // namespace sculpt
