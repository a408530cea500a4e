// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file model_edit.h
/// @brief A whole-model edit (smooth, offset, a cut, a mask selection, import into the model,
///        bake primitives): made on a copy of the model off the UI thread and landing as one undo
///        step, "LABEL done (Ctrl+Z undoes it)", in the stroke log when a script can replay it.
///        Workspace::startEdit is its one path.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "core/masks/mask_selection.h"
#include "sculpt/session/script_event.h"

#include <functional>
#include <optional>
#include <string>

namespace sculpt::ui {

struct ModelEdit {
    /// What of the result the document takes: the field, or its mask alone.
    enum class Takes { Field, Mask };
    using Work = std::function<FieldImage(FieldImage model, const Progress& progress)>;

    ModelEdit(std::string name, Work make, std::function<std::string()> landed = {})
        : label(std::move(name)), work(std::move(make)), summary(std::move(landed))
    {}

    std::string label;  ///< the job's and the undo step's name
    /// Makes the new model from a copy of the current one.
    Work work;
    /// Once landed: what the notice adds ("iso-value 120"), or "".
    std::function<std::string()> summary;
    /// The event a stroke script replays it by (a cut, a mask selection); none: Save Strokes
    /// refuses the document's log from then on.
    std::optional<ScriptEvent> scripted;
    Takes takes = Takes::Field;
};

/// A cut or fill along a prism of the view, as `sculpt apply` replays it.
ModelEdit prismEdit(const ViewPrism& prism, PrismMode mode, std::string label);
/// A mask made from what `selection` selects (a prism, the cavities, thin walls, an island).
ModelEdit maskSelectionEdit(const MaskSelection& selection, std::string label);

}  // namespace sculpt::ui
