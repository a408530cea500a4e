#!/usr/bin/env bash
# Installs the build tree BUILD into a temporary prefix and checks what a packager relies on: the
# installed programs run from there (--version names the build), the docs, licences, schemas
# and examples are where the GNU layout puts them, and a small program builds against the
# installed CMake package.   usage: install_test.sh BUILD
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
            share/sculpt/strokes.schema.json share/sculpt/reports.schema.json share/sculpt/examples/strokes/face.json \
            share/man/man1/sculpt.1 share/man/man1/sculpt-ui.1 share/bash-completion/completions/sculpt \
            share/zsh/vendor-completions/_sculpt share/fish/vendor_completions.d/sculpt.fish; do
  [[ -f $prefix/$file ]] || fail "$file is not installed"
done
# The man page documents every command (help2man's COMMANDS section), as man shows it.
if command -v man >/dev/null; then
  page=$(MANWIDTH=100 man -l "$prefix/share/man/man1/sculpt.1" 2>/dev/null)
  for command in new info mesh smooth offset morph build apply import export-labels hollow islands pieces render; do
    grep -q "sculpt $command" <<<"$page" || fail "man sculpt says nothing of 'sculpt $command'"
  done
fi
# Another program finds the installed libraries with find_package(sculpt) and links sculpt::core.
cmake -S "$(dirname "$0")/consumer" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >"$prefix/consumer.log" 2>&1 || { cat "$prefix/consumer.log"; fail "find_package(sculpt)"; }
cmake --build "$prefix/consumer" >>"$prefix/consumer.log" 2>&1 || { cat "$prefix/consumer.log"; fail "building against sculpt::core"; }
"$prefix/consumer/consumer" "$prefix/consumer-ball.vdb" || fail "the consumer's ball"
"$prefix/bin/sculpt" info "$prefix/consumer-ball.vdb" >/dev/null || fail "sculpt info of the consumer's document"
echo "install_test: programs, docs, data, libraries and the CMake package installed into a prefix and used from it"
