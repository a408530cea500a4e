#pragma once
/// @file morph_mode.h
/// @brief A finished morph's frames (the Morph panel) shown in place of the document: played
///        (Space), stepped (PageUp/PageDown), scrubbed. Enter or K keeps the frame shown as the
///        document (one undo step); Esc goes back to the document.

#include "ui/document/morph_frames.h"
#include "ui/modes/mode.h"

namespace sculpt::ui {

class MorphMode final : public Mode {
public:
    /// `label` names the morph ("morph to cat.vdb").
    MorphMode(std::string label, MorphRun run) : mLabel(std::move(label)), mFrames(std::move(run)) {}

    MorphFrames& frames() { return mFrames; }

    const char* name() const override { return "morph"; }
    std::string waitNotice() const override;
    std::string hint() const override;
    bool sync(double now) override;
    const IncrementalMesher* shownMesher() const override { return &mFrames.mesher(); }
    bool showsBrush() const override { return false; }  // no brush on a frame
    bool holdsReplay() const override { return mFrames.playing(); }
    void step(int direction) override { mFrames.show(mFrames.shown() - direction); }
    bool accept(ModeHost& host) override;
    void drawPanel(SculptApp& app) override;
    nlohmann::json report() override;

private:
    std::string mLabel;
    MorphFrames mFrames;
};

}  // namespace sculpt::ui
