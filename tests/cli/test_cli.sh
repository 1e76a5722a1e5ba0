#!/usr/bin/env bash
# The command line on bad input: a clear message on stderr and a non-zero exit, never a crash.
# Usage: test_cli.sh AERONC_CLI
set -u
cli=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

expect_error() {  # name, expected message fragment, command...
  local name=$1 want=$2
  shift 2
  local err code
  err=$("$@" 2>&1 >/dev/null)
  code=$?
  if [ "$code" -ne 0 ] && [ "$code" -lt 128 ] && grep -q -- "$want" <<<"$err"; then
    passed=$((passed + 1)); echo "ok   $name"
  else
    failed=$((failed + 1)); echo "FAIL $name (exit $code): $err"
  fi
}

echo "just some text" > "$tmp/notes.step"
: > "$tmp/empty.step"
printf 'ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=GARBAGE(;\nENDSEC;\nEND-ISO-10303-21;\n' > "$tmp/broken.step"

expect_error "text file" "not a STEP" "$cli" recognise "$tmp/notes.step"
expect_error "empty file" "empty" "$cli" recognise "$tmp/empty.step"
expect_error "missing file" "no such file" "$cli" recognise "$tmp/none.step"
expect_error "broken STEP" "STEP" "$cli" recognise "$tmp/broken.step"
expect_error "unknown option" "unknown option" "$cli" recognise "$tmp/empty.step" --frobnicate
expect_error "bad direction" "bad direction" "$cli" recognise "$tmp/notes.step" --directions 1:2
expect_error "unknown command" "unknown command" "$cli" explode

# A good part still works and writes JSON.
"$cli" panel "$tmp/p.step" --pockets 2x1 --plain 2>/dev/null
if "$cli" recognise "$tmp/p.step" --directions +Z --json "$tmp/p.json" 2>/dev/null && grep -q '"closed_pocket"' "$tmp/p.json"; then
  passed=$((passed + 1)); echo "ok   good part"
else
  failed=$((failed + 1)); echo "FAIL good part"
fi
expect_error "no face normal to direction" "no planar face normal" "$cli" recognise "$tmp/p.step" --directions 1:1:0

# Tool selection: an unknown material is refused, a good part gets tools and JSON.
expect_error "select-tools unknown material" "material" "$cli" select-tools "$tmp/p.step" --kb "$tmp/kb.sqlite" --material unobtainium
if "$cli" select-tools "$tmp/p.step" --kb "$tmp/kb.sqlite" --material 7050-T7451 --directions +Z --json "$tmp/tools.json" 2>/dev/null &&
   grep -q '"roughingTool"' "$tmp/tools.json" && [ -s "$tmp/kb.sqlite" ]; then
  passed=$((passed + 1)); echo "ok   select-tools writes JSON"
else
  failed=$((failed + 1)); echo "FAIL select-tools writes JSON"
fi

# Tool selection from a stored recognition: the same plan as from the part, bad trees refused.
"$cli" recognise "$tmp/p.step" --directions +Z --json "$tmp/tree.json" 2>/dev/null
if "$cli" select-tools --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 --json "$tmp/tree_tools.json" 2>/dev/null &&
   grep -q '"roughingTool"' "$tmp/tree_tools.json" && cmp -s "$tmp/tools.json" "$tmp/tree_tools.json"; then
  passed=$((passed + 1)); echo "ok   select-tools --tree plans as the part form does"
else
  failed=$((failed + 1)); echo "FAIL select-tools --tree plans as the part form does"
fi
echo '{"faceCount": 2}' > "$tmp/short.json"
sed 's/"type": "closed_pocket"/"type": "slot"/' "$tmp/tree.json" > "$tmp/slot.json"
expect_error "select-tools --tree without a file" "--tree needs a value" "$cli" select-tools --tree
expect_error "select-tools --tree missing file" "cannot be read" "$cli" select-tools --tree "$tmp/none.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools --tree not JSON" "not valid JSON" "$cli" select-tools --tree "$tmp/notes.step" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools --tree missing field" "missing field 'setups'" "$cli" select-tools --tree "$tmp/short.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools --tree unknown type" "elements\[0\].type: unknown element type 'slot'" "$cli" select-tools --tree "$tmp/slot.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools --tree with directions" "a --tree has its setups" "$cli" select-tools --tree "$tmp/tree.json" --directions +Z --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools --tree unknown material" "unknown workpiece material" "$cli" select-tools --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material unobtainium

