// SPDX-License-Identifier: Apache-2.0
#include "core/base/errors.h"
#include "ui/panels/dialogs.h"
#include "ui/status/notices.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

namespace {

const char* kindName(Prompt::Kind kind)
{
    using K = Prompt::Kind;
    switch (kind) {
    case K::New: return "new";
    case K::Open: return "open";
    case K::SaveAs: return "save-as";
    case K::ExportMesh: return "export";
    case K::ExportLabels: return "export-labels";
    case K::SaveStrokes: return "save-strokes";
    case K::SmoothModel: return "smooth-model";
    case K::OffsetModel: return "offset-model";
    case K::HollowModel: return "hollow-model";
    case K::RemoveIslands: return "remove-islands";
    case K::Morph: return "morph";
    case K::MorphExport: return "morph-export";
    case K::Target: return "target";
    case K::Import: return "import";
    case K::LoadScene: return "load-scene";
    case K::SaveScene: return "save-scene";
    case K::None: break;
    }
    return "none";
}

}  // namespace

bool Prompt::settingsOnly() const
{
    return kind == Kind::New || kind == Kind::SmoothModel || kind == Kind::OffsetModel || kind == Kind::HollowModel ||
           kind == Kind::RemoveIslands;
}

void Dialogs::ask(Prompt::Kind kind, std::string path, Prompt::Confirm confirm)
{
    prompt.kind = kind;
    if (path.empty() && (kind == Prompt::Kind::Open || kind == Prompt::Kind::Import)) path = std::move(dropped);
    dropped.clear();
    prompt.path = std::move(path);
    prompt.focusField = true;
    prompt.confirm = std::move(confirm);
}

void Dialogs::confirm(Notices& notices)
{
    const Prompt::Confirm action = std::move(prompt.confirm);
    const std::filesystem::path path = prompt.path;
    prompt.kind = Prompt::Kind::None;
    try {
        if (action) action(path);
    } catch (const InputError& e) {
        notices.fail(e.what());
    }
}

void Dialogs::report(nlohmann::json& out) const
{
    out["prompt"] = kindName(prompt.kind);
    out["prompt_path"] = prompt.path;  // the prompt's field, as the file chooser and Tab left it
    out["listed"] = prompt.listing.entries.size();
}

}  // namespace sculpt::ui
