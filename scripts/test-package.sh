#!/usr/bin/env bash
# The Debian package, tested as a trainer's PC would get it (docs/packaging.md):
#   1. cpack builds padrob_<version>_<arch>.deb from the build folder (default
#      build/default, already built); its Depends must name Debian's Qt, SUNDIALS and
#      Qt-plugin packages;
#   2. dpkg -x unpacks it into a temporary root (no root rights, the system untouched);
#      nothing in it may name the source tree (a path compiled into a program would),
#      and no library may be missing;
#   3. from a temporary working folder, with a fresh HOME: `padrob check` on every
#      installed model, `padrob tutorial` on the installed T0 with --demo, padrob-studio
#      --help and --version without a display (and --help in Spanish), and padrob-studio
#      on an X display (a virtual one when there is none) drawing its default model, the
#      installed liner manipulator, into a screenshot.
# Usage: scripts/test-package.sh [BUILD_DIR]
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd -P)
build=$(cd "${1:-$src/build/default}" && pwd -P)
cd "$src"
. scripts/start-xvfb.sh
work=$(mktemp -d /tmp/padrob-package.XXXXXX)
cleanup() {
  rm -rf "$work"
  [ -z "${xvfb_pid:-}" ] || kill "$xvfb_pid" 2>/dev/null || true
}
trap cleanup EXIT
fail() { echo "test-package: $*" >&2; exit 1; }

# 1. the package
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/cpack" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb=$(ls "$work"/cpack/padrob_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
for p in libqt6core6 libqt6widgets6 libqt6charts6 libqt6sql6 libsundials libassimp libfcl libsdl2 \
         libddsc0debian libssl3 qt6-qpa-plugins libqt6sql6-sqlite libqt6sql6-psql qt6-translations-l10n; do
  [[ "$depends" == *"$p"* ]] || fail "Depends lacks $p: $depends"
done

# 2. unpacked into a temporary root
root="$work/root"
dpkg -x "$deb" "$root"
bin="$root/usr/bin"
share="$root/usr/share/padrob"
for f in bin/padrob bin/padrob-studio share/padrob/models/liner_manipulator_fluid.pad \
         share/padrob/models/liner_manipulator.station/gamepad.json share/padrob/resources/tutorials/t0_reach.tut \
         share/padrob/resources/tutorials/t0_reach.demo.log share/padrob/resources/tutorials/t0_reach.demo.cam \
         share/padrob/resources/scenes/sag_mill.pad share/doc/padrob/model-language.md share/doc/padrob/LICENSE \
         share/applications/padrob-studio.desktop share/icons/hicolor/scalable/apps/padrob-studio.svg; do
  [ -f "$root/usr/$f" ] || fail "the package lacks /usr/$f"
done
# a program that could look in the source tree has its path compiled in: as bytes, or
# as UTF-16 (a QStringLiteral)
utf16=$(printf '%s' "$src" | od -An -tx1 -v | tr -d ' \n' | sed 's/../\\x&\\x00/g')
leaks=$( (grep -rlF -- "$src" "$root"; LC_ALL=C grep -rlaP -- "$utf16" "$root") || true)
[ -z "$leaks" ] || fail "these installed files name the source tree $src: ${leaks//$root/}"
missing=$(ldd "$bin/padrob" "$bin/padrob-studio" | grep "not found" || true)
[ -z "$missing" ] || fail "libraries not found: $missing"

# 3. the installed programs, run from elsewhere with a fresh HOME
mkdir -p "$work/run/home"
cd "$work/run"
export HOME="$work/run/home" XDG_CONFIG_HOME="$work/run/home/.config" XDG_DATA_HOME="$work/run/home/.local/share"
export LANG=C.UTF-8 LC_ALL=C.UTF-8
unset LANGUAGE
models=("$share"/models/*.pad)
"$bin/padrob" check "${models[@]}" >"$work/check.log" || { cat "$work/check.log" >&2; fail "padrob check failed"; }
"$bin/padrob" tutorial "$share/resources/tutorials/t0_reach.tut" --demo >"$work/t0.log" ||
  { cat "$work/t0.log" >&2; fail "padrob tutorial t0_reach.tut --demo did not pass"; }
grep -q "PASSED" "$work/t0.log" || { cat "$work/t0.log" >&2; fail "T0's demonstration did not pass"; }

# padrob-studio's texts need no display
version=$(env -u DISPLAY -u WAYLAND_DISPLAY "$bin/padrob-studio" --version) || fail "padrob-studio --version failed"
[[ "$version" == *"$(dpkg-deb -f "$deb" Version)"* ]] || fail "padrob-studio --version says '$version'"
env -u DISPLAY -u WAYLAND_DISPLAY "$bin/padrob-studio" --help >"$work/help.en" || fail "padrob-studio --help failed"
grep -q "^Usage: " "$work/help.en" || fail "padrob-studio --help: no usage line"
env -u DISPLAY -u WAYLAND_DISPLAY LC_ALL=es_CL.UTF-8 LANG=es_CL.UTF-8 "$bin/padrob-studio" --help >"$work/help.es" ||
  fail "padrob-studio --help in Spanish failed"
grep -q "^Uso: " "$work/help.es" || fail "padrob-studio --help under es_CL is not in Spanish"

# padrob-studio on the display: its default model is the installed liner manipulator
shot="$work/studio.png"
timeout 120 "$bin/padrob-studio" --screenshot "$shot" >"$work/studio.log" 2>"$work/studio.err" ||
  { cat "$work/studio.log" "$work/studio.err" >&2; fail "padrob-studio --screenshot failed"; }
grep -qF "$share/models/liner_manipulator_fluid.pad" "$work/studio.log" ||
  { cat "$work/studio.log" >&2; fail "padrob-studio did not draw the installed liner manipulator"; }
[ "$(stat -c %s "$shot")" -gt 20000 ] || fail "padrob-studio's screenshot is nearly empty"
[ -z "${PADROB_PACKAGE_SHOT:-}" ] || cp "$shot" "$PADROB_PACKAGE_SHOT"
echo "test-package: $(basename "$deb") installs and runs from $root (${#models[@]} models checked, T0 passed," \
     "padrob-studio drew the liner manipulator)"
