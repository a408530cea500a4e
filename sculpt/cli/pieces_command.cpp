// SPDX-License-Identifier: Apache-2.0
#include "core/base/atomic_file.h"
#include "core/base/errors.h"
#include "core/field/document_text.h"
#include "core/io/vdb_file.h"
#include "core/mesh/field_measures.h"
#include "core/pieces/piece_edits.h"
#include "sculpt/cli/command_report.h"
#include "sculpt/cli/commands.h"
#include "sculpt/cli/mesh_output.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

namespace sculpt::cli {

namespace {

struct PiecesOptions {
    std::string input, output;
    std::vector<std::string> add, rename, colour, hide, show, merge, split, remove;
    std::string mesh;
    RunOptions run;
};

/// "a" or "a 2", "a 3", ...: the first of them no piece has.
std::string freeName(const std::vector<Piece>& pieces, const std::string& wanted)
{
    const auto taken = [&](const std::string& name) {
        return std::any_of(pieces.begin(), pieces.end(), [&](const Piece& p) { return p.name == name; });
    };
    std::string name = wanted;
    for (int n = 2; taken(name); ++n) name = wanted + " " + std::to_string(n);
    return name;
}

class PieceList {
public:
    PieceList(std::vector<Piece> pieces, std::string document)
        : mPieces(std::move(pieces)), mDocument(std::move(document))
    {}

    std::vector<Piece>& pieces() { return mPieces; }

    /// The piece named `name`. @throws InputError listing the pieces there are.
    std::vector<Piece>::iterator find(const std::string& name)
    {
        const auto it = std::find_if(mPieces.begin(), mPieces.end(), [&](const Piece& p) { return p.name == name; });
        if (it != mPieces.end()) return it;
        std::string names;
        for (const Piece& p : mPieces) names += (names.empty() ? "'" : ", '") + p.name + "'";
        throw InputError(mDocument + ": no piece is named '" + name + "' (its pieces: " + names + ")");
    }

