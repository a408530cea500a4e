#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the Debian packages of the build tree BUILD (cpack) into a temporary directory and checks
# what apt relies on: the runtime package declares the libraries its programs link (read by
# dpkg-shlibdeps), holds the programs, man pages, completions and desktop files under /usr, and
# its programs run once unpacked; the -dev package holds the CMake package and depends on the
# runtime one.   usage: package_test.sh BUILD
set -euo pipefail
build=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "package_test: $*" >&2; exit 1; }
cpack -B "$out" --config "$build/CPackConfig.cmake" >"$out/cpack.log" 2>&1 || { cat "$out/cpack.log"; fail "cpack"; }
runtime=$(ls "$out"/sculpt_*.deb) dev=$(ls "$out"/sculpt-dev_*.deb)
depends=$(dpkg-deb --field "$runtime" Depends)
for library in libopenvdb libvtk9 libgdcm libglfw3 libtbb libopenexr; do
  grep -q "$library" <<<"$depends" || fail "the runtime package does not depend on $library: $depends"
done
contents=$(dpkg-deb --contents "$runtime")
grep -q "python3 (>= " <<<"$depends" || fail "the runtime package does not depend on python3: $depends"
grep -q "dist-packages/sculpt.cpython" <<<"$(dpkg-deb --contents "$runtime")" || fail "no Python module in /usr/lib/python3/dist-packages"
for file in usr/bin/sculpt usr/bin/sculpt-ui usr/share/man/man1/sculpt.1 usr/share/bash-completion/completions/sculpt \
            usr/share/applications/io.github.volumetric_sculpt.SculptUi.desktop usr/share/mime/packages/sculpt.xml \
            usr/share/thumbnailers/sculpt.thumbnailer usr/share/doc/sculpt/LICENSE; do
  grep -q " \./$file\$" <<<"$contents" || fail "the runtime package holds no /$file"
done
grep -q "sculpt (= " <<<"$(dpkg-deb --field "$dev" Depends)" || fail "sculpt-dev does not depend on sculpt"
grep -q "usr/lib/cmake/sculpt/sculptConfig.cmake" <<<"$(dpkg-deb --contents "$dev")" || fail "sculpt-dev holds no CMake package"
dpkg-deb -x "$runtime" "$out/root"
[[ $("$out/root/usr/bin/sculpt" --version) == "sculpt "*" (git "*")" ]] || fail "the packaged sculpt does not run"
echo "package_test: $(basename "$runtime") and $(basename "$dev") declare their dependencies and hold their files"
