#!/usr/bin/env python3
"""Runs ldfcz on public Abaqus-format decks and reports, deck by deck, whether it ran, what stopped it, and whether the
displacements it prints match the reference results (docs/host.md, "Public decks").

Two corpora, neither of them part of this project (fetch them yourself; nothing of them is committed):

  calculix     CalculiX's test suite (github.com/Dhondtguido/CalculiX, folder test/: JOB.inp with the reference
               output JOB.dat.ref). The decks taken are the static analyses of elastic solids without contact:
               a JOB.dat.ref exists; *STATIC is the only procedure; no contact or tie (*CONTACT PAIR, *SURFACE
               INTERACTION, *GAP, *TIE, ...); every material has *ELASTIC and no inelastic or user behaviour
               (*PLASTIC, *HYPERELASTIC, *CREEP, *USER MATERIAL, ...); only continuum elements (C3D*, CPS*, CPE*,
               CAX*); no keyword that Abaqus does not have (*REFINE MESH, *USE REFINED MESH, *MATRIX ASSEMBLE,
               *CHANGE SOLID SECTION, *INITIAL STRAIN INCREASE, *SOLIDSECTION, *RIGIDBODY). `select` lists them.
               The displacement tables of *NODE PRINT (CalculiX: "displacements (vx,vy,vz) for set S and time T")
               are compared with ldfcz's JOB.dat tables of the same set at the same total time: a deck matches
               when max |u - u_ref| <= tol * max |u_ref| over every compared table (tol default 1e-3: the
               element formulations differ, e.g. ldfcz's C3D8 is F-bar; JOB.dat prints 5 significant digits).
  third-party  decks that authors of Abaqus user routines published beside their UMAT/UEL (a JSON manifest:
               repository, commit, deck and routine files); each deck is run with --user and reported as ran
               (exit 0), stopped (exit 2 and the message) or did not converge (exit 3).

  python3 benchmarks/abaqus_corpus.py calculix --corpus DIR/test [--exe build/bin/ldfcz] [--report FILE]
  python3 benchmarks/abaqus_corpus.py select --corpus DIR/test
  python3 benchmarks/abaqus_corpus.py third-party --manifest benchmarks/abaqus_third_party.json --sources DIR [--report FILE]
  python3 benchmarks/abaqus_corpus.py recheck --corpus DIR/test --deck JOB --edit 'OLD=>NEW' [--edit ...]

`recheck` looks into one mismatch with CalculiX itself (Debian's calculix-ccx, `ccx` on the PATH): it runs the deck
as published and with the edits (plain text replacements, e.g. the solver or NLGEOM taken out) through both ccx and
ldfcz and prints how far each result is from each other one, and how far each program moves between the two decks.

--sources DIR holds one git clone per repository, named owner+name (e.g. DIR/KianAghani+UEL, or its repo/ folder);
the files are read at the manifest's commit with `git show`. The report (markdown) is stamped with the project's
commit, the command, the date and the machine.
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PROCEDURES = {'*STATIC', '*FREQUENCY', '*BUCKLE', '*DYNAMIC', '*HEAT TRANSFER', '*COUPLED TEMPERATURE-DISPLACEMENT',
              '*VISCO', '*MODAL DYNAMIC', '*STEADY STATE DYNAMICS', '*CFD', '*GREEN', '*COMPLEX FREQUENCY',
              '*UNCOUPLED TEMPERATURE-DISPLACEMENT', '*ELECTROMAGNETICS', '*SENSITIVITY', '*FEASIBLE DIRECTION',
              '*CRACK PROPAGATION', '*SUBSTRUCTURE GENERATE', '*SELECT CYCLIC SYMMETRY MODES', '*NO ANALYSIS',
              '*MASS FLOW'}
CONTACT = {'*CONTACT PAIR', '*SURFACE INTERACTION', '*SURFACE BEHAVIOR', '*GAP', '*CONTACT', '*FRICTION',
           '*CLEARANCE', '*CONTACT FILE', '*CONTACT PRINT', '*CONTACT OUTPUT', '*GAP CONDUCTANCE', '*TIE'}
INELASTIC = {'*PLASTIC', '*HYPERELASTIC', '*HYPERFOAM', '*CREEP', '*USER MATERIAL', '*DEFORMATION PLASTICITY',
             '*CYCLIC HARDENING', '*DEPVAR', '*VISCOPLASTIC', '*MOHR COULOMB'}
NOT_ABAQUS = {'*REFINE MESH', '*USE REFINED MESH', '*MATRIX ASSEMBLE', '*CHANGE SOLID SECTION',
              '*INITIAL STRAIN INCREASE', '*SOLIDSECTION', '*RIGIDBODY'}


# What stops or separates decks that the project leaves as they are (reports/corpus/calculix.md, "Notes"): CalculiX
# extensions that Abaqus lacks, out-of-scope procedures, and why the tables that do not match differ. Each names the
# decks it explains and the source (CalculiX's manual, doc/CalculiX.tex of the corpus repository, or the Abaqus
# Keywords Reference, KG).
CALCULIX_NOTES = [
    ('beamf3submodel, beamfsubmodel, submodelbeamp, submodelbeampdouble, submodeltwobeam, submodeltwobeamnlgeom',
     '*SUBMODEL drives nodes from a global model\'s results file: out of the static host\'s scope.'),
    ('beammr, beammrco, beammrlin, beamplane, beamstraight, dist',
     '*MPC types MEANROT, PLANE, STRAIGHT and DIST are CalculiX\'s; they are not among the Abaqus *MPC types (KG '
     '*MPC): out of scope.'),
    ('coupling6, coupling8, coupling9, coupling11, coupling12',
     '*DISTRIBUTING given one rotation (dof 4 or 6): every translation and that rotation coupled, the others '
     'released (inferred: docs/host.md, "Coupling constraints"); they print *SECTION PRINT only. In coupling12 '
     '(L-shaped face) CalculiX\'s section moment, (129.93, 0.0065, -3.41), is not the applied (131.45, 0, 0), which '
     'the Theory Manual\'s statically admissible distribution transmits exactly.'),
    ('coupling7, coupling10',
     '*COUPLING, ORIENTATION= with one rotation constrained about an oblique local axis: refused. Their *CLOAD at the '
     'reference node is global in Abaqus (KG *CLOAD: local only at a *TRANSFORM node) and has components about the '
     'released axes, which would act on nothing; CalculiX applies it in the local system (its section force is '
     '7910.5 along local 3).'),
    ('coupling3, cyl',
     '*KINEMATIC 2 in a cylindrical system (a twist): run; they print *SECTION PRINT only; the torque from the root '
     'reactions, 14.3824 and 73.593, against CalculiX\'s 14.3821 and 73.589 (3e-5, 5e-5).'),
    ('beamdelay', '*CLOAD, TIME DELAY is a CalculiX parameter (its manual, *CLOAD); Abaqus\'s *CLOAD has none.'),
    ('beamnlptp, beampo2, beampo6, c3d15',
     '*NODE PRINT, TIMEPOINTS= and *EL PRINT, GLOBAL= are CalculiX parameters (KG *NODE PRINT, *EL PRINT have '
     'neither; Abaqus names time points on *OUTPUT, which ldfcz reads). c3d15 with GLOBAL=YES taken out runs and '
     'matches CalculiX to 1.6e-5 (reports/corpus/recheck_c3d15.md).'),
    ('modelchel3', '*MODEL CHANGE, MECHSTRAINTORESIDUAL (the mechanical strain turned into a residual strain) is a '
     'CalculiX parameter (its manual, *MODEL CHANGE); Abaqus\'s *MODEL CHANGE has none (KG *MODEL CHANGE).'),
    ('beamprb, beamrb, beamrb2',
     '*RIGID BODY, NSET=, ROT NODE= is CalculiX\'s form (KG *RIGID BODY takes ELSET=, PIN NSET=, TIE NSET=, no '
     'ROT NODE); beamrb and beamrb2 also turn the body by 10 degrees under NLGEOM: out of scope.'),
    ('beamuamp, beamfrdread, beamd2, dloadlinI, c3d6',
     'CalculiX forms: *AMPLITUDE, USER (Abaqus: DEFINITION=USER), *TEMPERATURE, FILE= of a CalculiX .frd file, the '
     'load label P2NP, C3D8I elements of 10 nodes, *MEMBRANE: out of scope.'),
    ('segment1',
     'its second step has no *NODE PRINT of its own and the reference prints the first step\'s request again: '
     'ldfcz carries *NODE PRINT and *EL PRINT requests into later steps until a step gives its own, as Abaqus '
     'carries output requests (Analysis User\'s Guide, "Requesting output in multiple steps"; docs/host.md).'),
    ('beam8p, beam8t, beam8p_mpc',
     'mismatch 3-5 %: C3D8 is fully integrated in CalculiX (2x2x2, its manual) and locks in bending; ldfcz\'s C3D8 '
     'has the mean-dilatation B-bar (Abaqus\'s C3D8 is selectively reduced), so these coarse bending meshes deflect '
     'more. With C3D8I in both programs they agree to 5.7e-6, 4.7e-5 and 2.9e-6 (reports/corpus/recheck_beam8p.md, '
     'recheck_beam8t.md, recheck_beam8p_mpc.md): the element formulations differ, not the deck\'s meaning.'),
    ('beam20t',
     'C3D20 with nodal temperatures: matched once ldfcz interpolated temperatures in second-order hexahedra and '
     'quadrilaterals with their first-order part as Abaqus does (docs/elements.md, TEMP); CalculiX interpolates '
     'them linearly from the corner nodes (its manual, C3D10T), which gives the same field for this deck.'),
    ('planestress3',
     'mismatch 2.3 %: CalculiX expands plane-stress elements into a layer of 3D bricks (its manual, "2D elements '
     '... are automatically expanded into 3D"); ldfcz\'s CPS4 is a plane-stress element.'),
    ('beampic',
     'mismatch 1.7e-3: the reference was solved with CalculiX\'s iterative Cholesky solver; the same deck solved by '
     'ccx with its direct solver (SPOOLES) agrees with ldfcz to 5.6e-6 (reports/corpus/recheck_beampic.md, `recheck '
     '--deck beampic --edit \'SOLVER=ITERATIVE CHOLESKY=>SOLVER=SPOOLES\'`): the difference is the reference\'s '
     'solver tolerance, not the model.'),
    ('beamwrite, beamwrite2',
     'mismatch 1.24e-3: a bar pulled by a follower pressure p under NLGEOM (p/E = 4.76e-4). Without NLGEOM ldfcz and '
     'ccx agree to 1.3e-5; NLGEOM moves ccx by -1.00e-3 and ldfcz by +2.37e-4 (reports/corpus/recheck_beamwrite.md '
     'and recheck_beamwrite2.md print the change from NLGEOM to none, of opposite sign): '
     'CalculiX\'s *ELASTIC under NLGEOM is St. Venant-Kirchhoff (second Piola-Kirchhoff stress linear in the Green '
     'strain: the closed form for this bar is -(3/2 + 2 nu) p/E = -1.00e-3), Abaqus\'s (and ldfcz\'s) relates the '
     'Cauchy stress to the logarithmic strain (Analysis User\'s Guide, "Linear elastic behavior": +p/(2E) = +2.38e-4). '
     'The difference is the material\'s large-strain definition, and ldfcz keeps Abaqus\'s.'),
]


def keyword_lines(path, depth=0):
    """(keyword, {param: value}) of every keyword line of a deck and its *INCLUDE files."""
    out = []
    try:
        lines = open(path, errors='replace').read().splitlines()
    except OSError:
        return out
    for line in lines:
        s = line.strip()
        if not s.startswith('*') or s.startswith('**'):
            continue
        fields = [x.strip() for x in s.split(',')]
        kw = re.sub(r'\s+', ' ', fields[0].upper())
        params = {}
        for p in fields[1:]:
            if '=' in p:
                a, b = p.split('=', 1)
                params[re.sub(r'\s+', ' ', a.strip().upper())] = b.strip()
            elif p:
                params[re.sub(r'\s+', ' ', p.upper())] = ''
        out.append((kw, params))
        if kw == '*INCLUDE' and 'INPUT' in params and depth < 5:
            out += keyword_lines(os.path.join(os.path.dirname(path), params['INPUT'].strip('"')), depth + 1)
    return out


def select_calculix(corpus):
    """The static elastic no-contact decks of the CalculiX test folder (module docstring), sorted."""
    chosen = []
    for name in sorted(os.listdir(corpus)):
        if not name.endswith('.inp'):
            continue
        job = name[:-4]
        if not os.path.exists(os.path.join(corpus, job + '.dat.ref')):
            continue
        kws = keyword_lines(os.path.join(corpus, name))
        names = {k for k, _ in kws}
        if {k for k in names if k in PROCEDURES} != {'*STATIC'}:
            continue
        if names & CONTACT or names & INELASTIC or names & NOT_ABAQUS or '*ELASTIC' not in names:
            continue
        types = {p.get('TYPE', '').upper() for k, p in kws if k == '*ELEMENT'}
        if any(not re.match(r'^(C3D|CPS|CPE|CAX)', t) for t in types):
            continue
        chosen.append(job)
    return chosen


def number(text):
    """Float of a printed number (Fortran E or D exponent)."""
    return float(text.replace('D', 'E').replace('d', 'e'))


def read_calculix_dat(path):
    """{(set, time): {node: [u1, u2, u3]}} of the displacement tables of a CalculiX .dat file."""
    tables = {}
    current = None
    head = re.compile(r'^\s*displacements \(vx,vy,vz\) for set (\S+) and time\s+(\S+)')
    for line in open(path, errors='replace'):
        m = head.match(line)
        if m:
            current = {}
            tables[(m.group(1).upper(), number(m.group(2)))] = current
            continue
        if current is None:
            continue
        parts = line.split()
        if not parts:
            continue
        if re.match(r'^\d+$', parts[0]) and len(parts) >= 2:
            try:
                current[int(parts[0])] = [number(x) for x in parts[1:]]
            except ValueError:
                current = None
        else:
            current = None
    return tables


def read_ldfcz_dat(path):
    """{(set, time): {node: {var: value}}} of the *NODE PRINT tables of ldfcz's JOB.dat (set '' without NSET)."""
    tables = {}
    total = None
    current = None
    cols = None
    setname = None
    for line in open(path, errors='replace'):
        m = re.search(r'TOTAL TIME COMPLETED\s+(\S+)', line)
        if m:
            total = number(m.group(1))
            continue
        m = re.search(r'THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO NODE SET (\S+)', line)
        if m:
            setname = m.group(1).upper()
            continue
        if 'THE FOLLOWING TABLE IS PRINTED FOR ALL NODES' in line:
            setname = ''
            continue
        if re.match(r'^\s+NODE FOOT-', line):
            cols = line.split()[2:]
            current = {}
            tables[(setname if setname is not None else '', total)] = current
            setname = None
            continue
        if current is None:
            continue
        parts = line.split()
        if not parts:
            continue
        if parts[0] == 'NOTE':
            continue
        if re.match(r'^\d+$', parts[0]) and len(parts) == len(cols) + 1:
            current[int(parts[0])] = dict(zip(cols, [number(x) for x in parts[1:]]))
        else:
            current = None
    return tables