    void add(Piece piece)
    {
        piece.name = freeName(mPieces, piece.name);
        mPieces.push_back(std::move(piece));
    }

private:
    std::vector<Piece> mPieces;
    std::string mDocument;
};

/// "A=B" split at its '='. @throws InputError naming the option when there is none.
std::pair<std::string, std::string> pairOf(const std::string& text, const char* option)
{
    const auto at = text.find('=');
    if (at == std::string::npos || at == 0 || at + 1 == text.size())
        throw InputError(std::string(option) + " expects NAME=VALUE, got '" + text + "'");
    return {text.substr(0, at), text.substr(at + 1)};
}

/// "#rrggbb" as sRGB 0..1.
openvdb::Vec3f hexColour(const std::string& text)
{
    const bool hex = text.size() == 7 && text[0] == '#' && std::all_of(text.begin() + 1, text.end(), [](char c) {
                         return std::isxdigit(static_cast<unsigned char>(c));
                     });
    if (!hex) throw InputError("--colour expects a colour as #rrggbb, got '" + text + "'");
    const auto channel = [&](int i) {
        return float(std::stoi(text.substr(std::size_t(1 + 2 * i), 2), nullptr, 16)) / 255.0f;
    };
    return {channel(0), channel(1), channel(2)};
}

/// Names and looks: --rename, --colour, --hide, --show.
void relabel(PieceList& list, const PiecesOptions& o)
{
    for (const std::string& change : o.rename) {
        const auto [from, to] = pairOf(change, "--rename");
        if (const std::string problem = pieceNameProblem(to); !problem.empty())
            throw InputError("--rename " + change + ": the new name cannot be: " + problem);
        list.find(from)->name = freeName(list.pieces(), to);
    }
    for (const std::string& change : o.colour) {
        const auto [name, colour] = pairOf(change, "--colour");
        list.find(name)->colour = hexColour(colour);
    }
    for (const std::string& name : o.hide) list.find(name)->visible = false;
    for (const std::string& name : o.show) list.find(name)->visible = true;
}

/// Shapes: --merge A,B (B goes), --split NAME (its solids take its place).
void reshape(PieceList& list, const PiecesOptions& o)
{
    for (const std::string& pair : o.merge) {
        const auto comma = pair.find(',');
        if (comma == std::string::npos) throw InputError("--merge expects A,B, got '" + pair + "'");
        const auto b = list.find(pair.substr(comma + 1));
        const Piece merged = mergePieces(*list.find(pair.substr(0, comma)), *b);
        list.pieces().erase(b);
        *list.find(merged.name) = merged;
    }
    for (const std::string& name : o.split) {
        const auto at = list.find(name);
        const std::vector<Piece> parts = splitPiece(*at);
        const auto index = at - list.pieces().begin();
        list.pieces().erase(at);
        list.pieces().insert(list.pieces().begin() + index, parts.begin(), parts.end());
    }
}

void runPieces(const PiecesOptions& o)
{
    AtomicFile::checkTarget(o.output);
    checkMeshOutput(o.mesh);
    VdbPieces document = readVdbPieces(o.input);
    for (const std::string& warning : document.warnings) std::cerr << "sculpt: warning: " << warning << "\n";
    PieceList list(std::move(document.pieces), o.input);
    for (const std::string& file : o.add)
        for (Piece& piece : readVdbPieces(file).pieces) list.add(std::move(piece));
    relabel(list, o);
    reshape(list, o);
    for (const std::string& name : o.remove) list.pieces().erase(list.find(name));
    if (list.pieces().empty()) throw InputError(o.input + ": deleting every piece would leave nothing to save");
    writeVdbPieces(list.pieces(), o.output, document.companions);
    CommandReport report("pieces", o.run);
    report.wrote(o.output, "document");
    report.say("wrote " + o.output + ": " + std::to_string(list.pieces().size()) + " pieces");
    report["pieces"] = nlohmann::json::array();
    for (const Piece& piece : list.pieces()) {
        const FieldMeasures m = measureField(piece.field);
        report["pieces"].push_back(
            {{"name", piece.name}, {"volume", m.volume}, {"components", m.components}, {"visible", piece.visible}});
        std::ostringstream line;
        line << "  '" << piece.name << "': volume " << m.volume << ", " << m.components << " components"
             << (piece.visible ? "" : ", hidden");
        report.say(line.str());
    }
    writePiecesMeshes(list.pieces(), o.mesh, report);
    report.print();
}

}  // namespace

void addPiecesCommand(CLI::App& app)
{
    auto o = std::make_shared<PiecesOptions>();
    CLI::App* cmd = app.add_subcommand(
        "pieces", "Change a document's pieces (parts that never blend; `sculpt info` lists them) and write\n"
                  "the result: in this order, add other documents' pieces, rename, colour, hide and show,\n"
                  "merge pairs into one (CSG union), split pieces into their solids, delete.");
    cmd->footer("Examples:\n  sculpt pieces atlas.vdb --rename 'label 3=thalamus' --delete 'label 7' -o edited.vdb");
    cmd->add_option("input", o->input, "the .vdb document")->required();
    cmd->add_option("--add", o->add, "a .vdb document whose pieces to add (a name taken gets a number)");
    cmd->add_option("--rename", o->rename, "OLD=NEW");
    cmd->add_option("--colour", o->colour, "NAME=#rrggbb");
    cmd->add_option("--hide", o->hide, "a piece to hide (kept, not drawn)");
    cmd->add_option("--show", o->show, "a hidden piece to show");
    cmd->add_option("--merge", o->merge, "A,B: B united into A (resampled onto A's voxels if they differ)");
    cmd->add_option("--split", o->split, "a piece to split into one piece per solid ('NAME 1', 'NAME 2', ...)");
    cmd->add_option("--delete", o->remove, "a piece to delete");
    cmd->add_option("-o,--output", o->output, "the .vdb document to write")->required();
    addMeshOutput(*cmd, o->mesh);
    addRunOptions(*cmd, o->run);
    cmd->callback([o] { runPieces(*o); });
}

}  // namespace sculpt::cli
