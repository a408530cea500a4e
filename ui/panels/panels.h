#pragma once
/// @file panels.h
/// @brief The ImGui panels over the 3D view, one file each: the menu bar, the tool palette,
///        the history, the status bar, the dialogs and the help.

#include "ui/commands/commands.h"
#include "ui/document/file_listing.h"

#include <string>

namespace sculpt::ui {

class ImportDraft;
class MorphMode;
class PrimitiveDraft;
class SculptApp;

void drawMainMenu(SculptApp& app);
void drawToolPanel(SculptApp& app);
void drawHistoryPanel(SculptApp& app);
/// The document's pieces (when it has several, or in pieces mode): pick the one to sculpt, its
/// name, colour, visibility, solo, duplicate, delete, split and merge, push on contact.
void drawPiecesPanel(SculptApp& app);
void drawStatusBar(SculptApp& app);
void drawDialogs(SculptApp& app);
void drawHelpPanel(SculptApp& app);
/// The running job's progress bar and Cancel button, if a job runs.
void drawJobPanel(SculptApp& app);
/// A finished morph's frames: slider, play/pause, step, keep, export, close.
void drawMorphPanel(SculptApp& app, MorphMode& mode);
/// The scan or mesh being imported: what it holds, the iso-value over its histogram, crop,
/// smoothing, cleanup, voxel size and what the result becomes; Apply or Cancel.
void drawImportPanel(SculptApp& app, ImportDraft& draft);
/// The primitives being placed: their list, the selected one's skeleton and kernel, the scene's
/// iso-value and operation; Bake, Load and Save.
void drawPrimitivesPanel(SculptApp& app, PrimitiveDraft& draft);

/// A prompt's path field (focused when the prompt opens, Tab completes) and the file chooser
/// under it, listing what `kinds` accepts. True: answered (Enter in the field, or a file
/// double-clicked).
bool fileField(SculptApp& app, const FileKinds& kinds, const char* id);

/// A fixed window under the brush palette (the Import and Primitives panels); End() closes it.
void beginSidePanel(const char* title, float width);
/// Text in the warning colour, wrapped to `width` pixels.
void warningText(const std::string& text, float width);

/// A menu item running `command`, its keys shown beside it, greyed out when it cannot run.
void commandMenuItem(SculptApp& app, Command command);
/// A button running `command`, labelled as it is, greyed out when it cannot run, with its tooltip.
void commandButton(SculptApp& app, Command command);
/// The tooltip of the last item: what `command` does, its keys, and why it cannot run now.
void commandTooltip(const SculptApp& app, Command command);

}  // namespace sculpt::ui
