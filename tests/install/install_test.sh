#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix and checks what a packager relies on: the
# installed programs run from there (--version names the build), and the docs, licences, schemas
# and examples are where the GNU layout puts them.   usage: install_test.sh BUILD
set -euo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
fail() { echo "install_test: $*" >&2; exit 1; }
[[ $("$prefix/bin/sculpt" --version) == "sculpt "*" (git "*")" ]] || fail "installed sculpt --version"
[[ $("$prefix/bin/sculpt-ui" --version) == "sculpt-ui "*" (git "*")" ]] || fail "installed sculpt-ui --version"
"$prefix/bin/sculpt" new --radius 3 -o "$prefix/ball.vdb" >/dev/null || fail "installed sculpt new"
for file in share/doc/sculpt/LICENSE share/doc/sculpt/THIRD_PARTY_LICENSES share/doc/sculpt/README.md \
            share/sculpt/strokes.schema.json share/sculpt/reports.schema.json share/sculpt/examples/strokes/face.json; do
  [[ -f $prefix/$file ]] || fail "$file is not installed"
done
echo "install_test: programs, docs and data installed into a prefix and run from it"
