// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file import_mode.h
/// @brief File > Import once the file is read: the Import panel and the preview of the surface
///        its settings give (the document hidden when the import would replace it). Enter
///        imports as a job: a new document, or a union or difference with the model.

#include "ui/document/import_draft.h"
#include "ui/modes/mode.h"
#include "ui/view/shape_display.h"

namespace sculpt::ui {

class CommandRegistry;
class ModeSlot;

class ImportMode final : public Mode {
public:
    ImportMode(vtkRenderer* scene, ImportDraft draft);
    /// File > Import (the file read as a job, then this mode opened in `slot`) and Apply Import.
    static void addCommands(CommandRegistry& commands, ModeSlot& slot);

    ImportDraft& draft() { return mDraft; }

    const char* name() const override { return "import"; }
    std::string waitNotice() const override;
    std::string hint() const override;
    bool sync(double now) override;
    bool hidesDocument() const override { return mDraft.result == ImportDraft::Result::NewDocument; }
    void step(int direction) override;
    bool accept(PanelHost& host) override;
    void drawPanel(PanelHost& host) override;
    nlohmann::json report() override;

private:
    ImportDraft mDraft;
    ShapeDisplay mPreview;
};

}  // namespace sculpt::ui
