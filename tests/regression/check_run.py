#!/usr/bin/env python3
"""Runs ldfcz on a deck and checks the outcome (deck regression tests registered by tests/host.cmake).

  check_run.py --exe BIN --deck DECK --out DIR --bad
      malformed deck: exit status 2 and an error message naming the file, the line and the keyword given by the
      deck's first line `** EXPECT line=N keyword=*KW [file=NAME]`.
  check_run.py --exe BIN --deck DECK --out DIR --case NAME [--user FILE] [--expect-exit N]
      a run whose JOB.csv / JOB.sta / JOB.log is checked against a closed-form answer (functions case_<NAME> below).
"""
import argparse
import json
import csv
import math
import os
import re
import subprocess
import sys

from ldfcz_tools import outputs

PHI, DELTA = 0.2, 3.679e-3  # LDF cohesive properties of the decks (N/mm, mm)


def ldf_traction(d):
    """LDF envelope, paper Eq. 20: T = (phi/delta) (d/delta) exp(-d/delta)."""
    return PHI / DELTA * (d / DELTA) * math.exp(-d / DELTA)


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(name, got, want, rtol, atol=0.0):
    ok = abs(got - want) <= rtol * abs(want) + atol
    print("%-40s got %.10g want %.10g (rtol %g) %s" % (name, got, want, rtol, "ok" if ok else "FAIL"))
    if not ok:
        fail(name)


