#!/usr/bin/env bash
# Installs every Debian package Padrob needs to build, run and test.
# One list, shared by scripts/run.sh and scripts/test.sh, and the locale es_CL.UTF-8 the
# tests use. Idempotent: when every package is already installed and the locale exists it
# prints nothing and touches nothing.
#
# We install with --no-install-recommends. What that drops, and why it is fine:
#   - qt6-base-dev only *recommends* libqt6opengl6-dev and the SQLite driver;
#     the ones we use are listed explicitly below.
#   - Recommends would add ghostscript, GTK, a platform theme and udev (~400 MB)
#     that a build or a headless test never uses.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git ccache
  # solver
  libeigen3-dev
  # SUNDIALS 6.4 (ARKODE, CVODE). Heavy: it hard-depends on ~315 MB of MPI, PETSc,
  # hypre, Trilinos, MUMPS, gfortran and HDF5 that we never use. If install time
  # matters, build SUNDIALS from source instead (serial only: ARKODE, CVODE, dense).
  libsundials-dev
  # assimp 5.2 (mesh files for graphics and the inertia calculator)
  libassimp-dev
  # FCL 0.7 (clearances between the machine and the scene)
  libfcl-dev
  # Qt (the CLI's QtCore now; widgets, Linguist tools and translations for the apps)
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  # padrob-studio: OpenGL widgets (only recommended by qt6-base-dev), charts, the xcb
  # platform plugin, Mesa's software GL, fonts
  libqt6opengl6-dev qt6-charts-dev libqt6sql6-sqlite qt6-qpa-plugins libgl1-mesa-dri fonts-dejavu-core
  # the station: joysticks and gamepads (SDL2), the serial DAQ box, Comedi DAQ cards
  # (optional at build time; installed so CI builds and tests that back end too)
  libsdl2-dev qt6-serialport-dev libcomedi-dev
  # padrob bench's side-by-side comparison with MuJoCo (optional at build time;
  # installed so CI builds and runs it; its CMake config needs qhull's headers)
  libmujoco-dev libqhull-dev
  # GUI tests: a virtual X server (QOpenGLWidget needs xcb, not `offscreen`)
  xvfb xauth
  # trainee records on PostgreSQL: Qt's driver, and the server programs (initdb, pg_ctl) that
  # trainer_tests start a throwaway server with (about 1 s; its default cluster is not used)
  libqt6sql6-psql postgresql
  # the training centre (optional at build time; installed so CI builds and tests it):
  # Eclipse Cyclone DDS and its IDL compiler (idlc, in cyclonedds-tools)
  cyclonedds-dev cyclonedds-tools
  # its DDS Security PKI (padrob centre pki) is made with OpenSSL's libcrypto: its headers
  libssl-dev
  # padrob-studio's View ▸ Record Video: the ffmpeg program encodes the 3D view's frames
  # (its ffprobe checks the videos in the tests)
  ffmpeg
  # tests
  libgtest-dev libgmock-dev libbenchmark-dev locales
  # Qt's own texts in Spanish (the buttons of standard dialogs, context menus, --help)
  qt6-translations-l10n
  # the Debian package (scripts/test-package.sh): cpack's DEB generator reads the
  # binaries' library dependencies with dpkg-shlibdeps (dpkg-dev) and file
  dpkg-dev file
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = installed ] || missing+=("$p")
done

# es_CL.UTF-8, the Spanish (Chile) locale: tests run padrob and the model parser under it
# (a decimal comma) to check that model files and numbers keep the '.'. The `locales`
# package above ships its definition but generates no locale.
has_es_cl() { locale -a 2>/dev/null | grep -qiE '^es_CL\.utf-?8$'; }
need_locale=0
has_es_cl || need_locale=1

[ ${#missing[@]} -eq 0 ] && [ $need_locale -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  what="${missing[*]}"
  [ $need_locale -eq 0 ] || what="${what:+$what and }the locale es_CL.UTF-8"
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install $what" >&2; exit 1; }
  sudo=sudo
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq -o DPkg::Lock::Timeout=600
  $sudo apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=600 "${missing[@]}" >/dev/null
fi
if ! has_es_cl; then
  echo "install-deps: generating the locale es_CL.UTF-8" >&2
  $sudo localedef -i es_CL -f UTF-8 es_CL.UTF-8
fi
