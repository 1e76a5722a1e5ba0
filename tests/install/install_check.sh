#!/usr/bin/env bash
# `scripts/run.sh install` installs into the FreeCAD of the HOME it runs under (or AERONC_MOD_DIR),
# without the tests, and says where. Usage: install_check.sh SOURCE_DIR
set -uo pipefail
src=$1
fail=0
check() { if eval "$2"; then echo "PASS $1"; else echo "FAIL $1"; fail=1; fi; }
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
out=$(cd "$src" && env -u AERONC_MOD_DIR HOME="$home" scripts/run.sh install 2>&1)
mod=$home/.local/share/FreeCAD/Mod/AeroNC
check "installed into the given HOME" "[ -f '$mod/aeronc/__init__.py' ] && ls '$mod'/aeronc/_core*.so >/dev/null 2>&1"
check "with the commands, panels and posts" "[ -f '$mod/aeronc/commands/base.py' ] && [ -f '$mod/aeronc/panels/base.py' ] && [ -f '$mod/InitGui.py' ]"
check "without the tests" "[ ! -e '$mod/aeronc/tests' ]"
check "says where it went" "grep -q 'installed into $mod' <<< \"\$out\""
other=$home/elsewhere
out2=$(cd "$src" && HOME="$home" AERONC_MOD_DIR="$other" scripts/run.sh install 2>&1)
check "AERONC_MOD_DIR chooses the folder" "[ -f '$other/AeroNC/aeronc/__init__.py' ] && grep -q 'installed into $other/AeroNC' <<< \"\$out2\""
[ $fail -eq 0 ] && echo "install: all checks pass" || { echo "$out"; echo "$out2"; }
exit $fail
