#!/usr/bin/python3
"""Generate the peel decks of van den Bosch, Schreurs, Geers (2007), sections 7-9 (Abaqus keyword input).

The scene (docs/scenes.md explains the reading of Fig. 10 and every choice):

  x along the specimen, z through the thickness (coordinate 2 in plane strain), y the width (3D only).
  steel substrate   z in [-h_s, 0],  x in [0, L_b]             (C3D8 / CPE4, *ELASTIC 210000, 0.3)
  LDF cohesive layer z = 0,          x in [0, L_b]             (*USER ELEMENT U1: 8-node 3D, U2: 4-node 2D)
  PET coating        z in [0, h_c],  x in [0, L_b + a_0]       (C3D8 / CPE4, or C3D8I / CPE4I; Leonov UMAT)
  The coating part x in [L_b, L_b + a_0] is the pre-delaminated flap: it bridges the broken substrate (x = L_b is
  the substrate's fracture face) up to the specimen's mid-plane x = L_b + a_0, where its end face is pulled by a
  uniform u_x (node set LOAD). The substrate's far end x = 0 is held (node set HOLD). 3D: y in [0, b] with YSYMM on
  the mid-width plane y = 0 (node set YSYM); y = b is the free edge of the specimen.

Peel force per unit width: plane strain RF1 (per unit thickness); 3D quarter model RF1 / b (b = modelled width =
half the specimen width; the mid-length symmetry does not scale the force, the two halves are in series).

Python standard library only. Run `peel_deck.py --help` for the options; defaults give the main plane-strain scene.
"""
import argparse
import json
import math
import sys

E1 = math.exp(1.0)

# Table 1 (PET), PROPS order of docs/umat.md: E (MPa), nu, S_a, eta_0r (MPa s), tau_0 (MPa), mu, G_r (MPa), r0, r1, r2
PET_TABLE1 = [1250.0, 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.990, 200.0, -4.0]
# A documented alternative reading of Table 1 (issue 17; docs/scenes.md "Table 1"): the printed eta_0r = 0.486 MPa s
# leaves the fully softened material (S -> 0) almost no flow stress. The alternative keeps the aged viscosity
# eta_0r exp(S_a) = 1.05e12 MPa s of the printed set (hence the same yield stress at every rate and pressure, Eq. 37)
# and gives half of the printed S_a to the rejuvenated state: S_a' = S_a / 2 = 14.2, eta_0r' = eta_0r exp(S_a / 2).
PET_ALT = list(PET_TABLE1)
PET_ALT[2] = PET_TABLE1[2] / 2.0
PET_ALT[3] = PET_TABLE1[3] * math.exp(PET_TABLE1[2] / 2.0)
PET_SETS = {'table1': PET_TABLE1, 'alt': PET_ALT}
PET_NAMES = ['E', 'nu', 'S_a', 'eta_0r', 'tau_0', 'mu', 'G_r', 'r0', 'r1', 'r2']   # --pet NAME=VALUE
LEONOV_NSTATV = 11          # docs/umat.md: NSTATV >= 11
STEEL = (210000.0, 0.3)     # MPa, -
UEL_NSVARS_PER_IP = 4       # docs/uel.md: 4 SVARS per Gauss point


# the host-side declaration of the built-in UEL's SVARS layout (a comment for Abaqus; docs/uel.md)
LDFCZ_SVARS_3D = "**LDFCZ SVARS, TYPE=U1, POINTS=4, PER POINT=4, DELTA MAX=1, OPENING=2, TRACTION=3, LENGTH PROPERTY=2"
LDFCZ_SVARS_2D = "**LDFCZ SVARS, TYPE=U2, POINTS=2, PER POINT=4, DELTA MAX=1, OPENING=2, TRACTION=3, LENGTH PROPERTY=2"

def graded_lengths(total, first, ratio, cap):
    """Element lengths summing to total: start at `first`, grow by `ratio` up to `cap` (then constant).
    The count is the smallest that reaches total; the lengths are then scaled down uniformly to fit exactly."""
    if total <= 0.0:
        return []
    if ratio <= 1.0 or cap <= first:
        n = max(1, int(math.ceil(total / first - 1e-9)))
        return [total / n] * n
    lens = []
    s = 0.0
    h = first
    while s < total * (1.0 - 1e-9):
        lens.append(h)
        s += h
        h = min(h * ratio, cap)
    scale = total / s
    return [v * scale for v in lens]


