#!/usr/bin/env python3
"""Writes the malformed decks of *PRE-TENSION SECTION (docs/host.md, "Pre-tension sections") into
decks/bad/bad_pretension_<name>.inp: two C3D8 cubes stacked along z, cut between them by the top face of the lower
one (surface CUT), pre-tension node 20; each deck with one defect.

Each deck's first line is `** EXPECT line=N keyword=*KW`: the line and keyword the error message must name
(check_run.py --bad reads it; the run must end with exit status 2). Run from anywhere:
python3 tests/regression/make_pretension_bad_decks.py
"""
import os

BASE = """*HEADING
{title}
*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
9, 0., 0., 2.
10, 1., 0., 2.
11, 1., 1., 2.
12, 0., 1., 2.
20, 0., 0., 0.
*ELEMENT, TYPE=C3D8, ELSET=BOLT
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 5, 6, 7, 8, 9, 10, 11, 12
*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
9, 10, 11, 12
*SOLID SECTION, ELSET=BOLT, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
1000., 0.3
*SURFACE, NAME=CUT
1, S2
*SURFACE, NAME=FREE
2, S2
*PRE-TENSION SECTION, SURFACE=CUT, NODE=20
*BOUNDARY
BOTTOM, ENCASTRE
TOP, ENCASTRE
*STEP
*STATIC
*CLOAD
20, 1, 10.
*END STEP
"""

SECTION = "*PRE-TENSION SECTION, SURFACE=CUT, NODE=20"

# name, title, [(text replaced, replacement), ...], keyword the message must name, start of the offending line
CASES = [
    ("surface_undefined", "a section on an undefined surface",
     [(SECTION, "*PRE-TENSION SECTION, SURFACE=NOPE, NODE=20")], "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("surface_missing", "a section without SURFACE=", [(SECTION, "*PRE-TENSION SECTION, NODE=20")],
     "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("element", "a truss or beam section (ELEMENT=)", [(SECTION, "*PRE-TENSION SECTION, ELEMENT=1, NODE=20")],
     "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("follower", "FOLLOWER (a normal that turns)", [(SECTION, SECTION + ", FOLLOWER")], "*PRE-TENSION SECTION",
     "*PRE-TENSION SECTION"),
    ("node_missing", "a section without NODE=", [(SECTION, "*PRE-TENSION SECTION, SURFACE=CUT")],
     "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("node_undefined", "an undefined pre-tension node", [(SECTION, "*PRE-TENSION SECTION, SURFACE=CUT, NODE=99")],
     "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("node_set_size", "a pre-tension node set of four nodes",
     [(SECTION, "*PRE-TENSION SECTION, SURFACE=CUT, NODE=TOP")], "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("node_not_free", "a pre-tension node that belongs to an element",
     [(SECTION, "*PRE-TENSION SECTION, SURFACE=CUT, NODE=9")], "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("node_twice", "two sections on one pre-tension node", [("*SURFACE, NAME=FREE\n2, S2", "*SURFACE, NAME=LOW\n1, S1"),
     (SECTION, SECTION + "\n*PRE-TENSION SECTION, SURFACE=LOW, NODE=20")], "*PRE-TENSION SECTION",
     "*PRE-TENSION SECTION, SURFACE=LOW"),
    ("nodes_shared", "two sections sharing their nodes", [("20, 0., 0., 0.", "20, 0., 0., 0.\n21, 0., 0., 0."),
     (SECTION, SECTION + "\n*PRE-TENSION SECTION, SURFACE=CUT, NODE=21")], "*PRE-TENSION SECTION",
     "*PRE-TENSION SECTION, SURFACE=CUT, NODE=21"),
    ("not_a_cut", "a section on the mesh's free face (nothing on its other side)",
     [(SECTION, "*PRE-TENSION SECTION, SURFACE=FREE, NODE=20")], "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("both_sides", "a section of faces of elements on both sides of the cut", [("*SURFACE, NAME=CUT\n1, S2",
     "*SURFACE, NAME=CUT\n1, S2\n2, S1"), (SECTION, SECTION + "\n0., 0., 1.")], "*PRE-TENSION SECTION",
     "*PRE-TENSION SECTION"),
    ("normal_zero", "a zero normal", [(SECTION, SECTION + "\n0., 0., 0.")], "*PRE-TENSION SECTION", "0., 0., 0."),
    ("normal_text", "a normal that is not a number", [(SECTION, SECTION + "\n0., 0., up")], "*PRE-TENSION SECTION",
     "0., 0., up"),
    ("normal_two_lines", "two data lines", [(SECTION, SECTION + "\n0., 0., 1.\n0., 0., 1.")], "*PRE-TENSION SECTION",
     "0., 0., 1.\n0., 0., 1."),
    ("in_step", "a section inside a step", [(SECTION + "\n", ""), ("20, 1, 10.", "20, 1, 10.\n" + SECTION)],
     "*PRE-TENSION SECTION", "*PRE-TENSION SECTION"),
    ("load_dof2", "a force on dof 2 of the pre-tension node (it has dof 1 only)", [("20, 1, 10.", "20, 2, 10.")],
     "*CLOAD", "20, 2, 10."),
]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    outdir = os.path.join(here, "..", "..", "decks", "bad")
    for name, title, edits, kw, marker in CASES:
        deck = BASE.format(title="malformed deck: " + title)
        for old, new in edits:
            assert old in deck, (name, old)
            deck = deck.replace(old, new, 1)
        lines = deck.split("\n")
        first = marker.split("\n")
        hits = [i for i, l in enumerate(lines) if l.startswith(first[0])]
        assert hits, name
        # a marker of two equal lines names the second
        line = hits[len(first) - 1]
        deck = "** EXPECT line=%d keyword=%s\n" % (line + 2, kw) + deck
        with open(os.path.join(outdir, "bad_pretension_%s.inp" % name), "w") as f:
            f.write(deck)


if __name__ == "__main__":
    main()
