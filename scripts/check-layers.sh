#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks the dependency rules of ARCHITECTURE.md on the includes (a CTest entry runs this): each
# folder of core/ includes only the folders it may use, core/ nothing of sculpt/ or ui/, only
# core/scan and core/io reach VTK, the session nothing of the command line; in ui/ each folder
# includes only the ui/ folders it may use (nothing below ui/app includes it: panels, modes and
# tools see the window through their hosts), nothing of the command line, and VTK, ImGui and GLFW
# stay in the folders that own them.
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A allowed=(
  [base]=""
  [field]="base"
  [local]="base field"
  [motion]="base field local mesh"
  [tracking]="base field mesh motion"
  [pieces]="base field mesh"
  [mesh]="base field"
  [primitives]="base field"
  [masks]="base field local solids"
  [solids]="base field local mesh primitives"
  [brushes]="base field local masks motion primitives"
  [scan]="base field io"
  [render]="base field"
  [io]="base field mesh render"
)
declare -A uiAllowed=(
  [input]=""
  [commands]="input"
  [window]="input"
  [view]=""
  [document]=""
  [jobs]=""
  [status]="view"
  [sculpting]="view document input"
  [workspace]="commands document input jobs status"
  [files]="commands document jobs status workspace"
  [scene]="document input sculpting view"
  [tools]="commands document input jobs scene sculpting status view workspace"
  [panels]="commands document files input jobs scene sculpting status tools view workspace"
  [modes]="commands document files input jobs panels scene sculpting status tools view workspace"
  [app]="app commands document files input jobs modes panels scene sculpting status tools view window workspace"
)
failures=0
fail() { echo "check-layers: $*"; failures=$((failures + 1)); }

# check_parts ROOT RULES: each folder of ROOT/ includes only ROOT/ folders its RULES entry lists.
check_parts() {
  local root=$1
  local -n rules=$2
  for folder in "$root"/*/; do
    local part
    part=$(basename "$folder")
    [[ -v rules[$part] ]] || { fail "$root/$part is not in ARCHITECTURE.md"; continue; }
    while IFS=: read -r file used; do
      [[ $used == "$part" || " ${rules[$part]} " == *" $used "* ]] || fail "$file includes $root/$used/"
    done < <(grep -roE "#include \"$root/[a-z_]+/" "$folder" | sed -E "s#:\#include \"$root/([a-z_]+)/#:\1#")
  done
}

check_parts core allowed
check_parts ui uiAllowed
grep -rlE '#include "(sculpt|ui)/' core && fail "core/ includes sculpt/ or ui/"
grep -rlE '#include <vtk' core | grep -vE '^core/(scan|io)/' && fail "VTK included outside core/scan and core/io"
grep -rlE '#include ("sculpt/cli/|"ui/|<CLI/)' sculpt/session && fail "the session includes the command line or the UI"
grep -rlE '#include "sculpt/cli/' ui && fail "ui/ includes the command line"
grep -rlE '#include <vtk' ui | grep -vE '^ui/(view|app)/' && fail "VTK included outside ui/view and ui/app"
grep -rlE '#include <(imgui|backends/)' ui | grep -vE '^ui/(panels|modes|tools|app|input)/' &&
  fail "ImGui outside ui/panels, ui/modes, ui/tools, ui/input, ui/app"
# GLFW's key codes name the commands' keys where they are registered.
grep -rlE '#include <GLFW' ui | grep -vE '^ui/(window|input|app|panels|modes|tools|workspace)/' &&
  fail "GLFW outside ui/window, ui/input, ui/app and where commands are registered"
if ((failures > 0)); then exit 1; fi
echo "check-layers: every include follows ARCHITECTURE.md"
