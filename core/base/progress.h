#pragma once
/// @file progress.h
/// @brief How long operations report progress and learn they should stop.

#include <functional>
#include <stdexcept>

namespace sculpt {

/// Called with the fraction done in [0, 1]; returns false to cancel. Empty: no reporting.
using Progress = std::function<bool(double fraction)>;

/// Thrown when a Progress callback asked to stop; the document is left as before the operation
/// or, where stated, at the last consistent state.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

/// Reports `fraction`; throws Cancelled if the callback says stop.
inline void report(const Progress& progress, double fraction)
{
    if (progress && !progress(fraction)) throw Cancelled();
}

}  // namespace sculpt
