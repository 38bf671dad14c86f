"""Invariants of the deck generators of ldfcz_tools (no solver): every element's nodes exist and are distinct, the
counts the generators report are those of the text, node sets hold existing nodes, and geometry the decks promise
(a block's node grid, a ring's radii, the peel scene's sizes) holds."""
import math
import os
import tempfile
import unittest

from ldfcz_tools import block_deck, dcb_deck, peel_deck, ring_decks

from deck_text import read_deck

NODES_PER_TYPE = {'C3D8': 8, 'C3D8I': 8, 'C3D8R': 8, 'CPE4': 4, 'CPS4': 4, 'CPE8': 8, 'CPE8R': 8, 'C3D20': 20,
                  'C3D20R': 20, 'CAX4': 4, 'CAX8': 8, 'CAX8R': 8}


def written(writer, *args, **kw):
    """The text a deck writer (path first) writes."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, 'deck.inp')
        writer(path, *args, **kw)
        with open(path) as f:
            return f.read()


class DeckInvariants(unittest.TestCase):

    def check_mesh(self, text):
        nodes, elements, nsets = read_deck(text)
        self.assertTrue(nodes and elements)
        labels = [e[1] for e in elements]
        self.assertEqual(len(labels), len(set(labels)), 'element labels unique')
        for etype, label, conn in elements:
            self.assertTrue(set(conn) <= set(nodes), 'element %d: nodes defined' % label)
            self.assertEqual(len(conn), len(set(conn)), 'element %d: distinct nodes' % label)
            if NODES_PER_TYPE.get(etype):
                self.assertEqual(len(conn), NODES_PER_TYPE[etype], 'element %d (%s): node count' % (label, etype))
        for name, ids in nsets.items():
            self.assertTrue(ids and set(ids) <= set(nodes), 'node set %s: existing nodes' % name)
        return nodes, elements, nsets

    def test_block(self):
        # (nx+1)(ny+1)(nz+1) nodes on the 1 mm grid, nx ny nz elements, LOAD on x = nx, FIXED on x = 0
        nx, ny, nz = 5, 3, 2
        nodes, elements, nsets = self.check_mesh(block_deck.block_deck(2, 0.1, nx=nx, ny=ny, nz=nz))
        self.assertEqual(len(nodes), (nx + 1) * (ny + 1) * (nz + 1))
        self.assertEqual(len(elements), nx * ny * nz)
        self.assertEqual({nodes[n][0] for n in nsets['LOAD']}, {float(nx)})
        self.assertEqual({nodes[n][0] for n in nsets['FIXED']}, {0.0})
        self.assertEqual(len(nsets['LOAD']), (ny + 1) * (nz + 1))

    def test_rings(self):
        # nodes on a < r < b; the inner set on r = a, the outer on r = b (to the 15 digits written)
        a, b = 1.0, 2.0
        cases = [lambda: written(ring_decks.ring_deck, a, b, 4, 6, 1.0),
                 lambda: written(ring_decks.ring_deck, a, b, 4, 6, 1.0, three_d=True),
                 lambda: written(ring_decks.quadratic_ring_deck, 'CPE8', a, b, 2, 4, 1.0),
                 lambda: written(ring_decks.quadratic_ring_deck, 'C3D20', a, b, 2, 4, 1.0),
                 lambda: written(ring_decks.axisymmetric_cylinder_deck, 'CAX8', a, b, 3, 1.0)]
        for case in cases:
            nodes, elements, nsets = self.check_mesh(case())
            r = {n: math.hypot(x[0], x[1]) if elements[0][0] != 'CAX8' else x[0] for n, x in nodes.items()}
            self.assertTrue(all(a - 1e-12 <= v <= b + 1e-12 for v in r.values()))
            self.assertAlmostEqual(r[nsets['RIN'][0]], a, places=12)
            self.assertAlmostEqual(r[nsets['ROUT'][0]], b, places=12)
        # Lame: u(a) for p = 1, E = 1000, nu = 0.3, a = 1, b = 2: (1 + nu)/E ((1 - 2 nu) A a + B / a), A = 1/3,
        # B = 4/3
        self.assertAlmostEqual(ring_decks.lame(1.0, 1.0, 2.0, 1.0, 1000.0, 0.3),
                               1.3e-3 * (0.4 / 3 + 4.0 / 3), places=15)

    def test_dcb(self):
        # two arms of nx x nz elements, one cohesive element per element length beyond the pre-crack A0
        le, nz = 0.5, 2
        nodes, elements, nsets = self.check_mesh(dcb_deck.build(le, nz, 'none', 1.5))
        nx = int(round(dcb_deck.L / le))
        self.assertEqual(len([e for e in elements if e[0] == 'C3D8']), 2 * nx * nz)
        self.assertEqual(len([e for e in elements if e[0] == 'U1']), nx - int(round(dcb_deck.A0 / le)))

    def test_peel_scenes(self):
        # the counts --info reports are those of the text, for plane strain and 3D, both readings
        for args in ([], ['--3d', '--u-total', '0.002'], ['--rigid-substrate', '--reading', 'peel', '--flap', '0.1',
                                                       '--grip', 'carriage']):
            p = peel_deck.parser().parse_args(args)
            peel_deck.check(p)
            text, info = peel_deck.build(p)
            nodes, elements, nsets = self.check_mesh(text)
            self.assertEqual(info['nodes'], len(nodes), args)
            self.assertEqual(info['elements'], len(elements), args)
            self.assertEqual(info['cohesive_elements'], len([e for e in elements if e[0] in ('U1', 'U2')]), args)
            self.assertIn('LOAD', nsets)


if __name__ == '__main__':
    unittest.main()
