#!/usr/bin/env python3
"""Writes the malformed decks decks/bad/bad_<name>.inp from one valid single-element deck, each with one defect.

Each deck's first line is `** EXPECT line=N keyword=*KW`: the line and keyword the error message must name
(check_run.py --bad reads it). Run from anywhere: python3 tests/regression/make_bad_decks.py
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
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
1000., 0.3
*BOUNDARY
BOTTOM, ENCASTRE
*STEP, NLGEOM=YES
*STATIC
0.1, 1.0
*BOUNDARY
TOP, 3, 3, 0.1
*END STEP
"""

# name, title, text replaced, replacement, keyword the message must name, start of the offending line
CASES = [
    ("unknown_keyword", "an unknown keyword", "*STEP, NLGEOM=YES", "*FOOBAR, X=1\n*STEP, NLGEOM=YES",
     "*FOOBAR", "*FOOBAR"),
    ("nan_coordinate", "NaN in a node coordinate", "3, 1., 1., 0.", "3, 1., NaN, 0.", "*NODE", "3, 1., NaN"),
    ("inf_modulus", "Inf in *ELASTIC", "1000., 0.3", "Inf, 0.3", "*ELASTIC", "Inf, 0.3"),
    ("duplicate_node", "node 2 defined twice", "3, 1., 1., 0.", "2, 1., 1., 0.", "*NODE", "2, 1., 1., 0."),
    ("undefined_nset", "boundary on an undefined set", "BOTTOM, ENCASTRE", "BOTOM, ENCASTRE", "*BOUNDARY",
     "BOTOM, ENCASTRE"),
    ("wrong_node_count", "C3D8 with 7 nodes", "1, 1, 2, 3, 4, 5, 6, 7, 8", "1, 1, 2, 3, 4, 5, 6, 7", "*ELEMENT",
     "1, 1, 2, 3, 4, 5, 6, 7"),
    ("unsupported_element", "element type C3D8H", "*ELEMENT, TYPE=C3D8, ELSET=CUBE",
     "*ELEMENT, TYPE=C3D8H, ELSET=CUBE", "*ELEMENT", "*ELEMENT, TYPE=C3D8H"),
    ("cohesive_element", "element type COH3D8 (the LDF user element is the route)", "*ELEMENT, TYPE=C3D8, ELSET=CUBE",
     "*ELEMENT, TYPE=COH3D8, ELSET=CUBE", "*ELEMENT", "*ELEMENT, TYPE=COH3D8"),
    ("unsupported_parameter", "ORIENTATION on *SOLID SECTION", "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL",
     "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL, ORIENTATION=ORI", "*SOLID SECTION",
     "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL, ORIENTATION"),
    ("undefined_material", "section with an undefined material", "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL",
     "*SOLID SECTION, ELSET=CUBE, MATERIAL=ALU", "*SOLID SECTION", "*SOLID SECTION, ELSET=CUBE, MATERIAL=ALU"),
    ("bad_number", "a malformed number", "6, 1., 0., 1.", "6, 1.x, 0., 1.", "*NODE", "6, 1.x"),
    ("undefined_node", "element with an undefined node", "1, 1, 2, 3, 4, 5, 6, 7, 8",
     "1, 1, 2, 3, 4, 5, 6, 7, 99", "*ELEMENT", "1, 1, 2, 3, 4, 5, 6, 7, 99"),
    ("poisson_half", "Poisson ratio 0.5", "1000., 0.3", "1000., 0.5", "*ELASTIC", "1000., 0.5"),
    ("static_negative", "negative time in *STATIC", "0.1, 1.0\n", "-0.1, 1.0\n", "*STATIC", "-0.1, 1.0"),
    ("dload_unsupported", "*DLOAD with a load label ldfcz does not support", "*END STEP",
     "*DLOAD\n1, TRVEC, 1.0\n*END STEP", "*DLOAD", "1, TRVEC"),
    ("end_step_missing", "*END STEP missing before a second *STEP", "*END STEP\n",
     "*STEP\n*STATIC\n*END STEP\n", "*STEP", "*STEP\n"),
    ("end_step_at_end", "*END STEP missing at the end of the deck (located at the open *STEP)",
     "TOP, 3, 3, 0.1\n*END STEP\n", "TOP, 3, 3, 0.1\n", "*STEP", "*STEP, NLGEOM=YES"),
    ("keyword_typo", "a misspelt keyword (the message suggests *ELASTIC)", "*ELASTIC\n", "*ELASTC\n", "*ELASTC",
     "*ELASTC"),
    ("nlgeom_value", "NLGEOM=MAYBE", "*STEP, NLGEOM=YES", "*STEP, NLGEOM=MAYBE", "*STEP", "*STEP, NLGEOM=MAYBE"),
    ("include_missing", "*INCLUDE of a file that does not exist", "*NSET, NSET=BOTTOM",
     "*INCLUDE, INPUT=no_such_file.inc\n*NSET, NSET=BOTTOM", "*INCLUDE", "*INCLUDE, INPUT=no_such_file.inc"),
    ("user_element_undefined", "element type U7 not defined", "*ELEMENT, TYPE=C3D8, ELSET=CUBE",
     "*ELEMENT, TYPE=U7, ELSET=CUBE", "*ELEMENT", "*ELEMENT, TYPE=U7"),
    ("boundary_dof", "dof 7 in *BOUNDARY", "TOP, 3, 3, 0.1", "TOP, 7, 7, 0.1", "*BOUNDARY", "TOP, 7, 7, 0.1"),
    ("controls_unsupported", "an unsupported *CONTROLS field", "*BOUNDARY\nTOP, 3, 3, 0.1",
     "*CONTROLS, PARAMETERS=FIELD\n0.005, 0.01, , , 0.02\n*BOUNDARY\nTOP, 3, 3, 0.1", "*CONTROLS",
     "0.005, 0.01, , , 0.02"),
    # added for the robustness corpus (issue 6)
    ("missing_data_line", "*ELASTIC without its data line", "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n", "*ELASTIC",
     "*ELASTIC"),
    ("include_directory", "*INCLUDE of a directory", "*NSET, NSET=BOTTOM",
     "*INCLUDE, INPUT=include\n*NSET, NSET=BOTTOM", "*INCLUDE", "*INCLUDE, INPUT=include"),
    ("duplicate_element", "element 1 defined twice", "1, 1, 2, 3, 4, 5, 6, 7, 8\n",
     "1, 1, 2, 3, 4, 5, 6, 7, 8\n1, 8, 7, 6, 5, 4, 3, 2, 1\n", "*ELEMENT", "1, 8, 7, 6, 5"),
    ("amplitude_undefined", "boundary with an undefined amplitude", "*BOUNDARY\nTOP, 3, 3, 0.1",
     "*BOUNDARY, AMPLITUDE=NOPE\nTOP, 3, 3, 0.1", "*BOUNDARY", "*BOUNDARY, AMPLITUDE=NOPE"),
    ("negative_modulus", "negative Young's modulus", "1000., 0.3", "-1000., 0.3", "*ELASTIC", "-1000., 0.3"),
    ("boundary_dof_order", "first dof after the last dof", "TOP, 3, 3, 0.1", "TOP, 3, 1, 0.1", "*BOUNDARY",
     "TOP, 3, 1, 0.1"),
    ("inc_zero", "INC=0 on *STEP", "*STEP, NLGEOM=YES", "*STEP, NLGEOM=YES, INC=0", "*STEP", "*STEP, NLGEOM=YES, INC=0"),
    ("node_id_overflow", "a node id beyond the integer range", "8, 0., 1., 1.", "99999999999999999999, 0., 1., 1.",
     "*NODE", "99999999999999999999"),
    ("static_initial_gt_period", "initial increment larger than the period", "0.1, 1.0\n", "2.0, 1.0\n",
     "*STATIC", "2.0, 1.0"),
    ("depvar_negative", "*DEPVAR with a negative count", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n*DEPVAR\n-3\n", "*DEPVAR", "-3"),
    # loads (issue 18)
    ("cload_moment", "*CLOAD on a rotational dof", "*END STEP", "*CLOAD\nTOP, 5, 1.0\n*END STEP", "*CLOAD",
     "TOP, 5, 1.0"),
    ("cload_follower", "*CLOAD, FOLLOWER", "*END STEP", "*CLOAD, FOLLOWER\nTOP, 3, 1.0\n*END STEP", "*CLOAD",
     "*CLOAD, FOLLOWER"),
    ("cload_undefined_node", "*CLOAD on an undefined node", "*END STEP", "*CLOAD\n99, 3, 1.0\n*END STEP",
     "*CLOAD", "99, 3, 1.0"),
    ("cload_model_data", "*CLOAD outside a step", "*STEP, NLGEOM=YES", "*CLOAD\nTOP, 3, 1.0\n*STEP, NLGEOM=YES",
     "*CLOAD", "*CLOAD"),
    ("amplitude_definition", "*AMPLITUDE, DEFINITION=PERIODIC", "*STEP, NLGEOM=YES",
     "*AMPLITUDE, NAME=A, DEFINITION=PERIODIC\n0., 0., 1., 1.\n*STEP, NLGEOM=YES", "*AMPLITUDE",
     "*AMPLITUDE, NAME=A"),
    ("step_amplitude_value", "*STEP, AMPLITUDE=SINE", "*STEP, NLGEOM=YES", "*STEP, NLGEOM=YES, AMPLITUDE=SINE",
     "*STEP", "*STEP, NLGEOM=YES, AMPLITUDE"),
    ("dload_grav_density", "GRAV without *DENSITY", "*END STEP", "*DLOAD\nCUBE, GRAV, 9810., 0., 0., -1.\n*END STEP",
     "*DLOAD", "CUBE, GRAV"),
    ("dload_user_label_on_solid", "a user load type on a C3D8", "*END STEP", "*DLOAD\n1, U1, 1.0\n*END STEP",
     "*DLOAD", "1, U1"),
    ("surface_no_label", "*SURFACE data line without a face label", "*STEP, NLGEOM=YES",
     "*SURFACE, NAME=SURF\nCUBE\n*STEP, NLGEOM=YES", "*SURFACE", "CUBE"),
    ("surface_node_type", "*SURFACE, TYPE=NODE", "*STEP, NLGEOM=YES",
     "*SURFACE, NAME=SURF, TYPE=NODE\nTOP\n*STEP, NLGEOM=YES", "*SURFACE", "*SURFACE, NAME=SURF, TYPE=NODE"),
    ("dsload_undefined_surface", "*DSLOAD on an undefined surface", "*END STEP", "*DSLOAD\nNOPE, P, 1.0\n*END STEP",
     "*DSLOAD", "NOPE, P"),
    ("density_two_lines", "*DENSITY with two data lines", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*DENSITY\n1e-9\n2e-9\n", "*DENSITY", "*DENSITY"),
    ("equation_dof", "*EQUATION on a rotational dof", "*STEP, NLGEOM=YES",
     "*EQUATION\n2\n5, 4, 1., 1, 4, -1.\n*STEP, NLGEOM=YES", "*EQUATION", "5, 4, 1."),
    ("equation_terms", "*EQUATION with fewer terms than announced", "*STEP, NLGEOM=YES",
     "*EQUATION\n3\n5, 1, 1., 6, 1, -1.\n*STEP, NLGEOM=YES", "*EQUATION", "5, 1, 1., 6, 1"),
    ("tie_undefined_surface", "*TIE with an undefined surface", "*STEP, NLGEOM=YES",
     "*SURFACE, NAME=S1\nCUBE, S2\n*TIE, NAME=T\nS1, NOPE\n*STEP, NLGEOM=YES", "*TIE", "S1, NOPE"),
    ("mpc_beam", "*MPC BEAM (needs rotational dofs)", "*STEP, NLGEOM=YES", "*MPC\nBEAM, 5, 1\n*STEP, NLGEOM=YES",
     "*MPC", "BEAM, 5, 1"),
    ("initial_field", "*INITIAL CONDITIONS, TYPE=FIELD without VARIABLE", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=FIELD\nALL, 20.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS",
     "*INITIAL CONDITIONS, TYPE=FIELD"),
    ("initial_field_variable_zero", "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0\nALL, 20.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS",
     "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0"),
    ("initial_field_undefined_nset", "*INITIAL CONDITIONS, TYPE=FIELD on an undefined node set",
     "*STEP, NLGEOM=YES", "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=1\nNOPE, 20.\n*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS", "NOPE, 20."),
    ("field_no_variable", "*FIELD without VARIABLE", "*END STEP", "*FIELD\nALL, 20.\n*END STEP", "*FIELD",
     "*FIELD\n"),
    ("field_variable_negative", "*FIELD, VARIABLE=-1", "*END STEP", "*FIELD, VARIABLE=-1\nALL, 20.\n*END STEP",
     "*FIELD", "*FIELD, VARIABLE=-1"),
    ("field_undefined_nset", "*FIELD on an undefined node set", "*END STEP",
     "*FIELD, VARIABLE=2\nNOPE, 20.\n*END STEP", "*FIELD", "NOPE, 20."),
    ("field_model_data", "*FIELD outside a step", "*STEP, NLGEOM=YES",
     "*FIELD, VARIABLE=1\nALL, 20.\n*STEP, NLGEOM=YES", "*FIELD", "*FIELD, VARIABLE=1"),
    ("temperature_op", "*TEMPERATURE, OP=REPLACE", "*END STEP", "*TEMPERATURE, OP=REPLACE\nALL, 20.\n*END STEP",
     "*TEMPERATURE", "*TEMPERATURE, OP=REPLACE"),
    ("boundary_velocity_model_data", "*BOUNDARY, TYPE=VELOCITY in model data", "*STEP, NLGEOM=YES",
     "*BOUNDARY, TYPE=VELOCITY\nTOP, 3, 3, 1.\n*STEP, NLGEOM=YES", "*BOUNDARY", "*BOUNDARY, TYPE=VELOCITY"),
    ("boundary_type", "*BOUNDARY, TYPE=ACCELERATION", "*END STEP",
     "*BOUNDARY, TYPE=ACCELERATION\nTOP, 3, 3, 1.\n*END STEP", "*BOUNDARY", "*BOUNDARY, TYPE=ACCELERATION"),
    ("expansion_ortho", "*EXPANSION, TYPE=ORTHO", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*EXPANSION, TYPE=ORTHO\n1e-5, 2e-5, 3e-5\n", "*EXPANSION", "*EXPANSION, TYPE=ORTHO"),
    ("initial_stress_components", "seven initial stress components", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=STRESS\nCUBE, 1., 2., 3., 4., 5., 6., 7.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS",
     "CUBE, 1., 2."),
    ("initial_solution_elastic", "TYPE=SOLUTION on a material without state variables", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=SOLUTION\nCUBE, 1.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS", "CUBE, 1."),
]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    outdir = os.path.join(here, "..", "..", "decks", "bad")
    for name, title, old, new, kw, marker in CASES:
        deck = BASE.format(title="malformed deck: " + title)
        assert old in deck, name
        deck = deck.replace(old, new, 1)
        lines = deck.split("\n")
        if marker.endswith("\n"):
            hits = [i for i, l in enumerate(lines) if l == marker[:-1]]
        else:
            hits = [i for i, l in enumerate(lines) if l.startswith(marker)]
        assert hits, name
        lineno = hits[0] + 2  # 1-based, shifted by the EXPECT line put first
        deck = "** EXPECT line=%d keyword=%s\n" % (lineno, kw) + deck
        with open(os.path.join(outdir, "bad_%s.inp" % name), "w") as f:
            f.write(deck)


if __name__ == "__main__":
    main()
