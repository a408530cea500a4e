// SPDX-License-Identifier: Apache-2.0
#include "ui/jobs/model_edit.h"

#include "core/solids/prism_cut.h"
#include "sculpt/session/model_filter.h"

namespace sculpt::ui {

ModelEdit prismEdit(const ViewPrism& prism, PrismMode mode, std::string label)
{
    ModelEdit edit(label, [prism, mode, label](FieldImage model, const Progress&) {
        FieldImage result = applyPrism(model, prism, mode);
        refuseEmptyResult(result, "the model", label);
        return result;
    });
    edit.scripted = script::CutEvent{prism, mode};
    return edit;
}

ModelEdit maskSelectionEdit(const MaskSelection& selection, std::string label)
{
    ModelEdit edit(std::move(label), [selection](FieldImage model, const Progress&) {
        applyMaskSelection(model, selection, nullptr);
        return model;
    });
    edit.scripted = script::MaskSelectionEvent{selection};
    edit.takes = ModelEdit::Takes::Mask;
    return edit;
}

}  // namespace sculpt::ui