# The machining chain: the part and the stored tree give the same chain; bad input is named.
if "$cli" chain "$tmp/p.step" --directions +Z --kb "$tmp/kb.sqlite" --material 7050-T7451 --json "$tmp/chain.json" 2>/dev/null &&
   grep -q '"operation": "pocket"' "$tmp/chain.json" &&
   "$cli" chain --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 --json "$tmp/tree_chain.json" 2>/dev/null &&
   cmp -s "$tmp/chain.json" "$tmp/tree_chain.json"; then
  passed=$((passed + 1)); echo "ok   chain writes JSON, the same from the part and the tree"
else
  failed=$((failed + 1)); echo "FAIL chain writes JSON, the same from the part and the tree"
fi
# chain reads a part as the other commands do (a child process the OCCT fault guard and
# --time-limit watch), and takes the tool plan select-tools wrote (--tool-plan) as it is.
if "$cli" chain "$tmp/p.step" --directions +Z --kb "$tmp/kb.sqlite" --material 7050-T7451 --time-limit 60 \
     --json "$tmp/chain_limit.json" 2>/dev/null && cmp -s "$tmp/chain.json" "$tmp/chain_limit.json"; then
  passed=$((passed + 1)); echo "ok   chain PART --time-limit"
else
  failed=$((failed + 1)); echo "FAIL chain PART --time-limit"
fi
if "$cli" chain --tree "$tmp/tree.json" --tool-plan "$tmp/tree_tools.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 \
     --json "$tmp/plan_chain.json" 2>/dev/null && cmp -s "$tmp/tree_chain.json" "$tmp/plan_chain.json"; then
  passed=$((passed + 1)); echo "ok   chain --tool-plan takes select-tools' plan"
else
  failed=$((failed + 1)); echo "FAIL chain --tool-plan takes select-tools' plan"
fi
expect_error "chain --tool-plan of another material" "the tool plan was made for '7050-T7451', not '2024-T351'" \
  "$cli" chain --tree "$tmp/tree.json" --tool-plan "$tmp/tree_tools.json" --kb "$tmp/kb.sqlite" --material 2024-T351
expect_error "chain --tool-plan missing file" "tool plan $tmp/none.json cannot be read" \
  "$cli" chain --tree "$tmp/tree.json" --tool-plan "$tmp/none.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools has no --tool-plan" "unknown option --tool-plan" \
  "$cli" select-tools --tree "$tmp/tree.json" --tool-plan "$tmp/tree_tools.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
expect_error "select-tools unknown machine" "unknown machine 'Lathe'" \
  "$cli" select-tools --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 --machine Lathe
expect_error "chain unknown family" "no process template or part family 'impeller'" "$cli" chain --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 --family impeller
expect_error "chain unknown machine" "unknown machine" "$cli" chain --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite" --material 7050-T7451 --machine Lathe
expect_error "chain without material" "chain needs --material" "$cli" chain --tree "$tmp/tree.json" --kb "$tmp/kb.sqlite"
expect_error "chain --tree missing field" "missing field 'setups'" "$cli" chain --tree "$tmp/short.json" --kb "$tmp/kb.sqlite" --material 7050-T7451
python3 -c 'import json, sys
t = json.load(open(sys.argv[1]))
t["elements"] = []
t["faceElement"] = [-1] * len(t["faceElement"])
for s in t["setups"]: s["elements"] = []
json.dump(t, open(sys.argv[2], "w"))' "$tmp/tree.json" "$tmp/bare.json"
expect_error "chain of a tree with no element" "no domain element" "$cli" chain --tree "$tmp/bare.json" --kb "$tmp/kb.sqlite" --material 7050-T7451

# Cutting-parameter optimisation: the paper's example solves; bad parameter files are refused.
opt="$(dirname "$0")/../../resources/optimise/xa5032_face_mill_45_steel.json"
if "$cli" optimise "$opt" --method both --json "$tmp/opt.json" >/dev/null 2>&1 &&
   grep -q '"active"' "$tmp/opt.json" && grep -q '"genetic"' "$tmp/opt.json"; then
  passed=$((passed + 1)); echo "ok   optimise writes JSON"
else
  failed=$((failed + 1)); echo "FAIL optimise writes JSON"
fi
sed 's/"C_F": 825, //' "$opt" > "$tmp/no_cf.json"
expect_error "optimise missing coefficient" "force.C_F" "$cli" optimise "$tmp/no_cf.json"
sed 's/"power_kw": 7.5/"power_kw": 0.01/' "$opt" > "$tmp/weak.json"
expect_error "optimise infeasible" "raise P_max from 0.01 to" "$cli" optimise "$tmp/weak.json"
sed 's/"diameter_mm": 125/"diameter_mm": 0/' "$opt" > "$tmp/flat.json"
expect_error "optimise non-physical" "cutter diameter d_0 must be positive" "$cli" optimise "$tmp/flat.json"
expect_error "optimise bad method" "nlopt, ga or both" "$cli" optimise "$opt" --method simplex

