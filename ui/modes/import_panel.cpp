// SPDX-License-Identifier: Apache-2.0
// ImportMode's panel: what the file holds, the iso-value over its histogram, crop, smoothing,
// cleanup, voxel size and what the result becomes; Apply or Cancel.

#include "ui/modes/import_mode.h"
#include "ui/panels/panel_host.h"
#include "ui/panels/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sculpt::ui {

namespace {

constexpr float kPanelWidth = 340.f;
constexpr int kShownBins = 64;  // of the 256 counted: integer-valued scans leave every other bin empty

void scanFacts(const ScanVolume& scan)
{
    const openvdb::Coord d = scan.dims();
    ImGui::Text("%d x %d x %d samples", d.x(), d.y(), d.z());
    ImGui::Text("spacing %.4g x %.4g x %.4g", scan.spacing(0), scan.spacing(1), scan.spacing(2));
    const openvdb::Mat4d& m = scan.worldFromIndex();
    bool aligned = true;  // the index axes along the world's, each scaled by its spacing
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            aligned &= r == c ? m(c, r) != 0.0 : m(c, r) == 0.0;  // a flipped axis is still aligned
    if (aligned) ImGui::Text("axis-aligned, origin %.4g, %.4g, %.4g LPS", m(3, 0), m(3, 1), m(3, 2));
    else ImGui::Text("oblique, origin %.4g, %.4g, %.4g LPS", m(3, 0), m(3, 1), m(3, 2));
    const auto [lo, hi] = scan.range();
    ImGui::Text("values %.4g .. %.4g", lo, hi);
    for (const std::string& warning : scan.warnings()) warningText(warning, kPanelWidth - 20.f);
}

/// The histogram (log counts: the background's bin dwarfs tissue's) with Otsu's threshold (red)
/// and the iso-value (white) marked.
void histogramPlot(ImportDraft& draft)
{
    const std::vector<double>& counts = draft.file().histogram(draft.options);
    std::vector<double> merged(kShownBins, 0.0);
    for (std::size_t i = 0; i < counts.size(); ++i) merged[i * kShownBins / counts.size()] += counts[i];
    std::vector<float> heights(merged.size());
    std::transform(merged.begin(), merged.end(), heights.begin(), [](double c) { return float(std::log1p(c)); });
    const ImVec2 size(kPanelWidth - 20.f, 70.f);
    ImGui::PlotHistogram("##histogram", heights.data(), int(heights.size()), 0, nullptr, 0.f, FLT_MAX, size);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const std::pair<double, double> range = draft.file().range(draft.options);
    const auto mark = [&](double value, ImU32 colour) {
        const double along = (value - range.first) / (range.second - range.first);
        const float x = lo.x + float(along) * (hi.x - lo.x);
        ImGui::GetWindowDrawList()->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), colour, 2.f);
    };
    mark(draft.file().otsuThreshold(draft.options), IM_COL32(255, 90, 80, 255));
    mark(draft.iso(), IM_COL32(255, 255, 255, 255));
}

