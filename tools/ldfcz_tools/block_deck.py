"""The elastic block of the linear-algebra benchmarks (benchmarks/bench_calculix.py, bench_omp_wait.py) and of the
tests that need large fronts or a first iteration to watch (tests/regression/check_first_iteration.py,
check_threads.py): nx x ny x nz C3D8 elements of 1 mm, steel-like elasticity, NLGEOM, fixed increments of pull.
"""


NX, NY, NZ = 40, 40, 10     # elements along x, y, z (1 mm each) of the benchmark block


def block_deck(increments, du, nx=NX, ny=NY, nz=NZ, nlgeom=True, extrapolation=None):
    """The deck text: an nx x ny x nz block of 1 mm C3D8 elements, clamped at x = 0, increments fixed increments of
    du mm of pull on the face x = nx (u2 = u3 = 0 there). extrapolation: None (the default, LINEAR) or 'NO'.
    (Also the deck of the tests deck_first_iteration and robust_threads_agree.)"""
    def node_id(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)
    lines = ['*HEADING', '%dx%dx%d C3D8 elastic block, clamped at x=0, pulled at x=%d (tools/ldfcz_tools/block_deck.py)'
             % (nx, ny, nz, nx), '*NODE, NSET=NALL']
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                lines.append('%d, %.1f, %.1f, %.1f' % (node_id(i, j, k), i, j, k))
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=EALL')
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                n = [node_id(i, j, k), node_id(i + 1, j, k), node_id(i + 1, j + 1, k), node_id(i, j + 1, k),
                     node_id(i, j, k + 1), node_id(i + 1, j, k + 1), node_id(i + 1, j + 1, k + 1),
                     node_id(i, j + 1, k + 1)]
                lines.append('%d, %s' % (e, ', '.join(map(str, n))))

    def nset(name, i):
        ids = [node_id(i, j, k) for k in range(nz + 1) for j in range(ny + 1)]
        out = ['*NSET, NSET=%s' % name]
        for a in range(0, len(ids), 16):
            out.append(', '.join(map(str, ids[a:a + 16])))
        return out
    lines += nset('FIXED', 0) + nset('LOAD', nx)
    step = '*STEP, NLGEOM=%s, INC=%d' % ('YES' if nlgeom else 'NO', increments + 10)
    if extrapolation:
        step += ', EXTRAPOLATION=%s' % extrapolation
    lines += ['*MATERIAL, NAME=STEEL', '*ELASTIC', '210000., 0.3', '*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL',
              '*BOUNDARY', 'FIXED, 1, 3, 0.', 'LOAD, 2, 3, 0.', step, '*STATIC, DIRECT',
              '1.0, %d.0' % increments, '*BOUNDARY', 'LOAD, 1, 1, %.6g' % (du * increments),
              '*NODE PRINT, NSET=LOAD, TOTALS=YES', 'RF', '*END STEP']
    return '\n'.join(lines) + '\n'