# Impellers: a generated one is recognised as its truth says; no impeller, a bad spec refused.
"$cli" impeller-part "$tmp/imp.brep" --spec '{"bladeCount": 4, "splitters": false}' --truth "$tmp/imp_truth.json" 2>/dev/null
if "$cli" impeller "$tmp/imp.brep" --json "$tmp/imp.json" 2>/dev/null &&
   python3 -c 'import json, sys
r, t = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert (r["hub"], r["bore"], r["bladeCount"], r["splitterCount"]) == (t["hub"], t["bore"], 4, 0)
assert sorted(b["shroud"] for b in r["blades"]) == sorted(b["shroud"] for b in t["blades"])
assert abs(r["dimensions"]["filletRadius"] - t["filletRadius"]) < 1e-3' "$tmp/imp.json" "$tmp/imp_truth.json"; then
  passed=$((passed + 1)); echo "ok   impeller recognised as generated"
else
  failed=$((failed + 1)); echo "FAIL impeller recognised as generated"
fi
# The whole impeller program on that part (one channel, a few stations): checked and posted.
if "$cli" impeller-program "$tmp/imp.brep" --kb "$tmp/kb.sqlite" --out "$tmp/prog" --stations 3 --channels 1 2>/dev/null &&
   grep -q "TRAORI" "$tmp/prog/IMPELLER.mpf" && grep -q "GOTO/" "$tmp/prog/IMPELLER.apt" &&
   python3 -c 'import json, sys
t = json.load(open(sys.argv[1]))["toolpaths"]
assert t["maxGougeMm"] <= 0.01 and t["holderCollisions"] == 0 and t["positionsChecked"] > 0, t' "$tmp/prog/impeller.json"; then
  passed=$((passed + 1)); echo "ok   impeller program checked and posted"
else
  failed=$((failed + 1)); echo "FAIL impeller program checked and posted"
fi
# The program cuts at the cutting data it reports: the optimiser's for the 5-axis tools (the same
# as Program impeller in FreeCAD), numbered in route order; the S and F words are those speeds.
if python3 -c 'import json, re, sys
d = json.load(open(sys.argv[1]))
cut = {c["tool"]: c for c in d["cutting"]}
rougher = d["toolpaths"]["rougher"]
c = cut[rougher["id"]]
assert c["active"] and c["active"] != ["knowledge base"], c
assert abs(c["rpm"] - rougher["rpm"]) < 1e-9 and abs(c["feed"] - rougher["feed"]) < 1e-9, (c, rougher)
text = open(sys.argv[2]).read()
tool = re.search(r"^T(\d+) D1 M6\nS(\d+)", text, re.M)
assert int(tool.group(1)) == rougher["number"], (tool.group(0), rougher)
assert int(tool.group(2)) == round(c["rpm"]), (tool.group(0), c["rpm"])
assert "F{:.3f}".format(c["feed"]) in text
assert d["machine"] == "AC-5AX"' "$tmp/prog/impeller.json" "$tmp/prog/IMPELLER.mpf"; then
  passed=$((passed + 1)); echo "ok   impeller program at the optimiser's cutting data"
else
  failed=$((failed + 1)); echo "FAIL impeller program at the optimiser's cutting data"
fi
# Another machine of the knowledge base, with its machine file; an unknown one is refused.
if "$cli" impeller-program "$tmp/imp.brep" --kb "$tmp/kb.sqlite" --out "$tmp/progL" --stations 3 --channels 1 \
     --machine AC-5AX-L 2>/dev/null && grep -q "for machine AC-5AX-L" "$tmp/progL/IMPELLER.mpf"; then
  passed=$((passed + 1)); echo "ok   impeller-program --machine"
else
  failed=$((failed + 1)); echo "FAIL impeller-program --machine"
fi
expect_error "impeller-program unknown machine" "unknown machine 'NO-MACHINE'" \
  "$cli" impeller-program "$tmp/imp.brep" --kb "$tmp/kb.sqlite" --out "$tmp/progX" --machine NO-MACHINE
expect_error "impeller-program without --kb" "needs --kb and --out" "$cli" impeller-program "$tmp/imp.brep" --out "$tmp/prog"
expect_error "impeller of a panel" "not an impeller: no rotational pattern" "$cli" impeller "$tmp/p.step"
expect_error "impeller-part unknown key" "unknown key blades" "$cli" impeller-part "$tmp/x.step" --spec '{"blades": 3}'
expect_error "impeller-part bad JSON" "not valid JSON" "$cli" impeller-part "$tmp/x.step" --spec '{blades'
expect_error "impeller-part impossible" "blade count must be 3 to 40" "$cli" impeller-part "$tmp/x.step" --spec '{"bladeCount": 2}'

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