def compare(ref, out, tol):
    """(status, worst relative error, tables compared): status 'match', 'mismatch' or 'not comparable: why'."""
    worst = 0.0
    compared = 0
    if not ref:
        return 'not comparable: the reference prints no displacement table', None, 0
    last_time = max(t for _, t in ref)
    for (setname, t), rows in sorted(ref.items(), key=lambda kv: kv[0][1]):
        match = None
        for (s2, t2), rows2 in out.items():
            if t2 is not None and s2 in (setname, '') and abs(t2 - t) <= 1e-6 * max(1.0, abs(t)):
                if match is None or s2 == setname:
                    match = rows2
        if match is None:
            if abs(t - last_time) <= 1e-9 * max(1.0, abs(t)):
                return 'not comparable: no ldfcz table of set %s at time %g' % (setname, t), None, compared
            continue
        scale = max((abs(v) for r in rows.values() for v in r), default=0.0)
        err = 0.0
        for node, vals in rows.items():
            got = match.get(node)
            if got is None and all(v == 0.0 for v in vals):
                # CalculiX keeps the undefined labels of a GENERATE range in a set and prints zeros for them;
                # ldfcz leaves them out of the set
                continue
            if got is None:
                return 'not comparable: node %d of set %s not in ldfcz\'s table' % (node, setname), None, compared
            for k, v in enumerate(vals):
                name = 'U%d' % (k + 1)
                if name in got:
                    err = max(err, abs(got[name] - v))
        rel = err / scale if scale > 0.0 else err
        worst = max(worst, rel)
        compared += 1
    if compared == 0:
        return 'not comparable: no table at a common time', None, 0
    return ('match' if worst <= tol else 'mismatch'), worst, compared


