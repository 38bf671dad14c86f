#!/usr/bin/env python3
"""How Abaqus/Standard grows its time increment, read from the status files (.sta) of published runs.

  python3 benchmarks/abaqus_sta_growth.py --sources DIR [--md FILE]

DIR holds git mirrors as the `fetch` tool lays them out (DIR/OWNER+NAME/repo, bare); every file ending in .sta at
each mirror's HEAD whose first lines name Abaqus is read. For every increment C whose two predecessors A and B (same
step, each converged at its first attempt, C's first attempt too) both converged in at most 4 equilibrium
iterations without severe discontinuity iterations, the ratio dt_C / dt_B is classified (x1.5, x2.0 - the factor of
diffusion-dominated procedures -, unchanged, other) separately for B grown from A by 1.5 ("after a growth") and B
not grown. Increments at the largest increment of their step that did not grow, and each step's last increment
(which may be cut to end the step), are left out. ldfcz's rule (host/analysis/step_control.f90) restarts the count
after a growth, so after a growth it keeps the increment unchanged; the column "after a growth" tells which rule
the runs follow. Also counted: the same ratio by the larger iteration count of A and B.
"""
import argparse
import collections
import os
import re
import subprocess
import sys

from abaqus_corpus import stamp

ROW = re.compile(r"\s*(\d+)\s+(\d+)\s+(\d+)(U?)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)")


def sta_files(sources):
    for name in sorted(os.listdir(sources)):
        git = os.path.join(sources, name, "repo")
        if not os.path.isdir(git):
            continue
        p = subprocess.run(["git", "--git-dir", git, "ls-tree", "-r", "--name-only", "HEAD"], capture_output=True,
                           text=True, errors="replace")
        for path in p.stdout.splitlines():
            if path.lower().endswith(".sta"):
                text = subprocess.run(["git", "--git-dir", git, "show", "HEAD:" + path], capture_output=True,
                                      text=True, errors="replace").stdout
                if "abaqus" in text[:400].lower():
                    yield name, path, text


def rows(text):
    out = []
    for line in text.splitlines():
        m = ROW.match(line)
        if m:
            try:
                out.append(dict(step=int(m.group(1)), att=int(m.group(3)), failed=m.group(4) == "U",
                                sdi=int(m.group(5)), eq=int(m.group(6)), dt=float(m.group(10))))
            except ValueError:
                pass
    return [r for r in out if not r["failed"]]


def classify(ratio):
    if abs(ratio - 1.5) < 0.01:
        return "x1.5"
    if abs(ratio - 2.0) < 0.01:
        return "x2.0"
    if abs(ratio - 1.0) < 1e-3:
        return "unchanged"
    return "other"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sources", required=True, help="folder of git mirrors (OWNER+NAME/repo)")
    ap.add_argument("--md", help="also write a stamped report to this file")
    a = ap.parse_args()
    after = collections.Counter()
    by_iter = collections.Counter()
    files = 0
    repos = set()
    for repo, path, text in sta_files(a.sources):
        conv = rows(text)
        if len(conv) < 4:
            continue
        files += 1
        repos.add(repo)
        dt_max = {}
        for r in conv:
            dt_max[r["step"]] = max(dt_max.get(r["step"], 0.0), r["dt"])
        for i in range(2, len(conv) - 1):
            pa, pb, pc = conv[i - 2], conv[i - 1], conv[i]
            if not (pa["step"] == pb["step"] == pc["step"] == conv[i + 1]["step"]):
                continue
            if pa["att"] != 1 or pb["att"] != 1 or pc["att"] != 1:
                continue
            kind = classify(pc["dt"] / pb["dt"])
            if kind != "x1.5" and kind != "x2.0" and pc["dt"] >= 0.999 * dt_max[pc["step"]]:
                continue
            if max(pa["sdi"], pb["sdi"]) > 0:
                continue
            by_iter[(max(pa["eq"], pb["eq"]), kind)] += 1
            if max(pa["eq"], pb["eq"]) <= 4:
                grown = abs(pb["dt"] / pa["dt"] - 1.5) < 0.01
                after[("after a growth" if grown else "no growth before", kind)] += 1
    kinds = ["x1.5", "x2.0", "unchanged", "other"]
    lines = ["%d Abaqus .sta files in %d repositories" % (files, len(repos)), "",
             "| increment B (both A and B easy: <= 4 iterations) | " + " | ".join(kinds) + " |",
             "|---|" + "---|" * len(kinds)]
    for label in ("after a growth", "no growth before"):
        lines.append("| %s | %s |" % (label, " | ".join(str(after[(label, k)]) for k in kinds)))
    lines += ["", "| larger iteration count of A and B | " + " | ".join(kinds) + " |", "|---|" + "---|" * len(kinds)]
    for n in sorted({k[0] for k in by_iter}):
        lines.append("| %d | %s |" % (n, " | ".join(str(by_iter[(n, k)]) for k in kinds)))
    print("\n".join(lines))
    if a.md:
        head = ["# Abaqus/Standard's increment growth in published .sta files", ""] + stamp(sys.argv, "no ldfcz run") + \
            ["", __doc__.split("\n\n", 2)[2].strip(), ""]
        with open(a.md, "w") as f:
            f.write("\n".join(head + lines) + "\n")
    return 0 if files else 1


if __name__ == "__main__":
    from ldfcz_tools.cli import guard
    sys.exit(guard(main))
