#!/usr/bin/env bash
# AeroNC developer entry point. Each command first installs the Debian packages (once),
# configures a Release build in build/ (once), builds what changed and installs the addon
# into build/stage/AeroNC.
#
#   scripts/run.sh demo      the main job on the embedded sample part -> out/demo/
#   scripts/run.sh corpus    the main job on every STEP part of ../shared/data -> out/corpus/summary.md
#                            and .json (AERONC_CELL: the verification's cell, default 1.0 mm; extra
#                            arguments go to scripts/corpus.py, e.g. --parts milled_004 --mfcad)
#   scripts/run.sh post      the 5-axis posts on the sample panel -> out/post/
#   scripts/run.sh drill     datum holes and compensated drilling of a generated wing skin -> out/drill/
#   scripts/run.sh impeller  a generated 2 x 9 impeller programmed in FreeCAD -> out/impeller/:
#                            document, 840D program, report.html with pictures (docs/impeller.md)
#   scripts/run.sh test      every test: C++ unit tests, freecadcmd tests, GUI test under
#                            Xvfb, FreeCAD's own Path suite with the addon installed
#   scripts/run.sh bench     the benchmarks (figures on stdout)
#   scripts/run.sh install   install the addon into your FreeCAD Mod folder ($HOME/.local/share/FreeCAD/Mod,
#                            or AERONC_MOD_DIR)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=$ROOT/build
STAGE=$BUILD/stage

bash scripts/setup-debian.sh
if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD" -j "$(nproc)"
rm -rf "$STAGE/AeroNC"  # afresh: a module moved or removed in the source must not linger here
cmake --install "$BUILD" --prefix "$STAGE" > /dev/null

# FreeCAD run with a private HOME so nothing touches the user's settings.
fc_home() {
  local home=$BUILD/home-$1
  mkdir -p "$home/.local/share/FreeCAD/Mod" "$home/.config/FreeCAD"
  ln -sfn "$STAGE/AeroNC" "$home/.local/share/FreeCAD/Mod/AeroNC"
  echo "$home"
}

case "${1:-}" in
  demo)
    out=$ROOT/out/demo
    mkdir -p "$out"
    # FreeCAD's start-up banner is not the job's; the job's own log follows it.
    HOME=$(fc_home demo) AERONC_OUT=$out freecadcmd "$ROOT/scripts/demo.py" 2>&1 |
      awk '!/^(FreeCAD [0-9]|\(c\) Juergen|FreeCAD is free|FreeCAD wouldn.t be possible)/ && !/^[# ]+$/'
    ;;
  corpus)
    shift
    HOME=$(fc_home corpus) python3 "$ROOT/scripts/corpus.py" --out "$ROOT/out/corpus" \
      --cell "${AERONC_CELL:-1.0}" "$@"
    ;;
  post)
    out=$ROOT/out/post
    mkdir -p "$out"
    HOME=$(fc_home post) AERONC_OUT=$out freecadcmd "$ROOT/scripts/post_sample.py"
    ;;
  drill)
    out=$ROOT/out/drill
    mkdir -p "$out"
    HOME=$(fc_home drill) AERONC_OUT=$out freecadcmd "$ROOT/scripts/drill.py" 2>&1 |
      awk '!/^(FreeCAD [0-9]|\(c\) Juergen|FreeCAD is free|FreeCAD wouldn.t be possible)/ && !/^[# ]+$/'
    ;;
  impeller)
    out=$ROOT/out/impeller
    mkdir -p "$out"
    # AERONC_IMPELLER_SPEC, AERONC_ALLOWANCE, AERONC_STATIONS, AERONC_CHANNELS change the run.
    HOME=$(fc_home impeller) AERONC_OUT=$out freecadcmd "$ROOT/scripts/impeller.py" 2>&1 |
      awk '!/^(FreeCAD [0-9]|\(c\) Juergen|FreeCAD is free|FreeCAD wouldn.t be possible)/ && !/^[# ]+$/'
    ;;
  test)
    ctest --test-dir "$BUILD" --output-on-failure
    ;;
  bench)
    cmake --build "$BUILD" --target bench
    ;;
  install)
    # Into the FreeCAD of the HOME it runs under (the prefix configured with the build is not
    # used: it is the configuring user's), or into AERONC_MOD_DIR when given.
    dest=${AERONC_MOD_DIR:-$HOME/.local/share/FreeCAD/Mod}
    rm -rf "$dest/AeroNC"  # afresh, as the stage: nothing of an older install lingers
    cmake --install "$BUILD" --component addon --prefix "$dest" > /dev/null  # without the tests
    echo "AeroNC installed into $dest/AeroNC; start FreeCAD and switch to the Path workbench"
    ;;
  *)
    echo "usage: scripts/run.sh demo|corpus|drill|post|impeller|test|bench|install" >&2
    exit 2
    ;;
esac
