#!/usr/bin/env python3
"""Writes the malformed decks of *COUPLING, *KINEMATIC, *DISTRIBUTING, CENTRIF/ROTA, *MODEL CHANGE, *TIME POINTS,
*NODE PRINT GLOBAL, *EQUATION over node sets and *INITIAL CONDITIONS PLASTIC STRAIN/USER (docs/host.md) into
decks/bad/bad_<name>.inp, from the single-element deck of make_bad_decks.py, each with one defect.

Each deck's first line is `** EXPECT line=N keyword=*KW`: the line and keyword the error message must name
(check_run.py --bad reads it; the run must end with exit status 2). Run from anywhere:
python3 tests/regression/make_constraint_bad_decks.py
"""
import os

from make_bad_decks import BASE

REF = "8, 0., 1., 1.\n9, 0.5, 0.5, 2.\n*NSET, NSET=REF\n9"
SURF = "*SURFACE, NAME=TS\nCUBE, S2\n"
STEP = "*STEP, NLGEOM=YES"
COUPLING = SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=REF, SURFACE=TS\n"

# name, title, [(text replaced, replacement), ...], keyword the message must name, start of the offending line
CASES = [
    ("coupling_no_type", "*COUPLING without *KINEMATIC or *DISTRIBUTING", [("8, 0., 1., 1.", REF),
     (STEP, COUPLING + STEP)], "*COUPLING", "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_surface_undefined", "*COUPLING on an undefined surface", [("8, 0., 1., 1.", REF),
     (STEP, "*COUPLING, CONSTRAINT NAME=C, REF NODE=REF, SURFACE=NOPE\n*KINEMATIC\n" + STEP)], "*COUPLING",
     "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_ref_undefined", "*COUPLING with an undefined reference node",
     [(STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=99, SURFACE=TS\n*KINEMATIC\n" + STEP)], "*COUPLING",
     "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_ref_set", "*COUPLING whose REF NODE set holds four nodes",
     [(STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=BOTTOM, SURFACE=TS\n*KINEMATIC\n" + STEP)],
     "*COUPLING", "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_ref_missing", "*COUPLING without REF NODE",
     [(STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, SURFACE=TS\n*KINEMATIC\n" + STEP)], "*COUPLING",
     "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_orientation", "*COUPLING, ORIENTATION=", [("8, 0., 1., 1.", REF),
     (STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=REF, SURFACE=TS, ORIENTATION=O\n*KINEMATIC\n" + STEP)],
     "*COUPLING", "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_ref_on_surface", "*COUPLING whose reference node is a node of the surface",
     [(STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=5, SURFACE=TS\n*KINEMATIC\n" + STEP)], "*COUPLING",
     "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_radius", "*COUPLING with an influence radius holding no node", [("8, 0., 1., 1.", REF),
     (STEP, SURF + "*COUPLING, CONSTRAINT NAME=C, REF NODE=REF, SURFACE=TS, INFLUENCE RADIUS=0.1\n*KINEMATIC\n"
      + STEP)], "*COUPLING", "*COUPLING, CONSTRAINT NAME=C"),
    ("coupling_nlgeom_rotation", "a kinematic coupling with a free reference rotation under NLGEOM",
     [("8, 0., 1., 1.", REF), ("TOP, 3, 3, 0.1", "REF, 3, 3, 0.1"), (STEP, COUPLING + "*KINEMATIC\n" + STEP)],
     "*COUPLING", "*COUPLING, CONSTRAINT NAME=C"),
    ("kinematic_alone", "*KINEMATIC without a *COUPLING", [(STEP, "*KINEMATIC\n" + STEP)], "*KINEMATIC",
     "*KINEMATIC"),
    ("kinematic_dof", "*KINEMATIC with dofs 1..7", [("8, 0., 1., 1.", REF),
     (STEP, COUPLING + "*KINEMATIC\n1, 7\n" + STEP)], "*KINEMATIC", "1, 7"),
    ("kinematic_rotations_only", "*KINEMATIC of rotations only (continuum nodes have none)",
     [("8, 0., 1., 1.", REF), (STEP, COUPLING + "*KINEMATIC\n4, 6\n" + STEP)], "*KINEMATIC", "*KINEMATIC"),
    ("cload_node_without_element", "a force on a node of no element (it would act on nothing)",
     [("8, 0., 1., 1.", "8, 0., 1., 1.\n9, 3., 3., 3."), ("*END STEP", "*CLOAD\n9, 1, 1.0\n*END STEP")], "*CLOAD",
     "9, 1, 1.0"),
    ("distributing_weighting", "*DISTRIBUTING, WEIGHTING METHOD=SQUARE", [("8, 0., 1., 1.", REF),
     (STEP, COUPLING + "*DISTRIBUTING, WEIGHTING METHOD=SQUARE\n" + STEP)], "*DISTRIBUTING",
     "*DISTRIBUTING, WEIGHTING"),
    ("distributing_structural", "*DISTRIBUTING, COUPLING=STRUCTURAL", [("8, 0., 1., 1.", REF),
     (STEP, COUPLING + "*DISTRIBUTING, COUPLING=STRUCTURAL\n" + STEP)], "*DISTRIBUTING",
     "*DISTRIBUTING, COUPLING"),
    ("boundary_rotation_user", "*BOUNDARY, USER on a rotation", [("TOP, 3, 3, 0.1", "TOP, 3, 3, 0.1\n"
     "*BOUNDARY, USER\nTOP, 4, 4")], "*BOUNDARY", "TOP, 4, 4"),
    ("centrif_density", "CENTRIF without *DENSITY", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*DLOAD\nCUBE, CENTRIF, 100., 0., 0., 0., 0., 0., 1.")], "*DLOAD", "CUBE, CENTRIF"),
    ("centrif_axis", "CENTRIF in a 3D model without the axis direction", [("1000., 0.3\n",
     "1000., 0.3\n*DENSITY\n1e-9\n"), ("TOP, 3, 3, 0.1", "TOP, 3, 3, 0.1\n*DLOAD\nCUBE, CENTRIF, 100.")], "*DLOAD",
     "CUBE, CENTRIF"),
    ("rota_fields", "ROTA with a tenth field", [("1000., 0.3\n", "1000., 0.3\n*DENSITY\n1e-9\n"),
     ("TOP, 3, 3, 0.1", "TOP, 3, 3, 0.1\n*DLOAD\nCUBE, ROTA, 1., 0., 0., 0., 0., 0., 1., 5.")], "*DLOAD",
     "CUBE, ROTA"),
    ("model_change_model_data", "*MODEL CHANGE outside a step", [(STEP, "*MODEL CHANGE, REMOVE\nCUBE\n" + STEP)],
     "*MODEL CHANGE", "*MODEL CHANGE"),
    ("model_change_both", "*MODEL CHANGE with REMOVE and ADD", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*MODEL CHANGE, REMOVE, ADD\nCUBE")], "*MODEL CHANGE", "*MODEL CHANGE"),
    ("model_change_add_value", "*MODEL CHANGE, ADD= of another value than STRAIN FREE, WITH STRAIN",
     [("TOP, 3, 3, 0.1", "TOP, 3, 3, 0.1\n*MODEL CHANGE, ADD=WITH STRESS\nCUBE")], "*MODEL CHANGE", "*MODEL CHANGE"),
    ("model_change_mechstrain", "*MODEL CHANGE, MECHSTRAINTORESIDUAL (a CalculiX extension)",
     [("TOP, 3, 3, 0.1", "TOP, 3, 3, 0.1\n*MODEL CHANGE, ADD, MECHSTRAINTORESIDUAL\nCUBE")], "*MODEL CHANGE",
     "*MODEL CHANGE"),
    ("model_change_contact", "*MODEL CHANGE, TYPE=CONTACT PAIR", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nCUBE")], "*MODEL CHANGE", "*MODEL CHANGE"),
    ("model_change_undefined", "*MODEL CHANGE of an undefined element set", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*MODEL CHANGE, REMOVE\nNOPE")], "*MODEL CHANGE", "NOPE"),
    ("model_change_no_data", "*MODEL CHANGE without elements", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*MODEL CHANGE, REMOVE")], "*MODEL CHANGE", "*MODEL CHANGE"),
    ("model_change_element", "*MODEL CHANGE of an undefined element", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*MODEL CHANGE, REMOVE\n7")], "*MODEL CHANGE", "*MODEL CHANGE"),
    ("time_points_order", "*TIME POINTS not ascending", [(STEP, "*TIME POINTS, NAME=TP\n0.5, 0.2\n" + STEP)],
     "*TIME POINTS", "*TIME POINTS"),
    ("time_points_generate", "*TIME POINTS, GENERATE ending before it starts",
     [(STEP, "*TIME POINTS, NAME=TP, GENERATE\n1., 0., 0.1\n" + STEP)], "*TIME POINTS", "1., 0., 0.1"),
    ("time_points_undefined", "*OUTPUT, TIME POINTS= naming no *TIME POINTS", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*OUTPUT, FIELD, TIME POINTS=NOPE")], "*OUTPUT", "*OUTPUT, FIELD, TIME POINTS"),
    ("time_points_frequency", "*OUTPUT with TIME POINTS and FREQUENCY",
     [(STEP, "*TIME POINTS, NAME=TP\n0.5\n" + STEP), ("TOP, 3, 3, 0.1",
      "TOP, 3, 3, 0.1\n*OUTPUT, FIELD, TIME POINTS=TP, FREQUENCY=2")], "*OUTPUT", "*OUTPUT, FIELD, TIME POINTS"),
    ("time_points_in_step", "*TIME POINTS inside a step", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*TIME POINTS, NAME=TP\n0.5")], "*TIME POINTS", "*TIME POINTS"),
    ("node_print_global", "*NODE PRINT, GLOBAL=MAYBE", [("TOP, 3, 3, 0.1",
     "TOP, 3, 3, 0.1\n*NODE PRINT, NSET=TOP, GLOBAL=MAYBE\nU")], "*NODE PRINT", "*NODE PRINT, NSET=TOP, GLOBAL"),
    ("equation_set_sizes", "*EQUATION over node sets of different sizes",
     [(STEP, "*NSET, NSET=TWO\n6, 7\n*EQUATION\n2\nTOP, 1, 1., TWO, 1, -1.\n" + STEP)], "*EQUATION",
     "TOP, 1, 1., TWO"),
    ("equation_node_then_set", "*EQUATION: a single first node, then a node set",
     [(STEP, "*NSET, NSET=TWO\n6, 7\n*EQUATION\n2\n5, 1, 1.\nTWO, 1, -1.\n" + STEP)], "*EQUATION", "TWO, 1, -1."),
    ("initial_plastic_strain", "*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN (no plastic material)",
     [(STEP, "*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN\nCUBE, 1, 0.01, 0., 0., 0., 0., 0.\n" + STEP)],
     "*INITIAL CONDITIONS", "*INITIAL CONDITIONS, TYPE=PLASTIC"),
    ("initial_user", "*INITIAL CONDITIONS, TYPE=SOLUTION, USER without a user library holding SDVINI",
     [(STEP, "*INITIAL CONDITIONS, TYPE=SOLUTION, USER\n" + STEP)], "*INITIAL CONDITIONS",
     "*INITIAL CONDITIONS, TYPE=SOLUTION, USER"),
    ("initial_user_temperature", "*INITIAL CONDITIONS, TYPE=TEMPERATURE, USER (no user routine for it)",
     [(STEP, "*INITIAL CONDITIONS, TYPE=TEMPERATURE, USER\n" + STEP)], "*INITIAL CONDITIONS",
     "*INITIAL CONDITIONS, TYPE=TEMPERATURE, USER"),
    ("initial_user_data", "*INITIAL CONDITIONS, TYPE=STRESS, USER with a data line",
     [(STEP, "*INITIAL CONDITIONS, TYPE=STRESS, USER\nCUBE, 1., 0., 0.\n" + STEP)], "*INITIAL CONDITIONS",
     "CUBE, 1., 0., 0."),
]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    outdir = os.path.join(here, "..", "..", "decks", "bad")
    for name, title, edits, kw, marker in CASES:
        deck = BASE.format(title="malformed deck: " + title)
        for old, new in edits:
            assert old in deck, (name, old)
            deck = deck.replace(old, new, 1)
        hits = [i for i, l in enumerate(deck.split("\n")) if l.startswith(marker)]
        assert hits, name
        deck = "** EXPECT line=%d keyword=%s\n" % (hits[0] + 2, kw) + deck
        with open(os.path.join(outdir, "bad_%s.inp" % name), "w") as f:
            f.write(deck)


if __name__ == "__main__":
    main()