def first_error(stderr):
    """The first 'ldfcz: error:' line, without the program prefix."""
    for line in stderr.splitlines():
        if line.startswith('ldfcz: error:'):
            return line[len('ldfcz: error:'):].strip()
    return stderr.strip().splitlines()[-1] if stderr.strip() else ''


def blocker_class(message):
    """A deck error message reduced to its keyword and kind, for counting ('*COUPLING: unsupported keyword')."""
    m = re.match(r'^\S+?:\d+: (\*[A-Z0-9 \-]+): (.*)$', message)
    if not m:
        return message[:80]
    what = re.sub(r'\d+(\.\d+)?(E[+-]?\d+)?', 'N', m.group(2))
    what = re.sub(r'\(.*', '', what).strip()
    return '%s: %s' % (m.group(1), what[:70])


def run_ldfcz(exe, deck, out, timeout, user=None, cwd=None, fflags=None):
    """Exit status ('timeout' when killed), first error message and wall seconds of one run. out None: no --out, the
    files go to the working directory cwd (as Abaqus writes a job's files where it runs)."""
    cmd = [exe, '--quiet', '--threads', '1']
    if out is not None:
        if os.path.isdir(out):
            shutil.rmtree(out)
        cmd += ['--out', out]
    if user:
        cmd += ['--user', user]
    if fflags:
        cmd += ['--fflags', fflags]
    cmd.append(deck)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=cwd)
        msg = {0: '', 3: 'no convergence (exit 3)'}.get(p.returncode, first_error(p.stderr))
        return p.returncode, msg.replace(os.path.dirname(os.path.abspath(deck)) + '/', ''), time.time() - t0
    except subprocess.TimeoutExpired:
        return 'timeout', 'killed after %d s' % timeout, time.time() - t0


