#pragma once
/// @file model_edit.h
/// @brief A whole-model edit (smooth, offset, import into the model, bake primitives): made on
///        a copy of the model off the UI thread and landing as one undo step, "LABEL done
///        (Ctrl+Z undoes it)". SculptApp::startEdit is its one path.

#include "core/base/progress.h"
#include "core/field/field_image.h"

#include <functional>
#include <string>

namespace sculpt::ui {

struct ModelEdit {
    std::string label;  ///< the job's and the undo step's name
    /// Makes the new model from a copy of the current one.
    std::function<FieldImage(FieldImage model, const Progress& progress)> work;
    /// Once landed: what the notice adds ("iso-value 120"), or "".
    std::function<std::string()> summary;
};

}  // namespace sculpt::ui
