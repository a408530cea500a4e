// SPDX-License-Identifier: Apache-2.0
#include "ui/modes/mode_slot.h"

#include "core/base/errors.h"
#include "ui/input/input_event.h"
#include "ui/modes/import_mode.h"
#include "ui/modes/morph_mode.h"
#include "ui/modes/primitives_mode.h"
#include "ui/panels/panel_host.h"

#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

namespace sculpt::ui {

void ModeSlot::open(std::unique_ptr<Mode> mode)
{
    close();
    mMode = std::move(mode);
    mHost.notices().say(mMode->hint());
}

void ModeSlot::close()
{
    if (!mMode) return;
    // Its hint, or why edits waited for it, would mislead once it is gone.
    mHost.notices().unsay(mMode->hint());
    mHost.notices().unsay(mMode->waitNotice());
    mMode.reset();
}

void ModeSlot::accept()
{
    if (!mMode || mHost.workspace().jobs().running()) return;
    try {
        if (mMode->accept(mHost)) close();
    } catch (const InputError& e) {  // the mode stays open, as it was
        mHost.notices().fail(e.what());
    }
}

void ModeSlot::drawPanel()
{
    if (mMode) mMode->drawPanel(mHost);
}

void ModeSlot::addCommands(CommandRegistry& commands)
{
    Workspace& work = mHost.workspace();
    const auto step = [this](int direction) {
        return [this, direction] {
            if (mMode) mMode->step(direction);
        };
    };
    commands.add({Command::Confirm,
                  "Apply",
                  "Applies the open panel: the import, the primitives' bake, the morph frame shown",
                  {{GLFW_KEY_ENTER}, {GLFW_KEY_KP_ENTER}},
                  [this, &work] {
                      if (work.jobs().running()) return work.waitReason();
                      return mMode ? std::string()
                                   : std::string("nothing to apply: Enter applies an import, primitives or a frame");
                  },
                  [this] { accept(); }});
    commands.add({Command::Cancel,
                  "Cancel",
                  "Cancels the running job, else closes the open panel (the document stays as it was)",
                  {{GLFW_KEY_ESCAPE}},
                  nullptr,
                  [this, &work] {
                      if (work.jobs().running()) work.jobs().cancel();
                      else close();
                  }});
    commands.add({Command::StepUp,
                  "Step Up",
                  "Morph: the previous frame; Import: the iso-value up by 1% of the range",
                  {{GLFW_KEY_PAGE_UP}},
                  nullptr,
                  step(1)});
    commands.add({Command::StepDown,
                  "Step Down",
                  "Morph: the next frame; Import: the iso-value down by 1% of the range",
                  {{GLFW_KEY_PAGE_DOWN}},
                  nullptr,
                  step(-1)});
    ImportMode::addCommands(commands, *this);
    PrimitivesMode::addCommands(commands, *this);
    MorphMode::addCommands(commands, *this);
}

void ModeSlot::report(nlohmann::json& out) const
{
    out["morph"] = nullptr;  // read by replays whether or not frames are on show
    out["mode"] = mMode ? nlohmann::json(mMode->name()) : nlohmann::json();
    if (mMode) out[mMode->name()] = mMode->report();
}

}  // namespace sculpt::ui
