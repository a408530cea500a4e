// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file panels.h
/// @brief The ImGui panels over the 3D view, one file each: the menu bar, the tool palette,
///        the history, the pieces, the status bar, the dialogs and the help; and the commands of
///        their menus and dialogs. They see the window through PanelHost only.

#include "ui/commands/commands.h"
#include "ui/document/file_listing.h"

#include <string>

namespace sculpt::ui {

class CommandRegistry;
class PanelHost;

void drawMainMenu(PanelHost& host);
void drawToolPanel(PanelHost& host);
void drawHistoryPanel(PanelHost& host);
/// The document's pieces (when it has several, or in pieces mode): pick the one to sculpt, its
/// name, colour, visibility, solo, duplicate, delete, split and merge, push on contact.
void drawPiecesPanel(PanelHost& host);
void drawStatusBar(PanelHost& host);
/// The Slices view's labels (names, directions, window and level) over its views.
void drawSliceLabels(PanelHost& host);
void drawDialogs(PanelHost& host);
void drawHelpPanel(PanelHost& host);
/// The running job's progress bar and Cancel button, if a job runs.
void drawJobPanel(PanelHost& host);

/// The commands of the panels' menus and dialogs, each file adding its own: File
/// (file_commands.cpp), Filters and Mask (model_commands.cpp), View (view_commands.cpp), the
/// dialogs' answers (dialog_commands.cpp).
void addPanelCommands(CommandRegistry& commands, PanelHost& host);
void addFileCommands(CommandRegistry& commands, PanelHost& host);
void addModelCommands(CommandRegistry& commands, PanelHost& host);
void addViewCommands(CommandRegistry& commands, PanelHost& host);
void addDialogCommands(CommandRegistry& commands, PanelHost& host);

/// A prompt's path field (focused when the prompt opens, Tab completes) and the file chooser
/// under it, listing what `kinds` accepts. True: answered (Enter in the field, or a file
/// double-clicked).
bool fileField(PanelHost& host, const FileKinds& kinds, const char* id);

/// A fixed window under the brush palette (the Import and Primitives panels); End() closes it.
void beginSidePanel(const char* title, float width);
/// A fixed window centred at the bottom (the job's progress, the morph's frames); End() closes it.
void beginBottomPanel(const char* title, bool titleBar);
/// Text in the warning colour, wrapped to `width` pixels.
void warningText(const std::string& text, float width);

/// A menu item running `command`, its keys shown beside it, greyed out when it cannot run.
void commandMenuItem(PanelHost& host, Command command);
/// A button running `command`, labelled as it is, greyed out when it cannot run, with its tooltip.
void commandButton(PanelHost& host, Command command);
/// The tooltip of the last item: what `command` does, its keys, and why it cannot run now.
void commandTooltip(const PanelHost& host, Command command);

}  // namespace sculpt::ui
