// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file dialogs.h
/// @brief What the dialogs hold between frames: the one prompt open (its kind, its path field
///        and the file chooser under it, what OK does), each dialog's settings kept between
///        openings, and the panels' own fields. The file questions ("save changes?", "recover?",
///        "which level set?") are DocumentFiles', the messages Notices'.

#include "core/motion/morph.h"
#include "sculpt/session/document.h"
#include "sculpt/session/model_filter.h"
#include "ui/document/file_listing.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace sculpt::ui {

class Notices;

/// A prompt: a dialog asking for a path (or for settings), OK running what opened it asked for.
struct Prompt {
    enum class Kind {
        None,
        New,
        Open,
        SaveAs,
        ExportMesh,
        ExportLabels,
        SaveStrokes,
        SmoothModel,
        OffsetModel,
        HollowModel,
        RemoveIslands,
        Morph,
        MorphExport,
        Target,
        Import,
        LoadScene,
        SaveScene
    };
    using Confirm = std::function<void(const std::filesystem::path& path)>;

    Kind kind = Kind::None;
    std::string path;          ///< its text field
    DirectoryListing listing;  ///< what the file chooser under it shows
    double listedAt = -1.0;    ///< when that was read (ImGui's clock)
    bool focusField = false;   ///< the field takes the keyboard at the next frame
    Confirm confirm;           ///< what OK does with the path

    bool open() const { return kind != Kind::None; }
    /// Asks for settings only (New, the model filters), not for a path.
    bool settingsOnly() const;
    /// OK can run: the prompt has a path if it asks for one.
    bool confirmable() const { return open() && (settingsOnly() || !path.empty()); }
};

/// The Pieces panel's name field: of piece `of`, named `seen` then.
struct PieceNameField {
    std::string text, seen;
    std::size_t of = ~std::size_t(0);
};

struct Dialogs {
    Prompt prompt;
    NewShape newShape;          ///< New
    ModelFilter filter;         ///< Smooth, Offset, Hollow, Remove Small Islands
    MorphOptions morph;         ///< Morph To (the target: the prompt's path) ...
    bool morphTracked = false;  ///< ... and whether it tracks a mesh along
    double creaseRadius = 0.0;  ///< Mask Cavities: concave within it is a cavity (0: four voxels)
    PieceNameField pieceName;   ///< the Pieces panel's
    bool help = false;          ///< the Help panel is open
    /// A path dropped on the window: the next Open or Import prompt starts with it.
    std::string dropped;

    /// Opens the prompt `kind` with `path` in its field (an Open or Import prompt without one: the
    /// path dropped, if any), focused; OK runs `confirm` with the path.
    void ask(Prompt::Kind kind, std::string path, Prompt::Confirm confirm);
    /// OK: the prompt closes and runs what it was opened for (an error goes to `notices`).
    void confirm(Notices& notices);
    /// Closes the prompt without running anything (its field stays for the next one).
    void close()
    {
        prompt.kind = Prompt::Kind::None;
        prompt.confirm = nullptr;
    }
    /// The prompt open and its field, in the window's report.
    void report(nlohmann::json& out) const;
};

}  // namespace sculpt::ui
