// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file progress.h
/// @brief How long operations report progress and learn they should stop.

#include <algorithm>
#include <cstddef>
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

/// `progress` seen by a step that is the share [from, to] of a longer operation.
inline Progress scaledProgress(const Progress& progress, double from, double to)
{
    if (!progress) return {};
    return [progress, from, to](double fraction) { return progress(from + (to - from) * fraction); };
}

/// Runs body(begin, end) over [0, count) in consecutive ranges (one without a callback, about
/// 20 with one), reporting the share done, mapped onto [from, to], after each: a long parallel
/// pass that can say how far it is and stop between ranges.
template <typename Body>
void inBatches(std::size_t count, const Progress& progress, double from, double to, const Body& body)
{
    const std::size_t batch = progress ? std::max<std::size_t>(1, (count + 19) / 20) : std::max<std::size_t>(count, 1);
    for (std::size_t begin = 0; begin < count; begin += batch) {
        const std::size_t end = std::min(count, begin + batch);
        body(begin, end);
        report(progress, from + (to - from) * double(end) / double(count));
    }
}

}  // namespace sculpt