def uniform(total, h):
    """Equal lengths close to h summing to total (none for total <= 0)."""
    if total <= 0.0:
        return []
    n = max(1, int(round(total / h)))
    return [total / n] * n


def build(p):
    """Mesh and deck text for parameters p (argparse namespace). Returns (text, info dict)."""
    three_d = p.three_d
    delta = p.delta if p.delta else p.phi / (E1 * p.tmax)
    le = p.le
    if p.nx:
        le = p.fine_length / p.nx
    # ---- x stations: coarse far field [0, L_b - fine], fine [L_b - fine, L_b], flap [L_b, L_b + a_0]
    fine = min(p.fine_length, p.bonded)
    fine_x = uniform(fine, le)
    le = fine_x[0]
    far = p.bonded - fine
    if p.no_coarse:
        far_x = uniform(far, le) if far > 0 else []
    else:
        far_x = list(reversed(graded_lengths(far, le * p.coarse_ratio, p.coarse_ratio, p.coarse_max)))
    flap_x = uniform(p.flap, le)
    xs = [0.0]
    for h in far_x + fine_x + flap_x:
        xs.append(xs[-1] + h)
    nbx = len(far_x) + len(fine_x)          # element columns over the substrate
    nxt = len(xs) - 1                        # element columns of the coating
    x_front = xs[nbx]
    peel = p.reading == 'peel'
    theta = math.radians(p.peel_angle) if peel else 0.0
    radius = p.bend_radius if p.bend_radius else 1.5 * p.coating

    def coat_xz(ix, t):
        """(x, z) of the coating node of column ix at height t above the interface. Bonded part and the bridge's
        flap: (x, t). Peel reading: the flap's column at arc length s = x - x_front along its bottom face is bent
        upwards about the centre (x_front, R) by the angle s/R up to the peel angle theta (bottom face at radius R,
        top face at R - h_c), then runs straight in the direction (cos theta, sin theta)."""
        x = xs[ix]
        if not peel or ix <= nbx or theta == 0.0:
            return x, t
        sa = x - x_front
        sb = radius * theta
        a = min(sa / radius, theta)
        xx = x_front + (radius - t) * math.sin(a)
        zz = radius - (radius - t) * math.cos(a)
        if sa > sb:
            xx += (sa - sb) * math.cos(theta)
            zz += (sa - sb) * math.sin(theta)
        return xx, zz
    # ---- z stations: coating uniform n_z; steel graded from the interface down
    zc = [p.coating * k / p.nz for k in range(p.nz + 1)]
    if p.rigid_substrate:
        zs = [0.0]
    else:
        t1 = p.steel_first if p.steel_first else min(p.coating / p.nz, 2.0 * le)
        lens = graded_lengths(p.substrate, t1, p.steel_ratio, p.substrate)
        zs = [0.0]
        for h in lens:
            zs.append(zs[-1] - h)
        zs.reverse()                         # bottom (-h_s) ... top (0)
    nzs = len(zs) - 1
    # ---- y stations
    if three_d and p.full_width:
        ys = [p.width * (j - p.ny) / p.ny for j in range(2 * p.ny + 1)]
    else:
        ys = [p.width * j / p.ny for j in range(p.ny + 1)] if three_d else [0.0]
    nyn = len(ys)

    # ---- nodes: coating block then substrate block, id = base + 1 + ix + (nx+1) (iy + nyn iz)
    def cid(ix, iy, iz):
        return 1 + ix + (nxt + 1) * (iy + nyn * iz)
    ncoat = (nxt + 1) * nyn * (p.nz + 1)
    sbase = ncoat

    def sid(ix, iy, iz):
        return sbase + 1 + ix + (nbx + 1) * (iy + nyn * iz)
    nsub = (nbx + 1) * nyn * (nzs + 1)

    out = []
    w = out.append
    info = {
        'dimension': 3 if three_d else 2, 'delta_mm': delta, 'l_e_mm': le, 'n_fine_x': len(fine_x),
        'n_far_x': len(far_x), 'n_flap_x': len(flap_x), 'nz_coating': p.nz, 'nz_steel': nzs,
        'ny': p.ny if three_d else 0,
        'width_mm': (2.0 * p.width if p.full_width else p.width) if three_d else 1.0, 'x_front_mm': x_front,
        'x_load_mm': xs[-1], 'fine_length_mm': fine, 'rigid_substrate': p.rigid_substrate, 'rate_mm_s': p.rate,
        'du_mm': p.du, 'u_total_mm': p.u_total, 'phi_N_mm': p.phi, 'reading': p.reading,
        'peel_angle_deg': p.peel_angle if peel else 0.0, 'bend_radius_mm': radius if peel else 0.0,
        'grip': p.grip if peel else 'fixed', 'flap_mm': p.flap,
    }
    # the pull: LOAD moves by u_total along d = (cos theta, sin theta) in the (x, z) plane; the peel force is the
    # reaction along d. Carriage grip (90 degrees only): u_z prescribed, u_x free (the specimen rides on a carriage
    # that keeps the arm vertical). z is dof 3 in 3D, dof 2 in plane strain.
    zdof = 3 if three_d else 2
    pull_dir = tuple(0.0 if abs(c) < 1e-12 else c for c in (math.cos(theta), math.sin(theta)))
    if peel and p.grip == 'carriage':
        pull_dir = (0.0, 1.0)
    info.update({'z_dof': zdof, 'pull_dir': pull_dir})
    w('*HEADING')
    w('ldfcz peel scene (tools/peel_deck.py): %s%s, PET %g mm on %s, LDF phi=%g N/mm delta=%.4e mm'
      % ('3D quarter' if three_d else 'plane strain',
         ', reading B: flap lifted at %g degrees (%s grip)' % (p.peel_angle, p.grip) if peel else '', p.coating,
         'rigid substrate' if p.rigid_substrate else 'steel %g mm' % p.substrate, p.phi, delta))
    # parameters as JSON, split into comment lines of at most 132 characters (Abaqus reads lines up to 256)
    # (--pet only when given: the committed decks' headers stay as they were)
    pj = json.dumps({k: v for k, v in sorted(vars(p).items())
                     if k not in ('output', 'info') and not (k in ('pet', 'incompatible', 'edge_fixed_y') and not v)},
                    sort_keys=True)
    for k in range(0, len(pj), 120):
        w('**PARAMS ' + pj[k:k + 120])
    w('** units: mm, N, s, MPa. x along the specimen, %s through the thickness%s.'
      % ('z' if three_d else 'coordinate 2 (the paper\'s z)', ', y the width' if three_d else ''))
    rfd = 'RF1' if not peel else ('RF%d' % zdof if p.grip == 'carriage' else
                                   '(RF1 cos %g + RF%d sin %g)' % (p.peel_angle, zdof, p.peel_angle))
    if three_d:
        fw = ('%s of LOAD / (2 b), b = %%g mm (full width modelled)' % rfd if p.full_width else
              '%s of LOAD / b, b = %%g mm (quarter model: modelled width = half the specimen width)' % rfd) % p.width
    else:
        fw = '%s of LOAD (plane strain, unit thickness)' % rfd
    w('** peel force per unit width: ' + fw)
    w('*NODE')
    for iz, z in enumerate(zc):
        for iy, y in enumerate(ys):
            for ix in range(nxt + 1):
                x, zz = coat_xz(ix, z)
                if three_d:
                    w('%d, %.9g, %.9g, %.9g' % (cid(ix, iy, iz), x, y, zz))
                else:
                    w('%d, %.9g, %.9g' % (cid(ix, iy, iz), x, zz))
    for iz, z in enumerate(zs):
        for iy, y in enumerate(ys):
            for ix in range(nbx + 1):
                x = xs[ix]
                if three_d:
                    w('%d, %.9g, %.9g, %.9g' % (sid(ix, iy, iz), x, y, z))
                else:
                    w('%d, %.9g, %.9g' % (sid(ix, iy, iz), x, z))

    etype = ('C3D8' if three_d else 'CPE4') + ('I' if p.incompatible else '')
    csteel = 'C3D8' if three_d else 'CPE4'   # the elastic steel keeps the plain element (no bending to lock)
    info['element'] = etype
    eid = 0
    coat_el, steel_el, coh_el = [], [], []
    cont = []
    ny_el = max(1, len(ys) - 1) if three_d else 1

    def solid(idf, ix, iy, iz):
        if three_d:
            return [idf(ix, iy, iz), idf(ix + 1, iy, iz), idf(ix + 1, iy + 1, iz), idf(ix, iy + 1, iz),
                    idf(ix, iy, iz + 1), idf(ix + 1, iy, iz + 1), idf(ix + 1, iy + 1, iz + 1),
                    idf(ix, iy + 1, iz + 1)]
        return [idf(ix, 0, iz), idf(ix + 1, 0, iz), idf(ix + 1, 0, iz + 1), idf(ix, 0, iz + 1)]

    w('*ELEMENT, TYPE=%s, ELSET=COATING' % etype)
    for iz in range(p.nz):
        for iy in range(ny_el):
            for ix in range(nxt):
                eid += 1
                coat_el.append(eid)
                w('%d, %s' % (eid, ', '.join(str(n) for n in solid(cid, ix, iy, iz))))
    if not p.rigid_substrate:
        w('*ELEMENT, TYPE=%s, ELSET=SUBSTRATE' % csteel)
        for iz in range(nzs):
            for iy in range(ny_el):
                for ix in range(nbx):
                    eid += 1
                    steel_el.append(eid)
                    w('%d, %s' % (eid, ', '.join(str(n) for n in solid(sid, ix, iy, iz))))
    # cohesive layer: bottom face = substrate top (iz = nzs), top face = coating bottom (iz = 0)
    nprops, njprops = 3, 2
    if three_d:
        w('*USER ELEMENT, TYPE=U1, NODES=8, COORDINATES=3, PROPERTIES=%d, I PROPERTIES=%d, VARIABLES=%d, UNSYMM'
          % (nprops, njprops, 4 * UEL_NSVARS_PER_IP))
        w('1, 2, 3')
        w('**LDFCZ BUILTIN, UEL=LDF')
        w(LDFCZ_SVARS_3D)
        w('*ELEMENT, TYPE=U1, ELSET=COHESIVE')
    else:
        w('*USER ELEMENT, TYPE=U2, NODES=4, COORDINATES=2, PROPERTIES=%d, I PROPERTIES=%d, VARIABLES=%d, UNSYMM'
          % (nprops, njprops, 2 * UEL_NSVARS_PER_IP))
        w('1, 2')
        w('**LDFCZ BUILTIN, UEL=LDF')
        w(LDFCZ_SVARS_2D)
        w('*ELEMENT, TYPE=U2, ELSET=COHESIVE')
    for iy in range(ny_el):
        for ix in range(nbx):
            eid += 1
            coh_el.append(eid)
            if three_d:
                bot = [sid(ix, iy, nzs), sid(ix + 1, iy, nzs), sid(ix + 1, iy + 1, nzs), sid(ix, iy + 1, nzs)]
                top = [cid(ix, iy, 0), cid(ix + 1, iy, 0), cid(ix + 1, iy + 1, 0), cid(ix, iy + 1, 0)]
                conn = bot + top
            else:
                conn = [sid(ix, 0, nzs), sid(ix + 1, 0, nzs), cid(ix + 1, 0, 0), cid(ix, 0, 0)]
            w('%d, %s' % (eid, ', '.join(str(n) for n in conn)))
    w('*UEL PROPERTY, ELSET=COHESIVE')
    w('%.9g, %.9g, %.9g, %d, %d' % (p.phi, delta, p.kc, p.unloading, 1))

    # ---- node sets
    def write_set(name, ids):
        w('*NSET, NSET=%s' % name)
        for k in range(0, len(ids), 16):
            w(', '.join(str(i) for i in ids[k:k + 16]))
    load = [cid(nxt, iy, iz) for iz in range(p.nz + 1) for iy in range(nyn)]
    write_set('LOAD', load)
    if p.rigid_substrate:
        hold = [sid(ix, iy, 0) for iy in range(nyn) for ix in range(nbx + 1)]
    else:
        hold = [sid(0, iy, iz) for iz in range(nzs + 1) for iy in range(nyn)]
    write_set('HOLD', hold)
    front = [cid(nbx, iy, 0) for iy in range(nyn)]
    write_set('FRONT0', front)
    if p.edge_fixed_y:
        yedge = [cid(ix, nyn - 1, iz) for iz in range(p.nz + 1) for ix in range(nxt + 1)]
        if not p.rigid_substrate:
            yedge += [sid(ix, nyn - 1, iz) for iz in range(nzs + 1) for ix in range(nbx + 1)]
        write_set('YEDGE', yedge)
    if three_d and not p.full_width:
        ysym = [cid(ix, 0, iz) for iz in range(p.nz + 1) for ix in range(nxt + 1)]
        ysym += [sid(ix, 0, iz) for iz in range(nzs + 1) for ix in range(nbx + 1)]
        write_set('YSYM', ysym)

    w('*SOLID SECTION, ELSET=COATING, MATERIAL=PET')
    if not three_d:
        w('1.0')
    if not p.rigid_substrate:
        w('*SOLID SECTION, ELSET=SUBSTRATE, MATERIAL=STEEL')
        if not three_d:
            w('1.0')
    w('*MATERIAL, NAME=PET')
    pet = pet_constants(p.pet) + ([p.dgamma_max] if p.dgamma_max > 0.0 else [])
    w('**LDFCZ BUILTIN, UMAT=LEONOV')
    w('*USER MATERIAL, CONSTANTS=%d, UNSYMM' % len(pet))
    w(', '.join('%.9g' % v for v in pet[:8]))
    w(', '.join('%.9g' % v for v in pet[8:]))
    w('*DEPVAR')
    w('%d' % LEONOV_NSTATV)
    w('**LDFCZ STATEV, MATERIAL=PET, PLASTIC STRAIN=7')
    if not p.rigid_substrate:
        w('*MATERIAL, NAME=STEEL')
        w('*ELASTIC')
        w('%.9g, %.9g' % STEEL)
    w('*BOUNDARY')
    w('HOLD, ENCASTRE')
    if three_d and not p.full_width:
        w('YSYM, YSYMM')
    if p.edge_fixed_y:
        w('YEDGE, 2, 2')

    period = p.u_total / p.rate
    dt = p.du / p.rate
    ninc = int(math.ceil(p.u_total / p.du - 1e-9))
    info.update({'period_s': period, 'dt_s': dt, 'increments': ninc})
    # INC only caps runaway runs: the UMAT cuts increments to keep the plastic strain increment below 0.05, which
    # on fine meshes means increments far below --du (about 0.05 um at l_e = 2.5 um)
    w('*STEP, NLGEOM=YES, INC=%d%s' % (50 * ninc + 1000, ', EXTRAPOLATION=NO' if p.no_extrapolation else ''))
    if peel:
        w('pull the lifted flap end by %g mm along %g degrees (%s grip) at %g mm/s with %g mm per increment'
          % (p.u_total, p.peel_angle, p.grip, p.rate, p.du))
    else:
        w('pull the flap end: u_x = %g mm at %g mm/s with %g mm per increment' % (p.u_total, p.rate, p.du))
    w('*STATIC')
    w('%.9g, %.9g, %.9g, %.9g' % (dt, period, dt * p.dt_min_ratio, dt))
    w('*BOUNDARY')
    if not peel:
        w('LOAD, 1, 1, %.9g' % p.u_total)
    elif p.grip == 'carriage':
        w('LOAD, %d, %d, %.9g' % (zdof, zdof, p.u_total))
    else:
        w('LOAD, 1, 1, %.9g' % (p.u_total * pull_dir[0]))
        w('LOAD, %d, %d, %.9g' % (zdof, zdof, p.u_total * pull_dir[1]))
    w('*OUTPUT, FIELD, FREQUENCY=%d' % p.field_frequency)
    w('*NODE OUTPUT')
    w('U, RF')
    w('*ELEMENT OUTPUT')
    w('S, SDV')
    w('*NODE PRINT, NSET=LOAD, TOTALS=YES')
    w('RF1, RF%d, U1, U%d' % (zdof, zdof) if peel else 'RF1, U1, U2')
    w('*END STEP')

    nel = eid
    ndof = (ncoat + (nsub if not p.rigid_substrate else (nbx + 1) * nyn)) * (3 if three_d else 2)
    info.update({'nodes': ncoat + nsub, 'elements': nel, 'coating_elements': len(coat_el),
                 'substrate_elements': len(steel_el), 'cohesive_elements': len(coh_el), 'dofs': ndof})
    return '\n'.join(out) + '\n', info


