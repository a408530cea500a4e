// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file errors.h
/// @brief Exception types of the engine.
///
/// Core never exits and never prints: it throws. An InputError means the user's input (a file,
/// a parameter, a path) is at fault and the message names it; the command line maps it to exit
/// code 2 and the UI shows it while keeping the document. Any other std::exception is a bug or
/// an environment failure (exit code 1).

#include <stdexcept>
#include <string>

namespace sculpt {

/// What the user can change to get past an InputError. Core says it in words ("choose a coarser
/// voxel size"); a front end may add the control that does it (the CLI names its flag).
enum class Remedy { None, CoarserVoxelSize, FinerVoxelSize, AlignShapes, DescribeRawLayout, ChooseGrid };

/// Bad user input: the message is one sentence naming the file, field or value at fault.
class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message, Remedy remedy = Remedy::None)
        : std::runtime_error(message), mRemedy(remedy)
    {}
    Remedy remedy() const { return mRemedy; }

private:
    Remedy mRemedy;
};

}  // namespace sculpt
