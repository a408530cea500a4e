#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Makes PROGRAM's man page with help2man from its --help and --version, with a COMMANDS section
# holding the own --help of each command its --help lists (so a new command is in it at once).
# usage: man_page.sh PROGRAM OUTPUT SUMMARY
set -euo pipefail
program=$1 output=$2 summary=$3
mapfile -t commands < <("$program" --help | sed -n '/^Subcommands:/,$p' | grep -oE '^  [a-z][a-z-]*' | tr -d ' ')
set -- "${commands[@]}"
include=$(mktemp)
trap 'rm -f "$include"' EXIT
includes=()
if (($# > 0)); then
  includes=(--include="$include")
  echo "[COMMANDS]" >"$include"
  for command in "$@"; do
    echo ".SS \"$(basename "$program") $command\""
    echo ".nf"
    # roff: a backslash is \e; a line starting with a dot or a quote would be a request.
    "$program" "$command" --help | sed -e 's/\\/\\e/g' -e "s/^\([.']\)/\\\\\&\1/"
    echo ".fi"
  done >>"$include"
fi
help2man --no-info --no-discard-stderr --name="$summary" "${includes[@]}" --output="$output" "$program"