def pet_constants(overrides):
    """The PET constants (PROPS order of docs/umat.md): Table 1, or the set an item names (table1, alt), with the
    NAME=VALUE items applied in order."""
    pet = list(PET_TABLE1)
    for item in overrides or []:
        if item in PET_SETS:
            pet = list(PET_SETS[item])
            continue
        name, _, value = item.partition('=')
        if name not in PET_NAMES:
            raise SystemExit('peel_deck: --pet %s: unknown PET constant %r (one of %s)' % (item, name,
                                                                                     ', '.join(PET_NAMES)))
        try:
            pet[PET_NAMES.index(name)] = float(value)
        except ValueError:
            raise SystemExit('peel_deck: --pet %s: %r is not a number' % (item, value))
    return pet


def parser():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    g = ap.add_argument_group('scene')
    g.add_argument('--3d', dest='three_d', action='store_true', help='3D quarter model (C3D8 + U1); default plane strain')
    g.add_argument('--rigid-substrate', action='store_true',
                   help='no steel elements: the cohesive bottom face is fixed (simplification)')
    g.add_argument('--coating', type=float, default=0.030, help='coating thickness h_c (mm), default 0.030')
    g.add_argument('--substrate', type=float, default=0.210, help='steel thickness h_s (mm), default 0.210')
    g.add_argument('--bonded', type=float, default=0.30, help='bonded length L_b (mm), default 0.30')
    g.add_argument('--flap', type=float, default=0.020,
                   help='pre-delaminated flap length a_0 beyond the substrate edge (mm), default 0.020')
    g.add_argument('--width', type=float, default=0.040,
                   help='3D: modelled width b = half the specimen width (mm), default 0.040')
    g.add_argument('--full-width', action='store_true',
                   help='3D: model y in [-b, b] without the YSYMM plane (checks the quarter model; 2 n_y elements)')
    g.add_argument('--edge-fixed-y', action='store_true',
                   help='3D quarter: hold the free edge y = b in y (u_y = 0; node set YEDGE): no lateral contraction '
                   'at the edge (the plane-strain/3D gap study)')
    g.add_argument('--reading', choices=('bridge', 'peel'), default='bridge',
                   help='Fig. 10 reading: bridge (A, default: the flap bridges the broken substrate and is pulled '
                   'along x) or peel (B: the pre-delaminated flap is lifted and pulled at --peel-angle)')
    g.add_argument('--peel-angle', type=float, default=90.0,
                   help='reading B: angle of the lifted flap and of the pull from the interface (degrees, 0-180], '
                   'default 90')
    g.add_argument('--bend-radius', type=float, default=0.0,
                   help='reading B: radius of the flap\'s bottom face in its initial bend (mm, > h_c); '
                   'default 1.5 h_c')
    g.add_argument('--grip', choices=('fixed', 'carriage'), default='fixed',
                   help='reading B: fixed (default): the flap end moves by u_total along the peel direction, '
                   'both components prescribed; carriage (90 degrees only): u_z prescribed, u_x free')
    g.add_argument('--pet', action='append', default=[], metavar='SET|NAME=VALUE',
                   help='PET constants: a set, table1 (as printed, default) or alt (same aged viscosity '
                   'eta_0r exp(S_a), S_a halved: a rejuvenated state with a flow stress; docs/scenes.md), and/or '
                   'NAME=VALUE replacing one constant (names: %s); repeatable, applied in order'
                   % ', '.join(PET_NAMES))
    g.add_argument('--dgamma-max', type=float, default=0.0,
                   help='PET accuracy bound on the plastic strain increment, PROPS(11); 0 = UMAT default 0.05')
    g = ap.add_argument_group('interface (LDF, docs/uel.md)')
    g.add_argument('--phi', type=float, default=0.2, help='work of separation (N/mm), default 0.2 (200 J/m^2)')
    g.add_argument('--tmax', type=float, default=20.0, help='T_max (MPa), default 20; delta = phi/(e T_max)')
    g.add_argument('--delta', type=float, default=0.0, help='characteristic opening (mm); overrides --tmax')
    g.add_argument('--kc', type=float, default=0.0, help='contact stiffness PROPS(3) (MPa), 0 = UEL default phi/delta')
    g.add_argument('--unloading', type=int, default=2, choices=(1, 2, 3),
                   help='JPROPS(1): 1 reversible, 2 elastic damage (default), 3 plastic (paper Fig. 6)')
    g = ap.add_argument_group('mesh')
    g.add_argument('--le', type=float, default=0.010, help='element length in the fine region (mm), default 0.010')
    g.add_argument('--nx', type=int, default=0, help='elements over the fine region (overrides --le)')
    g.add_argument('--fine-length', type=float, default=0.10,
                   help='length of the fine region ahead of the initial front (mm), default 0.10')
    g.add_argument('--nz', type=int, default=3, help='elements over the coating thickness, default 3')
    g.add_argument('--ny', type=int, default=4, help='3D: elements over the width, default 4')
    g.add_argument('--incompatible', action='store_true',
                   help='coating elements with incompatible modes, CPE4I / C3D8I (free of shear locking in bending; '
                   'docs/elements.md), instead of CPE4 / C3D8')
    g.add_argument('--no-coarse', action='store_true', help='uniform fine mesh over the whole bonded length')
    g.add_argument('--coarse-ratio', type=float, default=1.5, help='growth ratio of the far field, default 1.5')
    g.add_argument('--coarse-max', type=float, default=0.05, help='largest far-field element (mm), default 0.05')
    g.add_argument('--steel-first', type=float, default=0.0,
                   help='steel layer at the interface (mm); default min(h_c/n_z, 2 l_e)')
    g.add_argument('--steel-ratio', type=float, default=2.0, help='steel layer growth ratio, default 2.0')
    g = ap.add_argument_group('loading')
    g.add_argument('--u-total', type=float, default=0.050, help='total pull u_x (mm), default 0.050')
    g.add_argument('--du', type=float, default=0.0003,
                   help='pull per increment (mm/inc), default 0.0003; the UMAT cuts back where it needs to')
    g.add_argument('--rate', type=float, default=0.001, help='pull rate (mm/s), default 0.001 (1 um/s)')
    g.add_argument('--no-extrapolation', action='store_true',
                   help='*STEP, EXTRAPOLATION=NO: every increment starts from the converged state (default: linear)')
    g.add_argument('--dt-min-ratio', type=float, default=1e-3, help='minimum increment / initial, default 1e-3')
    g.add_argument('--field-frequency', type=int, default=20, help='*OUTPUT, FIELD frequency, default 20')
    ap.add_argument('-o', '--output', default='-', help='deck file (default: standard output)')
    ap.add_argument('--info', action='store_true', help='print the mesh summary (JSON) on standard error')
    return ap