def last_row(job_dir, job):
    with open(os.path.join(job_dir, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail("no converged increment in %s.csv" % job)
    return {k: (float(v) if k not in ("step", "inc") else int(v)) for k, v in rows[-1].items()}, rows


def sta_ratios(job_dir, job):
    """Residual ratios r_max/q_avg of every converged increment in JOB.sta."""
    out = []
    with open(os.path.join(job_dir, job + ".sta")) as f:
        for line in f:
            if "converged" in line and "r/q:" in line:
                out.append([float(x) for x in line.split("r/q:")[1].split()])
    return out


# ---------------------------------------------------------------------------------------------- closed-form cases
def case_c3d8_uniaxial(d, job):
    """Uniaxial stress with NLGEOM, Abaqus *ELASTIC (hypoelastic, Jaumann; Hughes-Winget increments integrate the
    logarithmic strain to second order in the increment): sigma_33 = E ln(lambda), lateral stretch lambda^-nu,
    RF3 = sigma_33 * A = E ln(lambda) lambda_l^2. Tolerance 1e-4: the mid-point strain increment differs from
    ln(l1/l0) by O((dl/l)^3) = 1e-6 per increment of 2 %."""
    row, _ = last_row(d, job)
    e, nu, lam = 1000.0, 0.3, 1.2
    close("TOP.U3", row["TOP.U3"], 0.2, 1e-12)
    lam_l = 1.0 + 2.0 * row["TOP.U1"]  # mean over nodes at x = 0 and x = 1
    close("lateral stretch", math.log(lam_l), -nu * math.log(lam), 1e-4)
    close("TOP.RF3", row["TOP.RF3"], e * math.log(lam) * lam_l ** 2, 1e-4)
    close("BOTTOM.RF3 = -TOP.RF3", row["BOTTOM.RF3"], -row["TOP.RF3"], 1e-9)


def case_c3d6_uniaxial(d, job):
    """The closed form of case_c3d8_uniaxial on the cube of two C3D6 wedges, and its *EL PRINT table in JOB.dat headed
    with the type's name (element catalogue; earlier versions headed every type but C3D8 and CPE4 'SOLID')."""
    case_c3d8_uniaxial(d, job)
    with open(os.path.join(d, job + ".dat")) as f:
        text = f.read()
    if "FOR ELEMENT TYPE C3D6 AND ELEMENT SET CUBE" not in text:
        fail("JOB.dat: no *EL PRINT table headed ELEMENT TYPE C3D6")
    print("JOB.dat table headed ELEMENT TYPE C3D6: ok")


def case_c3d6_faces(d, job):
    """Uniform pressure p = 10 MPa on every outer face S1..S5 of two C3D6 wedges (decks/single/c3d6_faces.inp), only
    rigid-body motions suppressed: u = -e X with e = p (1 - 2 nu) / E = 4e-3 at the corner (1, 1, 1) and no reaction.
    Tolerance 1e-9 relative (linear elements and consistent face loads are exact; one linear solve), reactions
    1e-8 N, 1e-9 of the 10 N on a face: a face with wrong nodes leaves a resultant of the order of p x 1 mm^2."""
    row, _ = last_row(d, job)
    e = 10.0 * (1.0 - 2.0 * 0.3) / 1000.0
    for i in (1, 2, 3):
        close("N7.U%d = -e" % i, row["N7.U%d" % i], -e, 1e-9)
        close("FIXED.RF%d = 0" % i, row["FIXED.RF%d" % i], 0.0, 0.0, 1e-8)


def case_tri_faces(d, job):
    """Triangles (CPE3, CPS6, CAX3, CAX6) under a uniform pressure p = 10 MPa on every outer edge
    (tests/regression/make_single_decks.py, tri_faces): u = -e X at the corner node 3 (x0 + 1, 1), e = p (1 - nu) / E
    in plane stress, p (1 + nu)(1 - 2 nu) / E in plane strain, p (1 - 2 nu) / E axisymmetric (hydrostatic), and no
    reaction. 1e-9 relative (the exact field is linear: every type reproduces it, one linear solve); reactions 1e-8 N
    (1e-9 of the edge loads, 10 N per mm; an axisymmetric total over 2 pi is at most 2 pi 20 N)."""
    row, _ = last_row(d, job)
    kind = job.upper()[:3]
    e = {"CPS": 10.0 * 0.7, "CPE": 10.0 * 1.3 * 0.4, "CAX": 10.0 * 0.4}[kind] / 1000.0
    x3 = (2.0, 1.0) if kind == "CAX" else (1.0, 1.0)
    for i in (1, 2):
        close("N3.U%d = -e X" % i, row["N3.U%d" % i], -e * x3[i - 1], 1e-9)
        close("FIXED.RF%d = 0" % i, row["FIXED.RF%d" % i], 0.0, 0.0, 1e-8)


def case_midside_temperature(d, job):
    """A free C3D20 / CPS8 with temperature 100 at its mid-side nodes and 0 at its corners (make_single_decks.py,
    midside_temperature): the first-order part of that field is uniform (200 in the cube, 400/3 in the square), so
    node 3 moves by alpha T X (the corner (1, 1, 0) or (1, 1); plane stress: the in-plane free expansion) and no
    reaction arises. 1e-9 relative (one linear solve of a stress-free state); reactions 1e-9 N (the element's forces
    are of order E alpha T = 2 N: a quadratic temperature field would leave self-stress of that order and a
    different displacement)."""
    row, _ = last_row(d, job)
    three_d = job.lower().startswith("c3d")
    t = 200.0 if three_d else 400.0 / 3.0
    x3 = (1.0, 1.0, 0.0) if three_d else (1.0, 1.0)
    for i, x in enumerate(x3, start=1):
        close("N3.U%d = alpha T X" % i, row["N3.U%d" % i], 1e-5 * t * x, 1e-9, 1e-15)
        close("FIXED.RF%d = 0" % i, row["FIXED.RF%d" % i], 0.0, 0.0, 1e-9)


def case_surface_two_lines(d, job):
    """decks/single/surface_two_lines.inp: a surface of two element-set lines (10 MPa on both top faces) and a
    second *DSLOAD line on another surface (5 MPa on a side face): the bottom's total reactions are the applied
    resultants, RF3 = 20 N, RF1 = 5 N (1e-9: the consistent face loads of a linear element sum exactly to p times
    the area)."""
    row, _ = last_row(d, job)
    close("BOTTOM.RF3 = 20 N", row["BOTTOM.RF3"], 20.0, 1e-9)
    close("BOTTOM.RF1 = 5 N", row["BOTTOM.RF1"], 5.0, 1e-9)


def case_user_initial_values(d, job):
    """decks/single/user_initial_values.inp with tests/regression/user_initial_values.f90: SIGINI's sigma11 = -100
    relieved on the free face, u(1, 1, 1) = (1e-3, -3e-4, -3e-4) = -S sigma0 (1e-9 relative: one linear solve), and
    the stress at the end below 1e-6 of the initial 100 (JOB.dat prints 5 digits); SDVINI's SDV1 = each point's z
    (0.5 -+ 0.5/sqrt 3 for points 1-4 / 5-8 of the 2x2x2 rule, 5e-5: the printed digits) and SDV2 = its number
    NPT (the order and the coordinates SDVINI was called with)."""
    row, _ = last_row(d, job)
    for i, want in ((1, 1e-3), (2, -3e-4), (3, -3e-4)):
        close("N7.U%d" % i, row["N7.U%d" % i], want, 1e-9)
    pts = {}
    for line in open(os.path.join(d, job + ".dat")):
        p = line.split()
        if len(p) == 5 and p[0] == "1" and p[1].isdigit():
            pts[int(p[1])] = [float(v) for v in p[2:]]
    if sorted(pts) != list(range(1, 9)):
        fail("the *EL PRINT table of element 1 has points %s" % sorted(pts))
    g = 0.5 / math.sqrt(3.0)
    for k, (s11, z, npt) in sorted(pts.items()):
        close("point %d S11 = 0" % k, s11, 0.0, 0.0, 1e-6)
        close("point %d SDV1 = z" % k, z, 0.5 - g if k <= 4 else 0.5 + g, 0.0, 5e-5)
        close("point %d SDV2 = NPT" % k, npt, float(k), 0.0, 1e-12)


def case_cohesive_I(d, job):
    """Mode I: RF3 = T(0.0075) A0 (A0 = 1 mm^2); Eq. 20. The RF is summed from the UEL's RHS exactly."""
    row, _ = last_row(d, job)
    close("TOP.RF3", row["TOP.RF3"], ldf_traction(0.0075), 1e-9)
    close("TOP.RF1", row["TOP.RF1"], 0.0, 0.0, 1e-9)


def case_cohesive_II(d, job):
    """Mode II: the LDF traction follows the opening vector (Eq. 21): RF1 = T(0.0075) A0, no normal force."""
    row, _ = last_row(d, job)
    close("TOP.RF1", row["TOP.RF1"], ldf_traction(0.0075), 1e-9)
    close("TOP.U3 (free, stays 0)", row["TOP.U3"], 0.0, 0.0, 1e-12)


def case_cohesive_mixed(d, job):
    """Mixed mode: opening (0.0045, 0, 0.0060), |Delta| = 0.0075: RF = T(0.0075) Delta/|Delta| A0 (Eq. 21)."""
    row, _ = last_row(d, job)
    t = ldf_traction(0.0075)
    close("TOP.RF1", row["TOP.RF1"], t * 0.0045 / 0.0075, 1e-9)
    close("TOP.RF3", row["TOP.RF3"], t * 0.0060 / 0.0075, 1e-9)


def case_cohesive_block(d, job):
    """A C3D8 block on a cohesive element, pulled at its top: in series, the block's reaction equals the cohesive
    traction of the interface opening (uniform, mode I): RF3(TOP) = T(U3(IFACE)) A0, equilibrium to the Newton
    tolerance (R_n = 0.005 of the time-averaged force, so rtol 1e-2; the converged residual is far smaller)."""
    row, rows = last_row(d, job)
    for r in rows[1:]:
        rf = float(r["TOP.RF3"])
        t = ldf_traction(float(r["IFACE.U3"]))
        close("inc %s: TOP.RF3 vs T(IFACE.U3)" % r["inc"], rf, t, 1e-2, 1e-6)
    # energy balance of the closing summary: the external work (trapezoidal in the reactions) against the UEL's
    # ENERGY(2) + ENERGY(4) plus the block's SSE. With ~25 increments along a smooth path the trapezoidal error is
    # O(h^2) ~ 1e-3: bound 1e-2.
    energy = outputs.get(outputs.read_summary(d, job) or {}, "energy")
    if not energy or energy["stored_dissipated"] is None:
        fail("no energy balance in the run summary")
    close("energy: stored + dissipated vs external work", energy["stored_dissipated"], energy["external_work"], 1e-2)


# homogeneous displacement gradients and interior nodes of the patch decks (tests/regression/make_single_decks.py)
PATCH = {
    "patch_c3d8": ([[0.10, 0.02, -0.03], [-0.04, -0.05, 0.02], [0.03, 0.01, 0.06]], (0.57, 0.45, 0.54)),
    "patch_c3d8_linear": ([[0.10, 0.02, -0.03], [-0.04, -0.05, 0.02], [0.03, 0.01, 0.06]], (0.57, 0.45, 0.54)),
    "patch_cpe4": ([[0.10, 0.02], [-0.04, -0.05]], (0.57, 0.45)),
    "patch_c3d6": ([[0.10, 0.02, -0.03], [-0.04, -0.05, 0.02], [0.03, 0.01, 0.06]], (0.57, 0.45, 0.54)),
}


def case_patch(d, job):
    """Patch test: a distorted mesh whose boundary nodes follow u = A X (finite A, NLGEOM) must reproduce the
    homogeneous state, so the free interior node lands on A X. Tolerance 1e-8 relative: the Newton iteration stops
    at r_max <= 1e-8 q_avg (the deck's *CONTROLS and Abaqus' linear criterion), far below any element error."""
    row, _ = last_row(d, job)
    a, x = PATCH[job]
    for i in range(len(x)):
        want = sum(a[i][c] * x[c] for c in range(len(x)))
        close("INNER.U%d (interior node on u = A X)" % (i + 1), row["INNER.U%d" % (i + 1)], want, 1e-8, 1e-12)


def case_patch_linear(d, job):
    """Linear patch test (NLGEOM=NO, *ELASTIC): the exact field as case_patch, and ONE Newton correction with the
    default symmetric solver, since the small-strain B-bar stiffness of a linear elastic material is symmetric
    (docs/elements.md); an unsymmetric element matrix solved with its symmetric part needs more."""
    case_patch(d, job)
    with open(os.path.join(d, job + ".sta")) as f:
        rows = [line.split() for line in f if "converged" in line and not line.startswith("#")]
    if not rows:
        fail("no converged increment in JOB.sta")
    for r in rows:
        if int(r[3]) != 1:
            fail("increment %s needed %s Newton iterations, expected 1" % (r[1], r[3]))
    print("iterations per increment:", [int(r[3]) for r in rows])


def case_quadratic(d, job):
    """Quadratic Newton convergence on a large-rotation elastic problem: in each increment that needed at least 3
    residual evaluations, some pair of consecutive ratios r_k < 1e-2 r_0 satisfies r_(k+1) <= 10 r_k^2 / r_0
    (Newton's quadratic contraction of the residual relative to the first one, with a factor 10 for the
    non-symmetric F-bar/Jaumann part dropped by the symmetric solver being O(sigma/E); r_k < 1e-2 r_0: in the
    asymptotic range, where the quadratic model holds. Since the first iteration carries the prescribed rotation
    through the tangent, the third increment goes 6.2, 2.1, 1.1e-2, 4.2e-7: quadratic, r_k = 1.1e-2 = 1.8e-3 r_0)."""
    ratios = sta_ratios(d, job)
    if not ratios:
        fail("no converged increment with residual ratios in JOB.sta")
    checked = 0
    for r in ratios:
        if len(r) < 3:
            continue
        ok = any(r[k + 1] <= 10.0 * r[k] ** 2 / max(r[0], 1e-300) or r[k + 1] < 1e-10
                 for k in range(len(r) - 1) if r[k] < 1e-2 * r[0])
        print("ratios", " ".join("%.2e" % x for x in r), "quadratic" if ok else "NOT quadratic")
        if not ok:
            fail("residual ratios do not converge quadratically")
        checked += 1
    if checked == 0:
        fail("no increment with three or more residual evaluations")


def case_user_uel(d, job):
    """Third-party fixed-form UEL (tests/regression/user_uel_elastic.f, 4-node bar-like elastic interface with
    stiffness k per unit area along every active dof, lumped to the nodes): RF3 = k * opening * A0."""
    row, _ = last_row(d, job)
    k, opening = 100.0, 0.01
    close("TOP.RF3", row["TOP.RF3"], k * opening * 1.0, 1e-9)
    with open(os.path.join(d, job + ".log")) as f:
        log = f.read()
    if "user_uel_elastic.f" not in log:
        fail("the log does not say the user UEL was used")


def case_nonconvergence(d, job):
    """The minimum increment is reached: exit 3 (checked by the caller), the converged increments' rows are kept
    and the log says why."""
    with open(os.path.join(d, job + ".log")) as f:
        log = f.read()
    if "no convergence" not in log:
        fail("the log does not explain the stop")
    with open(os.path.join(d, job + ".csv")) as f:
        rows = list(csv.DictReader(f))
    print("converged rows kept:", len(rows))
    if len(rows) < 1:
        fail("no converged increment kept")


def case_broken_umat(d, job):
    """A user UMAT returns NaN at point 3 of element 2 (tests/regression/user_umat_broken.f90): without -v, the log
    names the element, the routine, the point and the reason of the cutback, once (the repeats are not logged
    again), and the run stops with exit 3 (checked by the caller)."""
    with open(os.path.join(d, job + ".log")) as f:
        log = f.read()
    want = "element 2 (UMAT): material returned a non-finite stress or DDSDDE at point 3"
    n = log.count(want)
    print("cause of the cutback logged %d time(s): %s" % (n, want))
    if n != 1:
        fail("the log names the failing element/point %d times (want 1)" % n)
    if "cutbacks 3" not in log:
        fail("expected 3 cutbacks before the minimum increment")


def case_first_deck(d, job):
    """The README's first deck (decks/first/two_blocks.inp): two elastic blocks glued by one LDF element. The blocks
    and the interface carry the same force, so at every increment RF3(TOP) = A T(opening) with the opening
    GLUE_TOP.U3 - GLUE_BOTTOM.U3 and T of Eq. 20 (A = 1 mm^2; equilibrium to the Newton tolerance, rtol 1e-2 as
    case_cohesive_block); the largest force is A T_max = 20 N (Eq. 5), reached at an opening of delta, within the
    increment size (0.4 um of pull, about 2 % of the force near the peak's flat top: rtol 2e-3 there)."""
    row, rows = last_row(d, job)
    peak = 0.0
    for r in rows:
        rf = float(r["TOP.RF3"])
        opening = float(r["GLUE_TOP.U3"]) - float(r["GLUE_BOTTOM.U3"])
        close("inc %s: TOP.RF3 vs A T(opening)" % r["inc"], rf, ldf_traction(opening), 1e-2, 1e-6)
        peak = max(peak, rf)
    close("peak force vs A T_max", peak, PHI / (math.e * DELTA), 2e-3)


def case_uel_arguments(d, job):
    """Every UEL call of decks/single/uel_arguments.inp (one element, label 7, type U5, all dofs prescribed), as
    recorded by tests/regression/user_uel_args.f, against Abaqus' documented values: LFLAGS = (1 static, 1 NLGEOM,
    1 RHS and AMATRX in a normal iteration even without free equations, 0 general step, 1 on an increment start
    extrapolated from the previous increment (not in the first increment of a step), else 0); TIME = step and total
    time at the start of the increment, DTIME, PERIOD, PARAMS(1:3) = 0 in a static step, NDLOAD = 0, NRHS = 1,
    MLVARX = NDOFEL = 24; the 16 PROPS and JPROPS after NPROPS and NJPROP read 0 (ldfcz pads them with zeros)."""
    with open(os.path.join(d, "uel_args.txt")) as f:
        calls = [line.split() for line in f if line.strip()]
    want = []
    for kstep, period, dt, ninc, t0 in ((1, 1.0, 0.25, 4, 0.0), (2, 2.0, 1.0, 2, 1.0)):
        for k in range(1, ninc + 1):
            want.append((kstep, k, 7, 5, (1, 1, 1, 0, 0 if k == 1 else 1), (k - 1) * dt, t0 + (k - 1) * dt, dt,
                         period))
    if len(calls) != len(want):
        fail("%d UEL calls recorded, expected %d (one per increment: nothing to iterate on)" % (len(calls), len(want)))
    for c, w in zip(calls, want):
        got_int = tuple(int(x) for x in c[:9])
        got_real = [float(x) for x in c[9:16]]
        tail = tuple(int(x) for x in c[16:19])
        ok = (got_int == (w[0], w[1], w[2], w[3]) + w[4] and
              all(abs(g - v) <= 1e-12 * max(1.0, abs(v)) for g, v in zip(got_real, (w[5], w[6], w[7], w[8], 0, 0, 0)))
              and tail == (0, 1, 24) and float(c[19]) == 0.0)
        print("step %d inc %d: LFLAGS %s TIME %s DTIME %s PERIOD %s %s" % (w[0], w[1], c[4:9], c[9:11], c[11], c[12],
                                                                          "ok" if ok else "FAIL"))
        if not ok:
            fail("UEL arguments differ from Abaqus' values: %s, want %s" % (c, w))


def case_umat_arguments(d, job, nlgeom=True):
    """Every UMAT call of decks/single/umat_arguments.inp (NLGEOM=YES) or umat_arguments_small.inp (NLGEOM=NO), as
    recorded by tests/regression/user_umat_args.f, against Abaqus' documented values. One C3D8 unit cube (label 3)
    with every dof prescribed: F = diag(1, 1, lambda), lambda = 1 + 0.1 t, 4 increments of 0.25, temperature
    ramped from 20 to 50. Per call: NOEL 3, NPT 1..8 (Abaqus' point order: xi fastest, then eta, then zeta),
    LAYER = KSPT = 1 (a homogeneous solid section: inferred), JSTEP = (step, 1 general static, NLGEOM flag, 0 no
    perturbation), KINC, NDI = NSHR = 3, NTENS = 6, NSTATV = 2 (*DEPVAR), NPROPS = 2, TIME = (step, total) time at
    the start of the increment, DTIME, TEMP at the start and DTEMP over the increment, CELENT = cube root of the
    element volume (current under NLGEOM), COORDS of the point (current under NLGEOM, original otherwise), STRAN at
    the start and DSTRAN (NLGEOM: the sum of and the midpoint (Hughes-Winget) increment 2 (l1 - l0) / (l0 + l1) of
    the logarithmic strain; otherwise the small strain l0 - 1 and l1 - l0), DFGRD0/DFGRD1 = diag(1, 1, l0/l1),
    DROT = I, CMNAME in upper case. Tolerance 1e-12: all values are O(1) and computed in double precision."""
    with open(os.path.join(d, "umat_args.txt")) as f:
        calls = [line.split() for line in f if line.strip()]
    if len(calls) != 32:
        fail("%d UMAT calls recorded, expected 32 (8 points x 4 increments: nothing to iterate on)" % len(calls))
    g = 1.0 / math.sqrt(3.0)
    dt = 0.25
    stran = 0.0
    for k in range(1, 5):
        t0 = (k - 1) * dt
        l0, l1 = 1.0 + 0.1 * t0, 1.0 + 0.1 * (t0 + dt)
        dstran = 2.0 * (l1 - l0) / (l0 + l1) if nlgeom else l1 - l0
        s0 = stran if nlgeom else l0 - 1.0
        rows = [c for c in calls if int(c[8]) == k]
        if sorted(int(c[1]) for c in rows) != list(range(1, 9)):
            fail("increment %d: points %s, want 1..8" % (k, [c[1] for c in rows]))
        for c in rows:
            npt = int(c[1])
            ints = tuple(int(x) for x in c[:14])
            want_ints = (3, npt, 1, 1, 1, 1, 1 if nlgeom else 0, 0, k, 3, 3, 6, 2, 2)
            r = [float(x) for x in c[14:62]]
            i, j, m = (npt - 1) % 2, ((npt - 1) // 2) % 2, (npt - 1) // 4
            x0 = [0.5 + 0.5 * g * (2 * q - 1) for q in (i, j, m)]
            coords = [x0[0], x0[1], x0[2] * (l1 if nlgeom else 1.0)]
            ident = [1.0, 0, 0, 0, 1.0, 0, 0, 0, 1.0]
            want = ([t0, t0, dt, 20.0 + 30.0 * t0, 30.0 * dt, l1 ** (1.0 / 3.0) if nlgeom else 1.0] + coords +
                    [0, 0, s0, 0, 0, 0] + [0, 0, dstran, 0, 0, 0] +
                    [1.0, 0, 0, 0, 1.0, 0, 0, 0, l0] + [1.0, 0, 0, 0, 1.0, 0, 0, 0, l1] + ident)
            names = (["TIME(1)", "TIME(2)", "DTIME", "TEMP", "DTEMP", "CELENT"] + ["COORDS(%d)" % q for q in (1, 2, 3)] +
                     ["STRAN(%d)" % q for q in range(1, 7)] + ["DSTRAN(%d)" % q for q in range(1, 7)] +
                     ["DFGRD0(%d)" % q for q in range(1, 10)] + ["DFGRD1(%d)" % q for q in range(1, 10)] +
                     ["DROT(%d)" % q for q in range(1, 10)])
            bad = [(n, got, w) for n, got, w in zip(names, r, want) if abs(got - w) > 1e-12]
            if ints != want_ints:
                fail("inc %d point %d: NOEL..NPROPS %s, want %s" % (k, npt, ints, want_ints))
            if bad:
                fail("inc %d point %d: %s" % (k, npt, ", ".join("%s = %.15g (want %.15g)" % b for b in bad)))
            if c[62] != "ARGSMAT":
                fail("CMNAME %r, want 'ARGSMAT' (the deck's ArgsMat in upper case)" % c[62])
        print("increment %d: 8 points, JSTEP %s, STRAN(3) %.12f DSTRAN(3) %.12f CELENT %.12f: ok"
              % (k, c[4:8], s0, dstran, want[5]))
        stran += dstran


def case_umat_arguments_small(d, job):
    """The NLGEOM=NO twin of case_umat_arguments."""
    case_umat_arguments(d, job, nlgeom=False)


def check_input_error_files(out, job, message):
    """A deck error leaves a record like any run's (issue 37): JOB.log with the message, JOB.sta with a status line
    '# input error', JOB.summary.json with status input_error and exit code 2, and no empty JOB.csv or JOB.dat."""
    err = message.split("ldfcz: error: ", 1)[-1]
    with open(os.path.join(out, job + ".log")) as f:
        if err not in f.read():
            fail("JOB.log does not hold the message: " + err)
    with open(os.path.join(out, job + ".sta")) as f:
        if not any(x.startswith("# input error (exit status 2): ") and err[:80] in x for x in f):
            fail("JOB.sta has no status line '# input error ...' with the message")
    with open(os.path.join(out, job + ".summary.json")) as f:
        doc = json.load(f)
    if (doc["status"], doc["exit_code"]) != ("input_error", 2):
        fail("JOB.summary.json: status %s, exit code %s" % (doc["status"], doc["exit_code"]))
    for ext in (".csv", ".dat"):
        path = os.path.join(out, job + ext)
        if os.path.exists(path) and os.path.getsize(path) == 0:
            fail("an empty %s was left behind" % (job + ext))
    print("ok: JOB.log, JOB.sta (input error), JOB.summary.json (input_error), no empty job files")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--bad", action="store_true")
    ap.add_argument("--case")
    ap.add_argument("--user")
    ap.add_argument("--expect-exit", type=int, default=0)
    ap.add_argument("--extra", nargs="*", default=[])
    ap.add_argument("--extra-args", default="", help="more ldfcz options, blank-separated (may start with --)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for name in ("uel_args.txt", "umat_args.txt"):  # appended to by user_uel_args.f / user_umat_args.f: start empty
        stale = os.path.join(a.out, name)
        if os.path.exists(stale):
            os.remove(stale)
    cmd = [a.exe, "--quiet", "--threads", "2", "--out", a.out]
    if a.user:
        cmd += ["--user", a.user]
    cmd += a.extra + a.extra_args.split() + [a.deck]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    print(" ".join(cmd))
    print("exit status", p.returncode)
    if p.stderr:
        print("stderr:", p.stderr.strip())
    job = os.path.splitext(os.path.basename(a.deck))[0]
    if a.bad:
        with open(a.deck) as f:
            first = f.readline()
        m = re.match(r"\*\* EXPECT line=(\d+) keyword=(\*[A-Z -]+?)(?: file=(\S+))?\s*$", first)
        if not m:
            fail("the deck has no '** EXPECT line=N keyword=*KW' first line")
        line, kw, fname = m.group(1), m.group(2), m.group(3) or os.path.basename(a.deck)
        if p.returncode != 2:
            fail("exit status %d, expected 2" % p.returncode)
        msg = p.stderr
        for what, needle in (("file name", fname + ":" + line + ":"), ("keyword", kw + ":")):
            if needle not in msg:
                fail("the message does not contain the %s '%s'" % (what, needle))
        print("ok: exit 2, message names %s:%s and %s" % (fname, line, kw))
        check_input_error_files(a.out, job, msg.strip().splitlines()[-1])
        return
    if p.returncode != a.expect_exit:
        fail("exit status %d, expected %d" % (p.returncode, a.expect_exit))
    if a.case:
        globals()["case_" + a.case](a.out, job)
    print("ok")


if __name__ == "__main__":
    main()
