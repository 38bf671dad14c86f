#!/usr/bin/env python3
"""Stability suite (issue 6): runs bin/ldfcz on every decks/stability/stab_*.inp, checks the outcome against the deck's
`** EXPECT exit=... check=...` line and a physical check, and prints/writes the table
reports/stability/{table.md,table.csv}.

  python3 tools/stability_suite.py [--exe build/bin/ldfcz] [--jobs 2] [--only PATTERN ...] [--out DIR] [--no-report]

Columns: outcome (exit status), expected, match (exit status expected AND the check passed), increments, attempts,
cutbacks, Newton iterations, energy-balance relative error (JOB.summary.json), NaN/Inf in any output (CSV, STA,
VTU, the summary's figures: must be never), wall time, and the check's note. Exit status of the tool: 0 when every case matches.
"""
import argparse
import concurrent.futures
import csv
import glob
import math
import os
import re
import subprocess
import sys
import time

from ldfcz_tools import outputs
from ldfcz_tools.cli import executable
from ldfcz_tools.paths import ROOT

NONFINITE = re.compile(r"(?i)(?<![a-z])[+-]?(nan|inf|infinity)(?![a-z])")


def parse_expect(deck):
    with open(deck) as f:
        first = f.readline()
    m = re.match(r"\*\* EXPECT (.*)$", first.strip())
    if not m:
        raise SystemExit("%s: no '** EXPECT' first line" % deck)
    kv = dict(x.split("=", 1) for x in m.group(1).split())
    kv["exit"] = [int(x) for x in kv["exit"].split(",")]
    return kv


