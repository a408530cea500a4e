// SPDX-License-Identifier: Apache-2.0
#include "tests/ui_unit/headless_app.h"

#include "ui/window/headless_window.h"

namespace sculpt::test {

ui::AppOptions headlessOptions(const TempDir& dir, const std::string& document)
{
    ui::AppOptions options;
    options.document = document;
    options.stateDir = dir / "state";
    return options;
}

int playHeadless(const TempDir& dir, const UiEvents& events, ui::AppOptions options)
{
    options.play = dir / "events.json";
    events.write(options.play);
    ui::HeadlessWindow window(1280, 800);
    ui::SculptApp app(window, options);
    return app.run();
}

}  // namespace sculpt::test
