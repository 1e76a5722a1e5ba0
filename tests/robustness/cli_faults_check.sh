#!/usr/bin/env bash
# The command line never ends with a signal: a fault while a part is read or recognised, and
# parameter files that once overflowed the stack, give one "aeronc: error:" line and exit 1.
# Usage: cli_faults_check.sh AERONC_CLI NIST_DIR
set -u
cli=$1
nist=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

check() {  # name, exit code, stderr file, expected fragment
  local name=$1 code=$2 err=$3 want=$4
  if [ "$code" -eq 1 ] && [ "$(wc -l <"$err")" -eq 1 ] && grep -q "^aeronc: error: .*$want" "$err"; then
    passed=$((passed + 1)); echo "ok   $name"
  else
    failed=$((failed + 1)); echo "FAIL $name (exit $code): $(cat "$err")"
  fi
}

# A fault the OCCT handlers do not take (SIGABRT, as std::terminate in a worker thread would
# raise) ends the child reading the part; the command still reports it in one line.
part="$nist/nist_ctc_02_asme1_ap203.stp"
"$cli" recognise "$part" --json "$tmp/out.json" 2>"$tmp/err" &
parent=$!
child=""
for _ in $(seq 100); do child=$(pgrep -P "$parent" || true); [ -n "$child" ] && break; sleep 0.05; done
if [ -n "$child" ]; then
  sleep 0.5
  kill -ABRT "$child"
  wait "$parent"
  check "a fault in the process reading the part" $? "$tmp/err" "signal 6"
  [ -e "$tmp/out.json" ] && { failed=$((failed + 1)); echo "FAIL a partial JSON was written"; }
else
  failed=$((failed + 1)); echo "FAIL no child process reads the part"
  wait "$parent"
fi

# chain reads its part the same way: the fault ends the child, not the command.
"$cli" chain "$part" --kb "$tmp/kb.sqlite" --material 7050-T7451 --json "$tmp/chain.json" 2>"$tmp/err" &
parent=$!
child=""
for _ in $(seq 200); do child=$(pgrep -P "$parent" || true); [ -n "$child" ] && break; sleep 0.05; done
if [ -n "$child" ]; then
  sleep 0.5
  kill -ABRT "$child"
  wait "$parent"
  check "chain: a fault in the process reading the part" $? "$tmp/err" "signal 6"
  [ -e "$tmp/chain.json" ] && { failed=$((failed + 1)); echo "FAIL chain: a partial JSON was written"; }
else
  failed=$((failed + 1)); echo "FAIL chain: no child process reads the part"
  wait "$parent"
fi

# Parameter files: nested 100,000 deep (a stack overflow once), and exponents that overflow.
python3 -c "print('{\"cutter\": {\"diameter_mm\": ' + '[' * 100000 + ']' * 100000 + '}}')" >"$tmp/deep.json"
"$cli" optimise "$tmp/deep.json" >/dev/null 2>"$tmp/err"
check "optimise: JSON nested 100,000 deep" $? "$tmp/err" "nested deeper than 64 levels"
opt="$(dirname "$0")/../../resources/optimise/xa5032_face_mill_45_steel.json"
python3 -c "
import json, sys
j = json.load(open(sys.argv[1])); j['tool_life']['q_v'] = -9.2e18
json.dump(j, open(sys.argv[2], 'w'))" "$opt" "$tmp/q_v.json"
"$cli" optimise "$tmp/q_v.json" --method ga >/dev/null 2>"$tmp/err"
check "optimise: q_v = -9.2e18" $? "$tmp/err" "search box"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
