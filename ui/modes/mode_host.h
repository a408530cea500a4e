#pragma once
/// @file mode_host.h
/// @brief What a mode may ask of the window when it is accepted: the document, a whole-model
///        edit or a new document made as a job, the unsaved-changes question, a notice.

#include "core/base/progress.h"
#include "core/field/field_image.h"
#include "ui/commands/commands.h"
#include "ui/jobs/model_edit.h"

#include <functional>
#include <memory>
#include <string>

namespace sculpt {
class Document;
}  // namespace sculpt

namespace sculpt::ui {

class ModeHost {
public:
    /// Sees a document's field once it is read, before its mesh is made: a large model shows a
    /// coarse preview meanwhile.
    using FieldReady = std::function<void(const FieldImage& field)>;
    using DocumentMaker = std::function<std::unique_ptr<Document>(const Progress& progress, const FieldReady& ready)>;

    virtual Document& document() = 0;
    /// Runs `edit` on a copy of the model as a job; its result lands as one undo step.
    virtual void startEdit(ModelEdit edit) = 0;
    /// Runs `make` as a job; the document it makes replaces the current one, and `notice`
    /// (called then) says so. `make` hands its field to `ready` before meshing it.
    virtual void startDocument(std::string label, DocumentMaker make, std::function<std::string()> notice) = 0;
    /// False when there are unsaved changes: the user is asked, and `again` runs once answered.
    virtual bool guardUnsaved(Command again) = 0;
    /// A recovery copy now, before a file is read.
    virtual void autosaveNow() = 0;
    /// The status bar's notice.
    virtual void notify(std::string notice) = 0;

protected:
    ~ModeHost() = default;
};

}  // namespace sculpt::ui
