#!/usr/bin/env bash
# Checks the dependency rules of ARCHITECTURE.md on the includes (a CTest entry runs this): each
# folder of core/ includes only the folders it may use, core/ nothing of sculpt/ or ui/, only
# core/scan and core/io reach VTK, the session nothing of the command line; in ui/ each folder
# includes only the ui/ folders it may use, nothing of the command line, and VTK, ImGui and GLFW
# stay in the folders that own them.
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A allowed=(
  [base]=""
  [field]="base"
  [local]="base field"
  [motion]="base field local"
  [mesh]="base field"
  [primitives]="base field"
  [brushes]="base field local motion primitives"
  [scan]="base field io"
  [render]="base field"
  [io]="base field mesh render"
)
declare -A uiAllowed=(
  [input]=""
  [window]="input"
  [view]=""
  [document]=""
  [sculpting]="view document input"
  [panels]="app"
  [app]="app document input panels sculpting view window"
)
failures=0
fail() { echo "check-layers: $*"; failures=$((failures + 1)); }

for folder in core/*/; do
  layer=$(basename "$folder")
  [[ -v allowed[$layer] ]] || { fail "core/$layer is not a layer of ARCHITECTURE.md"; continue; }
  while IFS=: read -r file used; do
    [[ $used == "$layer" || " ${allowed[$layer]} " == *" $used "* ]] || fail "$file includes core/$used/"
  done < <(grep -roE '#include "core/[a-z_]+/' "$folder" | sed -E 's#:\#include "core/([a-z_]+)/#:\1#')
done
grep -rlE '#include "(sculpt|ui)/' core && fail "core/ includes sculpt/ or ui/"
grep -rlE '#include <vtk' core | grep -vE '^core/(scan|io)/' && fail "VTK included outside core/scan and core/io"
grep -rlE '#include ("sculpt/cli/|"ui/|<CLI/)' sculpt/session && fail "the session includes the command line or the UI"
for folder in ui/*/; do
  part=$(basename "$folder")
  [[ -v uiAllowed[$part] ]] || { fail "ui/$part is not a part of ui/ in ARCHITECTURE.md"; continue; }
  while IFS=: read -r file used; do
    [[ $used == "$part" || " ${uiAllowed[$part]} " == *" $used "* ]] || fail "$file includes ui/$used/"
  done < <(grep -roE '#include "ui/[a-z_]+/' "$folder" | sed -E 's#:\#include "ui/([a-z_]+)/#:\1#')
done
grep -rlE '#include "sculpt/cli/' ui && fail "ui/ includes the command line"
grep -rlE '#include <vtk' ui | grep -vE '^ui/(view|app)/' && fail "VTK included outside ui/view and ui/app"
grep -rlE '#include <(imgui|backends/)' ui | grep -vE '^ui/(panels|app|input)/' && fail "ImGui outside ui/panels, ui/input, ui/app"
grep -rlE '#include <GLFW' ui | grep -vE '^ui/(window|input|app|panels)/' && fail "GLFW outside ui/window, ui/input, ui/app, ui/panels"
if ((failures > 0)); then exit 1; fi
echo "check-layers: every include follows ARCHITECTURE.md"