def check(p):
    for name in ('coating', 'substrate', 'bonded', 'width', 'phi', 'tmax', 'le', 'fine_length', 'u_total', 'du',
                 'rate', 'coarse_max'):
        if getattr(p, name) <= 0.0:
            raise SystemExit('peel_deck: --%s must be positive' % name.replace('_', '-'))
    if p.flap < 0.0:
        raise SystemExit('peel_deck: --flap must not be negative')
    if p.nz < 1 or p.ny < 1 or p.nx < 0:
        raise SystemExit('peel_deck: --nz, --ny must be >= 1')
    if p.edge_fixed_y and (not p.three_d or p.full_width):
        raise SystemExit('peel_deck: --edge-fixed-y needs the 3D quarter model (--3d without --full-width)')
    if p.du > p.u_total:
        raise SystemExit('peel_deck: --du larger than --u-total')
    if p.reading == 'peel':
        if not 0.0 < p.peel_angle <= 180.0:
            raise SystemExit('peel_deck: --peel-angle must be in (0, 180] degrees')
        r = p.bend_radius if p.bend_radius else 1.5 * p.coating
        if r <= p.coating:
            raise SystemExit('peel_deck: --bend-radius must exceed the coating thickness %g mm' % p.coating)
        if p.flap < r * math.radians(p.peel_angle):
            raise SystemExit('peel_deck: --flap %g mm is shorter than the bend (R theta = %g mm): lengthen it'
                             % (p.flap, r * math.radians(p.peel_angle)))
        if p.grip == 'carriage' and p.peel_angle != 90.0:
            raise SystemExit('peel_deck: --grip carriage needs --peel-angle 90')
    elif p.grip != 'fixed' or p.bend_radius or p.peel_angle != 90.0:
        raise SystemExit('peel_deck: --peel-angle, --bend-radius, --grip belong to --reading peel')
    pet_constants(p.pet)


def main(argv=None):
    p = parser().parse_args(argv)
    check(p)
    text, info = build(p)
    if p.output == '-':
        sys.stdout.write(text)
    else:
        with open(p.output, 'w') as f:
            f.write(text)
    if p.info:
        sys.stderr.write(json.dumps(info, sort_keys=True) + '\n')
    return 0


if __name__ == '__main__':
    from ldfcz_tools.cli import run
    sys.exit(run('peel_deck'))
