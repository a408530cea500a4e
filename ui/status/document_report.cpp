// SPDX-License-Identifier: Apache-2.0
#include "ui/status/document_report.h"

#include "core/field/grid_checksum.h"
#include "sculpt/session/document.h"

#include <nlohmann/json.hpp>

namespace sculpt::ui {

void reportDocument(nlohmann::json& out, const Document& document)
{
    const FieldImage& field = document.session().field();
    out["checksum"] = formatChecksum(gridChecksum(field.grid()));
    out["mask_checksum"] = field.mask() ? formatChecksum(gridChecksum(*field.mask())) : std::string();
    out["modified"] = document.modified();
    out["title"] = document.title();
    out["path"] = document.path().string();
    out["undo"] = document.undoLabels().size();
    out["redo"] = document.redoLabels().size();
    out["active_piece"] = document.activePiece();
    out["pieces"] = nlohmann::json::array();
    for (const DocumentPiece& piece : document.pieces()) {
        const double* placement = piece.look.placement.asPointer();
        out["pieces"].push_back({{"name", piece.look.name},
                                 {"checksum", formatChecksum(gridChecksum(piece.session->field().grid()))},
                                 {"visible", piece.look.visible},
                                 {"placement", std::vector<double>(placement, placement + 16)}});
    }
}

}  // namespace sculpt::ui
