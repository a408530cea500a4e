#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
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
  mapfile -t commands < <("$prefix/bin/sculpt" --help | sed -n '/^Subcommands:/,$p' | grep -oE '^  [a-z][a-z-]*' | tr -d ' ')
  ((${#commands[@]} >= 14)) || fail "sculpt --help lists ${#commands[@]} commands"
  for command in "${commands[@]}"; do
    grep -q "sculpt $command" <<<"$page" || fail "man sculpt says nothing of 'sculpt $command'"
  done
fi
# Desktop integration: the launcher and the AppStream entry pass their validators, the icon is
# there in every size, the MIME type recognises a document by its content, and the thumbnailer's
# command (as a file manager runs it) writes a PNG of the size asked.
id=io.github.volumetric_sculpt.SculptUi
desktop-file-validate "$prefix/share/applications/$id.desktop" || fail "desktop-file-validate"
appstreamcli validate --no-net "$prefix/share/metainfo/$id.metainfo.xml" >/dev/null || fail "appstreamcli validate"
for size in 48 64 128 256; do
  [[ -f $prefix/share/icons/hicolor/${size}x$size/apps/$id.png ]] || fail "no ${size}px icon"
done
mkdir -p "$prefix/xdg/mime/packages"
cp "$prefix/share/mime/packages/sculpt.xml" "$prefix/xdg/mime/packages/"
update-mime-database "$prefix/xdg/mime" >/dev/null 2>&1 || fail "update-mime-database"
grep -q "application/x-openvdb:\*.vdb" "$prefix/xdg/mime/globs2" || fail "no *.vdb glob"
grep -q "application/x-openvdb" "$prefix/xdg/mime/magic" || fail "no OpenVDB magic"
exec_line=$(sed -n 's/^Exec=//p' "$prefix/share/thumbnailers/sculpt.thumbnailer")
exec_line=${exec_line//%i/$prefix/ball.vdb}
exec_line=${exec_line//%o/$prefix/thumbnail.png}
exec_line=${exec_line//%s/128}
(PATH="$prefix/bin:$PATH" && eval "$exec_line") || fail "the thumbnailer's command: $exec_line"
[[ $(od -An -tx1 -N8 "$prefix/thumbnail.png" | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "the thumbnail is no PNG"
[[ $(od -An -tu4 --endian=big -j16 -N8 "$prefix/thumbnail.png" | xargs) == "128 128" ]] || fail "the thumbnail is not 128 x 128"

# The Python module imports from where it was installed.
python=$(find "$prefix/lib" -name "sculpt.cpython-*.so" | head -n 1)
[[ -n $python ]] || fail "the Python module is not installed"
PYTHONPATH=$(dirname "$python") /usr/bin/python3 -c "import sculpt; assert sculpt.new(radius=3).info()['euler_characteristic'] == 2" \
  || fail "import sculpt from the install"

# Another program finds the installed libraries with find_package(sculpt) and links sculpt::core.
cmake -S "$(dirname "$0")/consumer" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release >"$prefix/consumer.log" 2>&1 || { cat "$prefix/consumer.log"; fail "find_package(sculpt)"; }
cmake --build "$prefix/consumer" >>"$prefix/consumer.log" 2>&1 || { cat "$prefix/consumer.log"; fail "building against sculpt::core"; }
"$prefix/consumer/consumer" "$prefix/consumer-ball.vdb" || fail "the consumer's ball"
"$prefix/bin/sculpt" info "$prefix/consumer-ball.vdb" >/dev/null || fail "sculpt info of the consumer's document"
echo "install_test: programs, man pages, completions, desktop files, data, libraries and the CMake package installed into a prefix and used from it"
