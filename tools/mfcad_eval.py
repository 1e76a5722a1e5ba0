#!/usr/bin/env python3
"""Per-face agreement of AeroNC recognition with the MFCAD labels.

Usage: mfcad_eval.py AERONC_CLI MFCAD_DIR [--out report.md] [--min-binary F] [--min-class F]

With --min-binary/--min-class it exits 1 when the agreement falls below the given floor
(the test suite uses this to guard the measured figures).

Each part is recognised with `aeronc recognise PART --face-names`; faces are matched to
labels through their STEP entity names (see shared/data/README.md). Two mappings:

* binary: a face any element machines (floor, wall, fillet, chamfer, hole wall ...)
  is "feature"; top/stock faces are "stock" (label 15);
* class: the face's element type against the label family
    closed_pocket          <- triangular/rectangular/6sides_pocket (9, 10, 11)
    open_pocket            <- through/blind slots and steps (4-8, 12, 13, 14)
    opening, hole          <- passages (1, 2, 3)
    chamfer (face role)    <- chamfer (0)
    stock                  <- stock (15)

The label ids follow FeatureNet's feature order with its round features left out (0 chamfer,
1-3 triangular/rectangular/6-sided passage, 4-5 triangular/rectangular through slot, 6-8
rectangular/2-sided/slanted through step, 9-11 triangular/rectangular/6-sided pocket, 12
rectangular blind slot, 13-14 triangular/rectangular blind step, 15 stock): in the sample every
label 0 is one slanted face on an edge of the block, every label 11 seven faces, every label 1
three walls round a prism through the part (LABEL_NAMES below; docs/recognition.md has the count).
"""
import glob
import json
import os
import pickle
import subprocess
import sys
import tempfile

LABEL_NAMES = ["chamfer", "triangular_passage", "rectangular_passage", "6sides_passage", "triangular_through_slot",
               "rectangular_through_slot", "rectangular_through_step", "2sides_through_step", "slanted_through_step",
               "triangular_pocket", "rectangular_pocket", "6sides_pocket", "rectangular_blind_slot",
               "triangular_blind_step", "rectangular_blind_step", "stock"]
FAMILY = {9: "closed", 10: "closed", 11: "closed", 1: "through", 2: "through", 3: "through", 0: "chamfer",
          15: "stock"}
for k in (4, 5, 6, 7, 8, 12, 13, 14):
    FAMILY[k] = "open"
TYPE_FAMILY = {"closed_pocket": "closed", "open_pocket": "open", "opening": "through", "hole": "through"}
STOCK_ROLES = {"top", "stock", "unclaimed"}


def predicted(result):
    out = []
    for i, role in enumerate(result["faceRoles"]):
        if role == "chamfer" and result["faceElement"][i] < 0:
            out.append("chamfer")
        elif role in STOCK_ROLES or result["faceElement"][i] < 0:
            out.append("stock")
        elif role == "chamfer":
            out.append("chamfer")
        else:
            out.append(TYPE_FAMILY[result["elements"][result["faceElement"][i]]["type"]])
    return out


def main():
    cli, folder = sys.argv[1], sys.argv[2]
    out = sys.argv[sys.argv.index("--out") + 1] if "--out" in sys.argv else None
    parts = sorted(glob.glob(os.path.join(folder, "*.step")))
    tot = okb = okc = 0
    fam_tot, fam_ok, rows, confusion = {}, {}, [], {}
    for step in parts:
        truth = pickle.load(open(step[:-5] + ".face_truth", "rb"))
        with tempfile.NamedTemporaryFile(suffix=".json") as tmp:
            r = subprocess.run([cli, "recognise", step, "--face-names", "--json", tmp.name], capture_output=True,
                               text=True)
            if r.returncode != 0:
                rows.append((os.path.basename(step), 0, 0, 0, r.stderr.strip()))
                tot += len(truth)
                continue
            res = json.load(open(tmp.name))
        pred = predicted(res)
        n = b = c = 0
        for i, name in enumerate(res["faceNames"]):
            lab = truth[int(name)]
            fam = FAMILY[lab]
            p = pred[i]
            n += 1
            b += (fam == "stock") == (p == "stock")
            c += fam == p
            fam_tot[fam] = fam_tot.get(fam, 0) + 1
            fam_ok[fam] = fam_ok.get(fam, 0) + (fam == p)
            confusion[(fam, p)] = confusion.get((fam, p), 0) + 1
        tot, okb, okc = tot + n, okb + b, okc + c
        rows.append((os.path.basename(step), n, b, c, ""))
    lines = ["| part | faces | binary agree | class agree |", "|---|---|---|---|"]
    for name, n, b, c, err in rows:
        lines.append(f"| {name} | {n} | {b} | {c} |" if not err else f"| {name} | error | {err} | |")
    lines.append(f"| **all {len(parts)} parts** | {tot} | {okb / tot:.1%} | {okc / tot:.1%} |")
    lines.append("")
    lines.append("| label family | faces | recognised as that family |")
    lines.append("|---|---|---|")
    for fam in sorted(fam_tot):
        lines.append(f"| {fam} | {fam_tot[fam]} | {fam_ok[fam] / fam_tot[fam]:.1%} |")
    lines.append("")
    lines.append("Confusion (label family -> predicted): " + ", ".join(
        f"{a}->{b}: {v}" for (a, b), v in sorted(confusion.items()) if a != b))
    text = "\n".join(lines)
    print(text)
    print(f"binary agreement {okb / tot:.4f}, class agreement {okc / tot:.4f}")
    if out:
        with open(out + ".part", "w") as f:
            f.write(text + "\n")
        os.replace(out + ".part", out)
    floors = {"--min-binary": okb / tot, "--min-class": okc / tot}
    for flag, value in floors.items():
        if flag in sys.argv and value < float(sys.argv[sys.argv.index(flag) + 1]):
            print("agreement {} = {:.4f} is below {}".format(flag[6:], value, sys.argv[sys.argv.index(flag) + 1]))
            sys.exit(1)


if __name__ == "__main__":
    main()