def exe_commit(exe):
    """The commit of the source tree an ldfcz executable was built from (its build directory's parent), if known."""
    src = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(exe))))
    p = subprocess.run(['git', '-C', src, 'rev-parse', '--short', 'HEAD'], capture_output=True, text=True)
    return p.stdout.strip() if p.returncode == 0 else 'unknown'


def stamp(argv, exe):
    """Commit, command, date and machine of a report, and the executable measured."""
    try:
        commit = subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                                text=True).stdout.strip()
        # (the reports themselves are written by these runs: not a change of what is measured)
        dirty = subprocess.run(['git', '-C', ROOT, 'status', '--porcelain', '--untracked-files=no', '--', '.',
                                ':!reports'], capture_output=True, text=True).stdout.strip()
        if dirty:
            commit += ' (with uncommitted changes)'
    except OSError:
        commit = 'unknown'
    cpu = platform.processor() or platform.machine()
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                cpu = line.split(':', 1)[1].strip()
                break
    except OSError:
        pass
    date = datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')
    command = ' '.join(['python3'] + argv)
    machine = '%s, %s, %d cores' % (platform.node(), cpu, os.cpu_count() or 0)
    program = '%s (built from %s)' % (exe, exe_commit(exe))
    return ['Stamp: commit %s; program %s; command `%s`; %s; machine %s.' % (commit, program, command, date, machine),
            '', '- commit: %s' % commit, '- ldfcz measured: %s' % program, '- command: `%s`' % command,
            '- date: %s' % date, '- machine: %s' % machine]


