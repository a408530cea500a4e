#include "ui/jobs/model_edit.h"

#include "core/solids/prism_cut.h"
#include "sculpt/session/model_filter.h"

namespace sculpt::ui {

ModelEdit prismEdit(const ViewPrism& prism, PrismMode mode, std::string label)
{
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::Cut;
    event.prism = prism;
    event.prismMode = mode;
    ModelEdit edit(label, [prism, mode, label](FieldImage model, const Progress&) {
        FieldImage result = applyPrism(model, prism, mode);
        refuseEmptyResult(result, "the model", label);
        return result;
    });
    edit.scripted = std::move(event);
    return edit;
}

ModelEdit maskSelectionEdit(const MaskSelection& selection, std::string label)
{
    ScriptEvent event;
    event.kind = ScriptEvent::Kind::MaskSelection;
    event.maskSelection = selection;
    ModelEdit edit(std::move(label), [selection](FieldImage model, const Progress&) {
        applyMaskSelection(model, selection, nullptr);
        return model;
    });
    edit.scripted = std::move(event);
    edit.takes = ModelEdit::Takes::Mask;
    return edit;
}

}  // namespace sculpt::ui
