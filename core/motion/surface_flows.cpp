#include "core/motion/surface_flows.h"

#include "core/base/errors.h"
#include "core/base/text_format.h"
#include "core/local/speck_removal.h"
#include "core/mesh/field_measures.h"
#include "core/motion/level_set_evolution.h"

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
