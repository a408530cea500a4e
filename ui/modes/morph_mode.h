// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file morph_mode.h
/// @brief A finished morph's frames (the Morph panel) shown in place of the document: played
///        (Space), stepped (PageUp/PageDown), scrubbed. Enter or K keeps the frame shown as the
///        document (one undo step); Esc goes back to the document. A tracked morph also shows its
///        tracked mesh as a wireframe over each frame.

#include "ui/document/morph_frames.h"
#include "ui/modes/mode.h"
#include "ui/view/wire_display.h"

namespace sculpt::ui {

class CommandRegistry;
class ModeSlot;

class MorphMode final : public Mode {
public:
    /// Morph To (the morph run as a job, then this mode opened in `slot`), Play, Keep, Export.
    static void addCommands(CommandRegistry& commands, ModeSlot& slot);

    /// `label` names the morph ("morph to cat.vdb").
    MorphMode(vtkRenderer* scene, std::string label, MorphRun run);

    MorphFrames& frames() { return mFrames; }
    /// The tracked mesh's wireframe (a tracked morph's only).
    WireDisplay& wire() { return mWire; }

    const char* name() const override { return "morph"; }
    std::string waitNotice() const override;
    std::string hint() const override;
    bool sync(double now) override;
    const IncrementalMesher* shownMesher() const override { return &mFrames.mesher(); }
    bool showsBrush() const override { return false; }  // no brush on a frame
    bool holdsReplay() const override { return mFrames.playing(); }
    void step(int direction) override { mFrames.show(mFrames.shown() - direction); }
    bool accept(PanelHost& host) override;
    void drawPanel(PanelHost& host) override;
    nlohmann::json report() override;

private:
    std::string mLabel;
    MorphFrames mFrames;
    WireDisplay mWire;
    int mWireFrame = -1;  // the frame whose tracked mesh the wire shows
};

}  // namespace sculpt::ui