def write_report(path, lines):
    """The report to path (and standard output)."""
    text = '\n'.join(lines) + '\n'
    if path:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        with open(path, 'w') as f:
            f.write(text)
    sys.stdout.write(text)


def cmd_calculix(a, argv):
    decks = select_calculix(a.corpus)
    if a.only:
        decks = [d for d in decks if d in a.only.split(',')]
    work = os.path.abspath(a.work)
    rows, blockers = [], {}
    ran = comparable = matched = 0
    for job in decks:
        rc, msg, wall = run_ldfcz(os.path.abspath(a.exe), os.path.join(a.corpus, job + '.inp'),
                                  os.path.join(work, job), a.timeout)
        status, err, ntab = '', None, 0
        if rc == 0:
            ran += 1
            dat = os.path.join(work, job, job + '.dat')
            out = read_ldfcz_dat(dat) if os.path.exists(dat) else {}
            status, err, ntab = compare(read_calculix_dat(os.path.join(a.corpus, job + '.dat.ref')), out, a.tol)
            if not status.startswith('not comparable'):
                comparable += 1
                matched += status == 'match'
        else:
            status = 'exit %s' % rc
            key = blocker_class(msg) if rc == 2 else ('no convergence (exit 3)' if rc == 3 else str(rc))
            blockers.setdefault(key, []).append(job)
        rows.append((job, rc, status, err, ntab, msg, wall))
        sys.stderr.write('%-28s %-8s %s\n' % (job, rc, status if rc == 0 else msg[:100]))
    n = len(decks)
    lines = ['# CalculiX test decks (static, elastic solids, no contact) run by ldfcz', ''] + stamp(argv, a.exe) + [
        '- corpus: %s (%d decks selected by the rules of benchmarks/abaqus_corpus.py)' % (a.corpus, n),
        '- tolerance: max |u - u_ref| <= %g max |u_ref| per compared table' % a.tol, '',
        '**%d of %d run** (%.0f %%); %d print displacement tables comparable with the reference; **%d of %d match** '
        '(%.0f %%).' % (ran, n, 100.0 * ran / max(n, 1), comparable, matched, comparable,
                        100.0 * matched / max(comparable, 1)), '',
        '## Blockers (first error of each deck that did not run), most frequent first', '',
        '| count | blocker | decks |', '|---|---|---|']
    for key, jobs in sorted(blockers.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        lines.append('| %d | %s | %s |' % (len(jobs), key.replace('|', '/'), ', '.join(jobs)))
    lines += ['', '## Notes', ''] + ['- %s: %s' % (jobs, note) for jobs, note in CALCULIX_NOTES]
    lines += ['', '## Decks', '', '| deck | exit | result | max rel. error | tables | wall s |',
              '|---|---|---|---|---|---|']
    for job, rc, status, err, ntab, msg, wall in rows:
        lines.append('| %s | %s | %s | %s | %d | %.1f |' % (job, rc, status if rc == 0 else msg.replace('|', '/')[:160],
                                                          '%.2e' % err if err is not None else '', ntab, wall))
    write_report(a.report, lines)
    return 0


def run_ccx(deck_text, job, where):
    """Runs CalculiX's ccx on a deck text in folder where; its displacement tables (read_calculix_dat)."""
    os.makedirs(where, exist_ok=True)
    with open(os.path.join(where, job + '.inp'), 'w') as f:
        f.write(deck_text)
    subprocess.run(['ccx', '-i', job], cwd=where, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=600)
    dat = os.path.join(where, job + '.dat')
    return read_calculix_dat(dat) if os.path.exists(dat) else {}


def as_calculix(tables):
    """ldfcz's JOB.dat tables ({node: {U1..}}) in read_calculix_dat's form ({node: [u1, u2, u3]})."""
    return {key: {n: [v.get('U%d' % k, 0.0) for k in (1, 2, 3)] for n, v in rows.items()}
            for key, rows in tables.items()}


def largest_shift(a, b):
    """Relative change from result a to result b at the node and component where a is largest."""
    key = max(a, key=lambda k: k[1])
    node, comp = max(((n, k) for n, r in a[key].items() for k in range(len(r))), key=lambda nk: abs(a[key][nk[0]][nk[1]]))
    ua, ub = a[key][node][comp], b.get(key, {}).get(node, [0.0] * 3)[comp]
    return (ub - ua) / ua if ua else float('nan'), node, comp + 1


def cmd_recheck(a, argv):
    if shutil.which('ccx') is None:
        sys.stderr.write('abaqus_corpus recheck: ccx not found (Debian package calculix-ccx)\n')
        return 2
    text = open(os.path.join(a.corpus, a.deck + '.inp')).read()
    edited = text
    for edit in a.edit:
        old, sep, new = edit.partition('=>')
        if not sep or old not in edited:
            sys.stderr.write('abaqus_corpus recheck: edit %r: %r not in %s.inp\n' % (edit, old, a.deck))
            return 2
        edited = edited.replace(old, new)
    work = os.path.abspath(a.work)
    results = {'reference': read_calculix_dat(os.path.join(a.corpus, a.deck + '.dat.ref'))}
    for tag, deck_text in (('', text), (' edited', edited)):
        where = os.path.join(work, 'ccx' + tag.replace(' ', '_'))
        results['ccx' + tag] = run_ccx(deck_text, a.deck, where)
        deck = os.path.join(work, 'ldfcz_deck' + tag.replace(' ', '_'), a.deck + '.inp')
        os.makedirs(os.path.dirname(deck), exist_ok=True)
        with open(deck, 'w') as f:
            f.write(deck_text)
        where = os.path.join(work, 'ldfcz' + tag.replace(' ', '_'))
        rc, msg, _ = run_ldfcz(os.path.abspath(a.exe), deck, where, a.timeout)
        dat = os.path.join(where, a.deck + '.dat')
        results['ldfcz' + tag] = as_calculix(read_ldfcz_dat(dat)) if rc == 0 and os.path.exists(dat) else {}
        if rc != 0:
            sys.stderr.write('ldfcz%s: exit %s: %s\n' % (tag, rc, msg))
    lines = ['# recheck of %s against CalculiX (%s)' % (a.deck, '; '.join(a.edit)), ''] + stamp(argv, a.exe) + [
        '', '| result | against | max abs difference / max abs reference value |', '|---|---|---|']
    pairs = [('ccx', 'reference'), ('ldfcz', 'reference'), ('ldfcz', 'ccx'), ('ldfcz edited', 'ccx edited'),
             ('ldfcz', 'ccx edited')]
    for x, y in pairs:
        status, err, _ = compare(results[y], {k: {n: {'U%d' % (i + 1): v for i, v in enumerate(r)}
                                                   for n, r in rows.items()} for k, rows in results[x].items()}, a.tol)
        lines.append('| %s | %s | %s |' % (x, y, '%.3e' % err if err is not None else status))
    lines += ['', '| program | change from the deck as published to the edited deck (largest displacement) |',
              '|---|---|']
    for prog in ('ccx', 'ldfcz'):
        if results[prog] and results[prog + ' edited']:
            shift, node, comp = largest_shift(results[prog], results[prog + ' edited'])
            lines.append('| %s | %+.3e (node %d, U%d) |' % (prog, shift, node, comp))
    write_report(a.report, lines)
    return 0


def repo_dir(sources, repo):
    """The clone of repository owner/name under sources."""
    base = os.path.join(sources, repo.replace('/', '+'))
    return os.path.join(base, 'repo') if os.path.isdir(os.path.join(base, 'repo')) else base


def export_tree(src, commit, dest):
    """Every file of a repository at a commit into dest (git show, file by file); False when none could be read."""
    p = subprocess.run(['git', '-C', src, 'ls-tree', '-r', '-z', '--name-only', commit], capture_output=True)
    if p.returncode != 0:
        return False
    paths = [x.decode() for x in p.stdout.split(b'\0') if x]
    return export_files(src, commit, paths, dest) or bool(paths)


def export_files(src, commit, paths, dest):
    """Files of a repository at a commit into dest (git show); False when one is missing."""
    ok = True
    for path in paths:
        target = os.path.join(dest, path)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        p = subprocess.run(['git', '-C', src, 'show', '%s:%s' % (commit, path)], capture_output=True)
        if p.returncode != 0:
            ok = False
            continue
        with open(target, 'wb') as f:
            f.write(p.stdout)
    return ok


def cmd_third_party(a, argv):
    manifest = json.load(open(a.manifest))
    work = os.path.abspath(a.work)
    rows = []
    ran = 0
    for entry in manifest['decks']:
        name = entry['name']
        dest = os.path.join(work, name, 'src')
        if os.path.isdir(dest):
            shutil.rmtree(dest)
        src = repo_dir(a.sources, entry['repo'])
        # the whole tree at the commit: decks and routines include files beside them
        if not export_tree(src, entry['commit'], dest):
            rows.append((entry, 'missing', 'files not found at the commit in %s' % src, 0.0))
            continue
        deck = os.path.join(dest, entry['deck'])
        user = ','.join(os.path.join(dest, f) for f in entry['user'])
        # run where the deck lies, its files written there (Abaqus' working directory: GETOUTDIR is that folder,
        # and routines read their own data files relative to it)
        rc, msg, wall = run_ldfcz(os.path.abspath(a.exe), deck, None, a.timeout, user, cwd=os.path.dirname(deck),
                                  fflags=entry.get('fflags'))
        msg = msg.replace(dest + '/', '')
        ran += rc == 0
        rows.append((entry, rc, msg, wall))
        sys.stderr.write('%-12s %-8s %s\n' % (name, rc, msg[:120]))
    n = len(rows)
    lines = ['# Decks published with third-party Abaqus user routines, run by ldfcz with --user', '']
    lines += stamp(argv, a.exe) + [
        '- manifest: %s' % os.path.relpath(a.manifest, ROOT), '', manifest.get('about', ''), '',
        '**%d of %d run** (exit 0).' % (ran, n), '',
        '| deck | repository @ commit | deck file | routine files | exit | first error | wall s |',
        '|---|---|---|---|---|---|---|']
    for entry, rc, msg, wall in rows:
        lines.append('| %s | %s @ %s | %s | %s | %s | %s | %.1f |' % (
            entry['name'], entry['repo'], entry['commit'][:12], entry['deck'], ', '.join(entry['user']), rc,
            msg.replace('|', '/')[:200], wall))
    lines += ['', 'Notes:', ''] + ['- %s: %s' % (e['name'], e['note']) for e in manifest['decks'] if e.get('note')]
    write_report(a.report, lines)
    return 0


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    sub = ap.add_subparsers(dest='cmd', required=True)
    for name in ('calculix', 'select', 'third-party', 'recheck'):
        p = sub.add_parser(name)
        p.add_argument('--exe', default=os.path.join(ROOT, 'build', 'bin', 'ldfcz'))
        p.add_argument('--work', default='corpus_runs', help='run directory (default ./corpus_runs)')
        p.add_argument('--report', help='markdown report to write (also printed)')
        p.add_argument('--timeout', type=int, default=300, help='seconds per deck (default 300)')
        if name in ('calculix', 'select', 'recheck'):
            p.add_argument('--corpus', required=True, help='the CalculiX test folder')
            p.add_argument('--tol', type=float, default=1e-3)
            p.add_argument('--only', help='comma-separated deck names')
        if name == 'recheck':
            p.add_argument('--deck', required=True, help='deck name (JOB of JOB.inp)')
            p.add_argument('--edit', action='append', default=[], help="'OLD=>NEW' text replacement (repeatable)")
        if name == 'third-party':
            p.add_argument('--manifest', default=os.path.join(ROOT, 'benchmarks', 'abaqus_third_party.json'))
            p.add_argument('--sources', required=True, help='folder of clones named owner+name')
    a = ap.parse_args(argv[1:])
    if a.cmd == 'select':
        print('\n'.join(select_calculix(a.corpus)))
        return 0
    if a.cmd == 'calculix':
        return cmd_calculix(a, argv)
    if a.cmd == 'recheck':
        return cmd_recheck(a, argv)
    return cmd_third_party(a, argv)


if __name__ == '__main__':
    from ldfcz_tools.cli import guard
    sys.exit(guard(main, sys.argv))
