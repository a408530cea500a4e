// SPDX-License-Identifier: Apache-2.0
// The dialogs' answers, as keys of Scope::Dialog (a dialog open takes every key): OK and Close,
// "save changes?", "recover?" and "which level set?".

#include "ui/input/input_event.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <GLFW/glfw3.h>

namespace sculpt::ui {

namespace {

void addFileAnswers(CommandRegistry& commands, PanelHost& host)
{
    DocumentFiles& files = host.files();
    const auto execute = [&host](Command command) { host.execute(command); };
    const auto unsavedOpen = [&files] {
        return files.askingUnsaved() ? std::string() : std::string("no unsaved changes are being asked about");
    };
    commands.add({Command::AnswerSave,
                  "Save",
                  "Unsaved changes: save them, then go on",
                  {{GLFW_KEY_S}},
                  unsavedOpen,
                  [&files, execute] { files.answerUnsaved(true, false, execute); },
                  Scope::Dialog});
    commands.add({Command::AnswerDiscard,
                  "Discard",
                  "Unsaved changes: go on without saving them; Recover: delete the autosave",
                  {{GLFW_KEY_D}},
                  [&files, unsavedOpen] { return files.offeringRecovery() ? std::string() : unsavedOpen(); },
                  [&files, execute] {
                      if (files.askingUnsaved()) files.answerUnsaved(false, true, execute);
                      else files.recover(false);
                  },
                  Scope::Dialog});
    commands.add(
        {Command::AnswerRecover,
         "Recover",
         "Recover: open the autosave of the work that was not saved",
         {{GLFW_KEY_R}},
         [&files] { return files.offeringRecovery() ? std::string() : std::string("no autosave is being offered"); },
         [&files] { files.recover(true); },
         Scope::Dialog});
    for (std::size_t index = 0; index < 9; ++index) {
        commands.add({Command(int(Command::ChooseGrid1) + int(index)),
                      "Level set",
                      "Which level set?: open the one with this number",
                      {{GLFW_KEY_1 + int(index)}},
                      [&files, index] {
                          const auto& choice = files.askingGrid();
                          if (choice && index < choice->grids.size()) return std::string();
                          return "no level set has the number " + std::to_string(index + 1);
                      },
                      [&files, index] { files.chooseGrid(files.askingGrid()->grids[index]); },
                      Scope::Dialog});
    }
}

}  // namespace

void addDialogCommands(CommandRegistry& commands, PanelHost& host)
{
    addFileAnswers(commands, host);
    Notices& notices = host.notices();
    Dialogs& dialogs = host.dialogs();
    DocumentFiles& files = host.files();
    commands.add({Command::DialogConfirm,
                  "OK",
                  "Dialogs: confirm the prompt; dismiss an error",
                  {{GLFW_KEY_ENTER}, {GLFW_KEY_KP_ENTER}},
                  [&notices, &dialogs, &files] {
                      if (!notices.error().empty() || (!files.asking() && dialogs.prompt.confirmable()))
                          return std::string();
                      return std::string("nothing to confirm: answer the dialog's question");
                  },
                  [&notices, &dialogs] {
                      if (!notices.error().empty()) notices.dismiss();
                      else dialogs.confirm(notices);
                  },
                  Scope::Dialog});
    commands.add({Command::DialogCancel,
                  "Close",
                  "Dialogs: close without doing anything (unsaved changes: go back)",
                  {{GLFW_KEY_ESCAPE}},
                  [&notices, &files] {
                      return files.offeringRecovery() && notices.error().empty()
                                 ? std::string("recover the autosave (R) or discard it (D)")
                                 : std::string();
                  },
                  [&notices, &dialogs, &files, &host] {
                      if (!notices.error().empty()) notices.dismiss();
                      else if (files.askingGrid()) files.chooseGrid(std::nullopt);
                      else if (files.askingUnsaved())
                          files.answerUnsaved(false, false, [&host](Command c) { host.execute(c); });
                      else dialogs.close();
                  },
                  Scope::Dialog});
}

void addPanelCommands(CommandRegistry& commands, PanelHost& host)
{
    addFileCommands(commands, host);
    addModelCommands(commands, host);
    addViewCommands(commands, host);
    addDialogCommands(commands, host);
}

}  // namespace sculpt::ui
