// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file commands.h
/// @brief The subcommands of the `sculpt` program. Each adds itself to the application with its
///        options, help text and the callback that runs it. Callbacks throw InputError for bad
///        input; main() turns exceptions into one line on stderr and the exit code.

namespace CLI {
class App;
}

namespace sculpt::cli {

/// `sculpt new`: a starting shape (sphere, box, torus) as a new document.
void addNewCommand(CLI::App& app);
/// `sculpt info`: measures of a document, as text or JSON.
void addInfoCommand(CLI::App& app);
/// `sculpt mesh`: export the surface as PLY, OBJ or STL.
void addMeshCommand(CLI::App& app);
/// `sculpt smooth`: mean-curvature smoothing, optionally keeping the volume.
void addSmoothCommand(CLI::App& app);
/// `sculpt offset`: move the surface along its normal.
void addOffsetCommand(CLI::App& app);
/// `sculpt morph`: frames of the source following the target.
void addMorphCommand(CLI::App& app);
/// `sculpt build`: bake a primitive scene, alone or into a base document.
void addBuildCommand(CLI::App& app);
/// `sculpt apply`: replay a stroke script on a document.
void addApplyCommand(CLI::App& app);
/// `sculpt import`: a scan or a mesh as a new document.
void addImportCommand(CLI::App& app);
/// `sculpt export-labels`: the pieces as a label map on a scan's lattice.
void addExportLabelsCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
/// `sculpt hollow`: a shell of a wall thickness, with drain holes.
void addHollowCommand(CLI::App& app);
/// `sculpt islands`: remove the small disjoint solids.
void addIslandsCommand(CLI::App& app);
/// `sculpt pieces`: add, rename, colour, hide, merge, split and delete a document's pieces.
void addPiecesCommand(CLI::App& app);

}  // namespace sculpt::cli