def read_rows(d, job):
    path = os.path.join(d, job + ".csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def summary(d, job):
    """Counters and the energy balance's relative difference from JOB.summary.json (None: not there)."""
    s = {"increments": None, "attempts": None, "cutbacks": None, "iterations": None, "energy": None}
    doc = outputs.read_summary(d, job)
    if doc is None:
        return s
    s.update({k: doc["counters"][k] for k in ("increments", "attempts", "cutbacks", "iterations")})
    s["energy"] = outputs.get(doc, "energy.relative_difference")
    return s


def nonfinite(d, job):
    """Names of output files holding a NaN or an Inf (in JOB.summary.json: a measured figure written as null)."""
    bad = []
    for p in sorted(glob.glob(os.path.join(d, "*.csv")) + glob.glob(os.path.join(d, "*.sta")) +
                    glob.glob(os.path.join(d, "*.vtu"))):
        with open(p, errors="replace") as f:
            if NONFINITE.search(f.read()):
                bad.append(os.path.basename(p))
    doc = outputs.read_summary(d, job)
    if doc is not None and outputs.summary_nonfinite(doc):
        bad.append(os.path.basename(outputs.summary_path(d, job)))
    return bad


def ldf(phi, delta, d):
    """Eq. 20: T = (phi/delta)(d/delta) exp(-d/delta)."""
    return phi / delta * (d / delta) * math.exp(-d / delta)


def normal_traction(e, d):
    """Normal traction of a uniform normal opening d (negative: penetration) with the default k_c = phi/delta
    unless given: LDF along m = sign(d) e3 (Eq. 21) plus the contact penalty -k_c (d/delta)^2 (Eq. 22)."""
    phi, delta = float(e["phi"]), float(e["delta"])
    kc = float(e.get("kc", 0.0)) or phi / delta
    t = math.copysign(ldf(phi, delta, abs(d)), d)
    if d < 0:
        t -= kc * (d / delta) ** 2
    return t


# ------------------------------------------------------------------------------------------------------ checks
def check_cohesive_series(e, rows, ctx):
    """Block in series with the interface: RF3(TOP) = T(IFACE.U3) A0 at every increment (Newton tolerance: 1e-2 of the
    largest force; R_n = 0.005 of the average force)."""
    fmax = max(abs(r["TOP.RF3"]) for r in rows)
    err = max(abs(r["TOP.RF3"] - normal_traction(e, r["IFACE.U3"])) for r in rows) / fmax
    return err <= 1e-2, "max|RF - T(opening)|/max|RF| = %.1e" % err


def check_penetration(e, rows, ctx):
    """Cohesive element alone, top pushed down: RF3 = T_LDF + T_c closed form (exact, 1e-9)."""
    err = max(abs(r["TOP.RF3"] - normal_traction(e, r["TOP.U3"])) / abs(normal_traction(e, r["TOP.U3"]))
              for r in rows if r["TOP.U3"] != 0)
    last = rows[-1]
    return err <= 1e-9, "RF3 vs closed form %.1e; final opening %.3g delta, RF3 %.4g N" % (
        err, last["TOP.U3"] / float(e["delta"]), last["TOP.RF3"])


def check_rotation(e, rows, ctx):
    """Rigid rotation of the stretched bar: RF(X2) rotates with the body (R(theta) F0) and RF(X0) + RF(X2) = 0 at
    every increment, to 1e-6 |F0| (exact kinematics; Hughes-Winget is exact for a rigid increment)."""
    s1 = [r for r in rows if r["step"] == 1]
    s2 = [r for r in rows if r["step"] == 2]
    f0 = (s1[-1]["X2.RF1"], s1[-1]["X2.RF2"])
    n0 = math.hypot(*f0)
    err, net = 0.0, 0.0
    for r in s2:
        th = math.radians(float(e["degrees"])) * r["step_time"]
        want = (math.cos(th) * f0[0] - math.sin(th) * f0[1], math.sin(th) * f0[0] + math.cos(th) * f0[1])
        err = max(err, math.hypot(r["X2.RF1"] - want[0], r["X2.RF2"] - want[1]) / n0)
        net = max(net, math.hypot(r["X2.RF1"] + r["X0.RF1"], r["X2.RF2"] + r["X0.RF2"]) / n0)
    ok = err <= 1e-6 and net <= 1e-6 and len(s2) > 0
    return ok, "|RF - R F0|/|F0| %.1e, net force/|F0| %.1e over %d increments" % (err, net, len(s2))


def check_bending(e, rows, ctx):
    """Cantilever: no volumetric locking: the tip force at nu = 0.4999 within 10 % of the nu = 0.3 one (a locking
    element would be many times stiffer; beam theory does not depend on nu). The ratio to Euler-Bernoulli
    P = 3 E I w / L^3 (E = 1000, I = 1/12, w = 0.5, L = 8) is reported: two full-integration C3D8 through the depth
    are stiff in bending (shear locking, the same for both nu)."""
    p = rows[-1]["TIP.RF2"]
    beam = 3 * 1000.0 * (1.0 / 12) * 0.5 / 8 ** 3
    ctx.setdefault("bending", {})[e["nu"]] = p
    note = "tip force %.4g N = %.3f x beam theory" % (p, p / beam)
    ok = True
    if e["nu"] != "0.3":
        ref = ctx["bending"].get("0.3")
        ok = ref is not None and abs(p / ref - 1) <= 0.10
        note += "; %.3f x the nu = 0.3 force" % (p / ref if ref else float("nan"))
    return ok, note


def true_stress(r):
    """RF3 over the current area: the top nodes' mean U1 is half the lateral displacement of the x = 1 face."""
    return r["TOP.RF3"] / (1.0 + 2.0 * r["TOP.U1"]) ** 2


def material_point_stress(exe, rate):
    """True stress of the material-point driver (bin/material_point next to ldfcz) at ln(stretch) 0.3, 30 steps."""
    mp = os.path.join(os.path.dirname(exe), "material_point")
    if not os.path.exists(mp):
        return None
    out = "/tmp/ldfcz_stability_mp_%g.csv" % rate
    subprocess.run([mp, "mode=uniaxial", "rate=%g" % rate, "strain_end=0.3", "steps=30", "output=" + out],
                   capture_output=True, timeout=120)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return float(rows[-1]["stress"])


def check_pet_rate(e, rows, ctx):
    """PET tension at a constant true strain rate: reaches ln(stretch) = 0.3; the true stress (RF3 over the current
    area, lateral stretch 1 + 2 mean(U1) of the top nodes) grows with the rate (Eyring, Eq. 37): checked against
    the next slower case when it ran."""
    last = rows[-1]
    ok = abs(math.log(1 + last["TOP.U3"]) - 0.3) < 1e-9
    s = true_stress(last)
    ctx.setdefault("pet", {})[float(e["rate"])] = s
    note = "true stress at ln(stretch) 0.3: %.3f MPa" % s
    mp = material_point_stress(ctx["exe"], float(e["rate"]))
    if mp is not None:
        # same UMAT, same 30 log-strain increments: the one-element host run equals the driver to its Newton tolerance
        ok = ok and abs(s / mp - 1) < 1e-3
        note += " (material_point %.3f)" % mp
    slower = [k for k in ctx["pet"] if k < float(e["rate"])]
    if slower:
        k = max(slower)
        ok = ok and s > ctx["pet"][k]
        note += "; > %.3f at %.0e /s: %s" % (ctx["pet"][k], k, s > ctx["pet"][k])
    return ok, note


def check_dtime_cohesive(e, rows, ctx):
    """Rate-independent interface: the period (1e-12 s or 1e6 s) changes nothing: final RF3 equals the period-1 run's
    to 1e-6 (same increment sequence up to round-off in the time)."""
    ref = ctx.get("dtime_ref")
    if ref is None:
        return False, "reference stab_dtime_cohesive_ref did not run"
    err = abs(rows[-1]["TOP.RF3"] - ref) / abs(ref)
    return err <= 1e-6, "final RF3 %.10g vs %.10g at period 1 (rel %.1e)" % (rows[-1]["TOP.RF3"], ref, err)


def check_one_increment(e, rows, ctx):
    """50 % in one increment (hypoelastic *ELASTIC, Hughes-Winget): sigma = E * 2 ln... the mid-point strain increment
    is 0.5/1.25 = 0.4 against ln 1.5 = 0.405: RF3 within 3 % of E ln(1.5) lambda_l^2."""
    r = rows[-1]
    lam_l = 1 + 2 * r["TOP.U1"]
    want = 1000.0 * math.log(1.5) * lam_l ** 2
    err = abs(r["TOP.RF3"] / want - 1)
    return err <= 0.03 and len(rows) == 1, "RF3 %.4g vs E ln(1.5) A = %.4g (%.1f %%), %d increment" % (
        r["TOP.RF3"], want, 100 * err, len(rows))


def check_peel(e, rows, ctx):
    """Peel: finite force history; records the peak and final force (with eta: the effect of the regularisation)."""
    peak = max(r["LOAD.RF2"] for r in rows)
    note = "pulled to %.3g mm, peak force %.4g N/mm, final %.4g N/mm" % (rows[-1]["LOAD.U2"], peak, rows[-1]["LOAD.RF2"])
    ctx.setdefault("peel", {})[e.get("eta", "0")] = rows
    return True, note


def check_finite(e, rows, ctx):
    r = rows[-1] if rows else None
    return True, ("last converged step time %.4g" % r["step_time"]) if r else "no converged increment"


CHECKS = {n[6:]: f for n, f in globals().items() if n.startswith("check_")}


def run_case(exe, deck, outroot):
    job = os.path.splitext(os.path.basename(deck))[0]
    d = os.path.join(outroot, job)
    os.makedirs(d, exist_ok=True)
    for f in glob.glob(os.path.join(d, job + "*")):
        os.remove(f)
    t0 = time.time()
    try:
        p = subprocess.run([exe, "--quiet", "--threads", "1", "--out", d, deck], capture_output=True, text=True,
                           timeout=600)
        rc, err = p.returncode, p.stderr
    except subprocess.TimeoutExpired:
        rc, err = "timeout", ""
    return job, d, rc, err, time.time() - t0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "..", "build-robust-rel", "bin", "ldfcz"))
    ap.add_argument("--decks", default=os.path.join(ROOT, "decks", "stability"))
    ap.add_argument("--out", default="/tmp/ldfcz_stability")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--no-report", action="store_true", help="do not write reports/stability")
    a = ap.parse_args()
    executable(a.exe, 'ldfcz program')
    decks = sorted(glob.glob(os.path.join(a.decks, "stab_*.inp")))
    if a.only:
        decks = [d for d in decks if any(re.search(p, os.path.basename(d)) for p in a.only)]
    t0 = time.time()
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as ex:
        results = list(ex.map(lambda d: (d,) + run_case(a.exe, d, a.out), decks))
    ctx = {"exe": a.exe}
    # references first: the period-1 cohesive block, slower PET rates before faster ones
    for d, job, out, rc, err, wall in results:
        if job == "stab_dtime_cohesive_ref":
            rows = read_rows(out, job)
            if rows:
                ctx["dtime_ref"] = rows[-1]["TOP.RF3"]
    order = sorted(results, key=lambda r: (float(parse_expect(r[0]).get("rate", 0)), r[1].replace("nu03", "nu0")))
    table = []
    for d, job, out, rc, err, wall in order:
        e = parse_expect(d)
        rows = read_rows(out, job)
        s = summary(out, job)
        bad = nonfinite(out, job)
        crash = bool(re.search(r"Fortran runtime error|Backtrace|Segmentation|SIG", err))
        ok_exit = rc in e["exit"] and not crash
        if rows and e["check"] in CHECKS:
            try:
                ok_check, note = CHECKS[e["check"]](e, rows, ctx)
            except (KeyError, ZeroDivisionError, ValueError) as x:
                ok_check, note = False, "check failed: %r" % x
        else:
            ok_check, note = (e["exit"] == [3] and not rows), "no converged increment"
        if crash:
            note = "CRASH: " + err.strip().splitlines()[0][:80]
        table.append(dict(case=job[5:], outcome=rc, expected="/".join(map(str, e["exit"])),
                          match="yes" if (ok_exit and ok_check and not bad) else "NO",
                          increments=s["increments"], attempts=s["attempts"], cutbacks=s["cutbacks"],
                          iterations=s["iterations"],
                          energy="%.1e" % s["energy"] if s["energy"] is not None else "-",
                          nan_inf=",".join(bad) if bad else "never", wall="%.2f" % wall, note=note))
    # viscous regularisation: effect on the peel force
    peel = ctx.get("peel", {})
    if "0" in peel and len(peel) > 1:
        for eta, rows in peel.items():
            if eta == "0":
                continue
            base = peel["0"]
            umax = min(base[-1]["LOAD.U2"], rows[-1]["LOAD.U2"])
            fb = max(r["LOAD.RF2"] for r in base if r["LOAD.U2"] <= umax)
            fv = max(r["LOAD.RF2"] for r in rows if r["LOAD.U2"] <= umax)
            for t in table:
                if t["case"] == "peel_brittle_viscous":
                    t["note"] += "; peak force up to u = %.3g mm: %.4g (eta_v = %s) vs %.4g (eta_v = 0), %+.1f %%" % (
                        umax, fv, eta, fb, 100 * (fv / fb - 1))
    cols = ["case", "outcome", "expected", "match", "increments", "attempts", "cutbacks", "iterations", "energy",
            "nan_inf", "wall", "note"]
    head = ["case", "exit", "expected", "match", "increments", "attempts", "cutbacks", "Newton it.",
            "energy bal. err", "NaN/Inf", "wall (s)", "check"]
    md = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for t in table:
        md.append("| " + " | ".join(str(t[c]).replace("|", "\\|") if t[c] is not None else "-" for c in cols) + " |")
    nmatch = sum(t["match"] == "yes" for t in table)
    tail = "\n%d cases, %d match their expected outcome, NaN/Inf in outputs: %s; suite wall time %.1f s (%s)\n" % (
        len(table), nmatch, "never" if all(t["nan_inf"] == "never" for t in table) else "YES",
        time.time() - t0, os.path.basename(a.exe))
    print("\n".join(md) + tail)
    if not a.no_report and not a.only:
        rep = os.path.join(ROOT, "reports", "stability")
        os.makedirs(rep, exist_ok=True)
        with open(os.path.join(rep, "table.md"), "w") as f:
            f.write("# Stability suite (tools/stability_suite.py)\n\n" + "\n".join(md) + "\n" + tail)
        with open(os.path.join(rep, "table.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=cols)
            w.writeheader()
            w.writerows(table)
    sys.exit(0 if nmatch == len(table) else 1)


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('stability_suite'))
