// SPDX-License-Identifier: Apache-2.0
// A file prompt's path field and, under it, the file chooser: the directory the typed path
// names (its folders and the files the prompt accepts, with size and date), Up, Home and the
// recent files. Typing, Tab (completion) and Enter work without the mouse, and replays drive
// it like any other input.

#include "core/base/text_format.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <cstdio>
#include <ctime>

namespace sculpt::ui {

namespace fs = std::filesystem;

namespace {

constexpr double kRelistSeconds = 1.0;  // files appear and go while the prompt is open

int completeOnTab(ImGuiInputTextCallbackData* data)
{
    const auto& kinds = *static_cast<const FileKinds*>(data->UserData);
    const std::string completed = completePath(std::string(data->Buf, std::size_t(data->BufTextLen)), kinds);
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, completed.c_str());
    return 0;
}

/// The listing of the directory `d.path` names, read again when that changes or has aged.
const DirectoryListing& listingFor(Prompt& d, const FileKinds& kinds)
{
    const fs::path directory = directoryOf(d.path);
    const double now = ImGui::GetTime();
    if (directory != d.listing.directory || now - d.listedAt > kRelistSeconds || d.listedAt < 0.0) {
        d.listing = listDirectory(directory, kinds);
        d.listedAt = now;
    }
    return d.listing;
}

/// Puts `path` in the field (a folder with its "/", so the chooser lists it), the field focused.
void choose(Prompt& d, const fs::path& path, bool folder)
{
    d.path = path.string();
    if (folder && (d.path.empty() || d.path.back() != '/')) d.path += '/';
    d.focusField = true;
    d.listedAt = -1.0;
}

/// The listed directory in full ("" is the current one).
fs::path fullPath(const fs::path& directory)
{
    std::error_code ec;
    fs::path full = fs::absolute(directory.empty() ? fs::path(".") : directory, ec).lexically_normal();
    if (full.filename().empty() && full.has_relative_path()) full = full.parent_path();  // "/a/b/" -> "/a/b"
    return ec ? directory : full;
}

void navigationRow(PanelHost& host, const DirectoryListing& listing)
{
    Prompt& d = host.dialogs().prompt;
    const fs::path full = fullPath(listing.directory);
    if (ImGui::Button("Up")) choose(d, full.parent_path(), true);
    ImGui::SameLine();
    if (ImGui::Button("Home")) choose(d, expandHome("~"), true);
    ImGui::SameLine();
    const std::vector<fs::path>& recent = host.files().recent().entries();
    ImGui::SetNextItemWidth(300.f);
    if (ImGui::BeginCombo("##recent", "Recent files", ImGuiComboFlags_HeightLarge)) {
        for (const fs::path& path : recent) {
            if (ImGui::Selectable(path.string().c_str())) choose(d, path, false);
        }
        if (recent.empty()) ImGui::TextDisabled("none yet");
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%s", full.string().c_str());
}

/// One row; true if a file was double-clicked (the prompt is answered).
bool entryRow(Prompt& d, const DirectoryListing& listing, const FileEntry& entry)
{
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::string label = entry.folder ? entry.name + "/" : entry.name;
    const fs::path path = listing.directory / entry.name;
    const bool selected = fs::path(expandHome(d.path)) == path;
    bool answered = false;
    if (ImGui::Selectable(label.c_str(), selected,
                          ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowDoubleClick)) {
        choose(d, path, entry.folder);
        answered = !entry.folder && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
    }
    ImGui::TableNextColumn();
    if (!entry.folder) ImGui::TextDisabled("%s", formatBytes(double(entry.bytes)).c_str());
    ImGui::TableNextColumn();
    char date[32] = "";
    if (entry.modified) std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::localtime(&entry.modified));
    ImGui::TextDisabled("%s", date);
    return answered;
}

/// The directory's entries; true if a file was double-clicked.
bool entryTable(Prompt& d, const DirectoryListing& listing)
{
    if (!listing.error.empty())
        ImGui::TextDisabled("%s: %s", listing.directory.string().c_str(), listing.error.c_str());
    bool answered = false;
    if (ImGui::BeginTable("##files", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY, ImVec2(640.f, 220.f))) {
        ImGui::TableSetupScrollFreeze(0, 1);
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("size", ImGuiTableColumnFlags_WidthFixed, 80.f);
        ImGui::TableSetupColumn("modified", ImGuiTableColumnFlags_WidthFixed, 120.f);
        ImGui::TableHeadersRow();
        ImGuiListClipper clipper;  // a long folder costs only the rows on screen
        clipper.Begin(int(listing.entries.size()));
        while (clipper.Step()) {
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i)
                answered = entryRow(d, listing, listing.entries[std::size_t(i)]) || answered;
        }
        ImGui::EndTable();
    }
    if (listing.truncated) ImGui::TextDisabled("(only the first %zu entries are listed)", listing.entries.size());
    return answered;
}

}  // namespace

bool fileField(PanelHost& host, const FileKinds& kinds, const char* id)
{
    Prompt& d = host.dialogs().prompt;
    char buffer[4096];
    std::snprintf(buffer, sizeof buffer, "%s", d.path.c_str());
    if (d.focusField) ImGui::SetKeyboardFocusHere();
    d.focusField = false;
    ImGui::SetNextItemWidth(640.f);
    const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackCompletion;
    const bool entered =
        ImGui::InputText(id, buffer, sizeof buffer, flags, completeOnTab, const_cast<FileKinds*>(&kinds));
    d.path = buffer;
    const DirectoryListing& listing = listingFor(d, kinds);
    navigationRow(host, listing);
    return entryTable(d, listing) || entered;
}

}  // namespace sculpt::ui