/// A label map's label to import, or all its samples as intensities (at an iso-value).
void labelControls(ImportDraft& draft)
{
    const std::vector<int>& labels = draft.file().labels();
    if (labels.size() <= 2) return;  // a mask, or intensities: no labels to choose from
    constexpr const char* kEvery = "every label, a piece each";
    const std::string shown = draft.labelPieces     ? kEvery
                              : draft.options.label ? std::to_string(*draft.options.label)
                                                    : "none (iso-value)";
    ImGui::SetNextItemWidth(200.f);
    if (ImGui::BeginCombo("label", shown.c_str())) {
        if (ImGui::Selectable(kEvery, draft.labelPieces)) {
            draft.labelPieces = true;
            draft.options.label.reset();
            draft.result = ImportDraft::Result::NewDocument;
        }
        if (ImGui::Selectable("none (iso-value)", !draft.options.label && !draft.labelPieces)) {
            draft.options.label.reset();
            draft.labelPieces = false;
        }
        for (const int label : labels)
            if (ImGui::Selectable(std::to_string(label).c_str(), draft.options.label == label)) {
                draft.options.label = label;
                draft.options.iso.reset();
                draft.labelPieces = false;
            }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("a label map (%zu labels): the surface around one label's samples, anti-aliased",
                          labels.size());
}

void isoControls(ImportDraft& draft)
{
    if (draft.options.label) return;  // a label's surface is where its mask crosses 0.5
    const auto [lo, hi] = draft.file().range(draft.options);
    float iso = float(draft.iso());
    ImGui::SetNextItemWidth(200.f);
    if (ImGui::SliderFloat("iso-value", &iso, float(lo), float(hi), "%.4g")) draft.options.iso = iso;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Inside is where samples exceed it (PageUp/PageDown step it)");
    ImGui::SameLine();
    if (ImGui::Button(draft.options.iso ? "Otsu" : "Otsu *")) draft.options.iso.reset();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Otsu's threshold (red): the value splitting the histogram best in two");
}

void cropControls(ImportDraft& draft)
{
    const openvdb::Coord d = draft.file().scan().dims();
    bool crop = draft.options.crop.has_value();
    if (ImGui::Checkbox("crop", &crop)) {
        if (crop) draft.options.crop = openvdb::CoordBBox(openvdb::Coord(0), d - openvdb::Coord(1));
        else draft.options.crop.reset();
    }
    if (!draft.options.crop) return;
    openvdb::CoordBBox& box = *draft.options.crop;
    int from[3] = {box.min().x(), box.min().y(), box.min().z()}, to[3] = {box.max().x(), box.max().y(), box.max().z()};
    ImGui::SetNextItemWidth(200.f);
    const bool a = ImGui::InputInt3("from", from);
    ImGui::SetNextItemWidth(200.f);
    const bool b = ImGui::InputInt3("to", to);
    if (!a && !b) return;
    for (int k = 0; k < 3; ++k) {
        from[k] = std::clamp(from[k], 0, d[k] - 1);
        to[k] = std::clamp(to[k], from[k], d[k] - 1);
    }
    box = openvdb::CoordBBox(openvdb::Coord(from[0], from[1], from[2]), openvdb::Coord(to[0], to[1], to[2]));
}

void scanControls(ImportDraft& draft)
{
    scanFacts(draft.file().scan());
    histogramPlot(draft);
    labelControls(draft);
    isoControls(draft);
    cropControls(draft);
    float sigma = float(draft.options.smoothSigma);
    ImGui::SetNextItemWidth(120.f);
    if (ImGui::InputFloat("smoothing sigma", &sigma, 0.f, 0.f, "%.3g", ImGuiInputTextFlags_EnterReturnsTrue))
        draft.options.smoothSigma = std::max(0.f, sigma);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gaussian pre-smoothing of noisy scans, world units (0: none)");
    bool antiAlias = antiAliasesMask(draft.options, draft.file().twoValued());
    if (ImGui::Checkbox("anti-alias terraces", &antiAlias)) draft.options.antiAliasMask = antiAlias;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("smooth away the voxel terraces of a surface cut from binary data, keeping every sample\n"
                          "on its side (on by default for masks: scans of two values); applied on import");
}

void meshFacts(const ImportDraft& draft)
{
    const MeshImportReport& mesh = draft.file().meshReport();
    ImGui::Text("%zu triangles", mesh.triangles);
    if (!mesh.closed()) {
        warningText("not closed: " + std::to_string(mesh.boundaryEdges) + " open edges, " +
                        std::to_string(mesh.nonManifoldEdges) +
                        " non-manifold; inside and outside are guessed where it is open",
                    kPanelWidth - 20.f);
    }
}

void resultControls(PanelHost& host, ImportDraft& draft)
{
    ImGui::Checkbox("largest piece only", &draft.options.largestComponent);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drop islands and fill closed cavities: one printable solid");
    int result = int(draft.result);
    ImGui::RadioButton("new document", &result, 0);
    ImGui::SameLine();
    ImGui::RadioButton("union", &result, 1);
    ImGui::SameLine();
    ImGui::RadioButton("difference", &result, 2);
    draft.result = ImportDraft::Result(result);
    if (draft.result != ImportDraft::Result::NewDocument) draft.labelPieces = false;  // pieces make a document
    const double documentVoxel = host.document().session().field().voxelSize();
    if (draft.result != ImportDraft::Result::NewDocument) {
        ImGui::Text("voxel size %.4g (the document's)", documentVoxel);
        return;
    }
    float voxel = float(draft.options.voxelSize.value_or(draft.file().defaultVoxelSize()));
    ImGui::SetNextItemWidth(120.f);
    if (ImGui::InputFloat("voxel size", &voxel, 0.f, 0.f, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue) && voxel > 0.f)
        draft.options.voxelSize = voxel;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Of the document made; default: the scan's smallest spacing, or a mesh's longest side / 256");
}

}  // namespace

void ImportMode::drawPanel(PanelHost& host)
{
    ImportDraft& draft = mDraft;
    beginSidePanel("Import", kPanelWidth);
    ImGui::TextUnformatted(draft.file().path().filename().string().c_str());
    if (draft.file().isScan()) scanControls(draft);
    else meshFacts(draft);
    resultControls(host, draft);
    ImGui::Separator();
    if (!draft.problem().empty()) {
        warningText(draft.problem(), kPanelWidth - 20.f);
    } else {
        ImGui::TextDisabled("preview at voxel size %.3g, made in %.0f ms", draft.file().previewVoxelSize(),
                            draft.previewMs());
    }
    if (ImGui::Button("Apply (Enter)")) host.execute(Command::Confirm);
    commandTooltip(host, Command::ApplyImport);
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) host.execute(Command::Cancel);
    ImGui::End();
}

}  // namespace sculpt::ui
