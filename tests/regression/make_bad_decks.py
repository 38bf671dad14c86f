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
    ("unsupported_element", "element type C3D8X", "*ELEMENT, TYPE=C3D8, ELSET=CUBE",
     "*ELEMENT, TYPE=C3D8X, ELSET=CUBE", "*ELEMENT", "*ELEMENT, TYPE=C3D8X"),
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
    ("controls_unsupported", "*CONTROLS, PARAMETERS=CONSTRAINTS", "*BOUNDARY\nTOP, 3, 3, 0.1",
     "*CONTROLS, PARAMETERS=CONSTRAINTS\n0.005\n*BOUNDARY\nTOP, 3, 3, 0.1", "*CONTROLS",
     "*CONTROLS, PARAMETERS=CONSTRAINTS"),
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
    ("density_field_dependence", "*DENSITY with a field variable", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*DENSITY\n1e-9, 20., 3.\n", "*DENSITY", "1e-9, 20., 3."),
    ("equation_dof", "*EQUATION on a rotational dof", "*STEP, NLGEOM=YES",
     "*EQUATION\n2\n5, 4, 1., 1, 4, -1.\n*STEP, NLGEOM=YES", "*EQUATION", "5, 4, 1."),
    ("equation_terms", "*EQUATION with fewer terms than announced", "*STEP, NLGEOM=YES",
     "*EQUATION\n3\n5, 1, 1., 6, 1, -1.\n*STEP, NLGEOM=YES", "*EQUATION", "5, 1, 1., 6, 1"),
    ("tie_undefined_surface", "*TIE with an undefined surface", "*STEP, NLGEOM=YES",
     "*SURFACE, NAME=S1\nCUBE, S2\n*TIE, NAME=T\nS1, NOPE\n*STEP, NLGEOM=YES", "*TIE", "S1, NOPE"),
    ("mpc_beam", "*MPC BEAM (needs rotational dofs)", "*STEP, NLGEOM=YES", "*MPC\nBEAM, 5, 1\n*STEP, NLGEOM=YES",
     "*MPC", "BEAM, 5, 1"),
    ("initial_field_variable_zero", "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0\nALL, 20.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS",
     "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=0"),
    ("initial_field_undefined_nset", "*INITIAL CONDITIONS, TYPE=FIELD on an undefined node set",
     "*STEP, NLGEOM=YES", "*INITIAL CONDITIONS, TYPE=FIELD, VARIABLE=1\nNOPE, 20.\n*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS", "NOPE, 20."),
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
    ("expansion_short_fiber", "*EXPANSION, TYPE=SHORT FIBER", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*EXPANSION, TYPE=SHORT FIBER\n1e-5, 2e-5, 3e-5\n", "*EXPANSION",
     "*EXPANSION, TYPE=SHORT FIBER"),
    ("initial_stress_components", "seven initial stress components", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=STRESS\nCUBE, 1., 2., 3., 4., 5., 6., 7.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS",
     "CUBE, 1., 2."),
    ("initial_solution_elastic", "TYPE=SOLUTION on a material without state variables", "*STEP, NLGEOM=YES",
     "*INITIAL CONDITIONS, TYPE=SOLUTION\nCUBE, 1.\n*STEP, NLGEOM=YES", "*INITIAL CONDITIONS", "CUBE, 1."),
    # materials, declarations and reader leniency (issue 36): every new keyword's and parameter's malformed forms
    ("elastic_type_traction", "*ELASTIC, TYPE=TRACTION (cohesive elements)", "*ELASTIC\n", "*ELASTIC, TYPE=TRACTION\n",
     "*ELASTIC", "*ELASTIC, TYPE=TRACTION"),
    ("elastic_ortho_one_line", "ORTHOTROPIC with 8 constants on one line (9 and the temperature take 2 lines)",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC, TYPE=ORTHOTROPIC\n1000., 300., 1000., 300., 300., 1000., 350., 350.\n",
     "*ELASTIC", "1000., 300., 1000., 300., 300., 1000., 350., 350."),
    ("elastic_nine_values", "ANISOTROPIC with 9 values on its first line", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC, TYPE=ANISOTROPIC\n1000., 300., 1000., 300., 300., 1000., 0., 0., 0.\n0., 350., 0., 0., 0., 0., 350."
     "\n0., 0., 0., 0., 350.\n", "*ELASTIC", "1000., 300., 1000., 300., 300., 1000., 0., 0., 0."),
    ("elastic_temperatures_descending", "temperature-dependent *ELASTIC with descending temperatures",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3, 100.\n900., 0.3, 50.\n", "*ELASTIC", "900., 0.3, 50."),
    ("elastic_temperature_missing", "temperature-dependent *ELASTIC without the second temperature",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3, 20.\n900., 0.3\n", "*ELASTIC", "900., 0.3\n"),
    ("elastic_field_variable", "*ELASTIC with a field-variable value after the temperature",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3, 20., 1.\n", "*ELASTIC", "1000., 0.3, 20., 1."),
    ("elastic_dependencies", "*ELASTIC, DEPENDENCIES=1", "*ELASTIC\n", "*ELASTIC, DEPENDENCIES=1\n", "*ELASTIC",
     "*ELASTIC, DEPENDENCIES=1"),
    ("elastic_unstable", "ENGINEERING CONSTANTS with no positive definite stiffness (nu = 0.9)",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n1000., 1000., 1000., 0.9, 0.9, 0.9, 400., "
     "400.\n400.\n", "*ELASTIC", "*ELASTIC, TYPE=ENGINEERING CONSTANTS"),
    ("elastic_lamina_solid", "TYPE=LAMINA on a C3D8 element", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC, TYPE=LAMINA\n1000., 500., 0.3, 400., 400., 400.\n", "*ELASTIC", "*ELASTIC, TYPE=LAMINA"),
    ("expansion_zero_text", "*EXPANSION, ZERO= not a number", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*EXPANSION, ZERO=warm\n1e-5\n", "*EXPANSION", "*EXPANSION, ZERO=warm"),
    ("expansion_user", "*EXPANSION, USER (subroutine UEXPAN)", "*ELASTIC\n1000., 0.3\n",
     "*ELASTIC\n1000., 0.3\n*EXPANSION, USER\n", "*EXPANSION", "*EXPANSION, USER"),
    ("expansion_temperatures_equal", "temperature-dependent *EXPANSION with equal temperatures",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3\n*EXPANSION\n1e-5, 20.\n2e-5, 20.\n", "*EXPANSION",
     "2e-5, 20."),
    ("density_grav_temperature", "GRAV with a temperature-dependent *DENSITY",
     "1000., 0.3\n*BOUNDARY\nBOTTOM, ENCASTRE\n*STEP, NLGEOM=YES\n*STATIC\n0.1, 1.0\n*BOUNDARY\nTOP, 3, 3, 0.1\n"
     "*END STEP", "1000., 0.3\n*DENSITY\n1e-9, 0.\n2e-9, 100.\n*BOUNDARY\nBOTTOM, ENCASTRE\n*STEP, NLGEOM=YES\n"
     "*STATIC\n0.1, 1.0\n*BOUNDARY\nTOP, 3, 3, 0.1\n*DLOAD\nCUBE, GRAV, 9810., 0., 0., -1.\n*END STEP", "*DLOAD",
     "CUBE, GRAV"),
    ("depvar_name_index", "*DEPVAR naming state variable 3 of 2", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n*DEPVAR\n2\n3, X, \"third\"\n", "*DEPVAR", "3, X"),
    ("depvar_name_twice", "*DEPVAR naming state variable 1 twice", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n*DEPVAR\n2\n1, A\n1, B\n", "*DEPVAR", "1, B"),
    ("user_material_hybrid_total", "*USER MATERIAL, HYBRID FORMULATION=TOTAL (needs an independent pressure)",
     "*ELASTIC\n1000., 0.3\n", "*USER MATERIAL, CONSTANTS=2, HYBRID FORMULATION=TOTAL\n1000., 0.3\n",
     "*USER MATERIAL", "*USER MATERIAL, CONSTANTS=2, HYBRID"),
    ("element_hybrid_quadratic", "a hybrid name of a type without constant dilatation (C3D20H)",
     "*ELEMENT, TYPE=C3D8, ELSET=CUBE", "*ELEMENT, TYPE=C3D20H, ELSET=CUBE", "*ELEMENT",
     "*ELEMENT, TYPE=C3D20H"),
    ("depvar_delete_range", "*DEPVAR, DELETE=3 of 2 state variables", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n*DEPVAR, DELETE=3\n2\n", "*DEPVAR", "*DEPVAR, DELETE=3"),
    ("depvar_delete_value", "*DEPVAR, DELETE= not a number", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n*DEPVAR, DELETE=X\n2\n", "*DEPVAR", "*DEPVAR, DELETE=X"),
    ("depvar_delete_elastic", "*DEPVAR, DELETE= on an *ELASTIC material (no UMAT sets the variable)",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3\n*DEPVAR, DELETE=1\n1\n", "*DEPVAR",
     "*DEPVAR, DELETE=1"),
    ("constants_more_values", "*USER MATERIAL, CONSTANTS=1 with 2 values", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=1\n1000., 0.3\n", "*USER MATERIAL", "*USER MATERIAL, CONSTANTS=1"),
    ("routine_missing", "a *USER MATERIAL without --user and without **LDFCZ BUILTIN", "*ELASTIC\n1000., 0.3\n",
     "*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n", "*MATERIAL", "*MATERIAL, NAME=STEEL"),
    ("builtin_unknown", "**LDFCZ BUILTIN naming no built-in UMAT", "*ELASTIC\n1000., 0.3\n",
     "**LDFCZ BUILTIN, UMAT=NOSUCH\n*USER MATERIAL, CONSTANTS=2\n1000., 0.3\n", "*LDFCZ BUILTIN",
     "**LDFCZ BUILTIN, UMAT=NOSUCH"),
    ("builtin_both", "**LDFCZ BUILTIN with UMAT= and UEL=", "*ELASTIC\n1000., 0.3\n",
     "**LDFCZ BUILTIN, UMAT=LEONOV, UEL=LDF\n*ELASTIC\n1000., 0.3\n", "*LDFCZ BUILTIN",
     "**LDFCZ BUILTIN, UMAT=LEONOV, UEL"),
    ("builtin_outside_material", "**LDFCZ BUILTIN, UMAT= outside a material definition", "*STEP, NLGEOM=YES",
     "**LDFCZ BUILTIN, UMAT=LEONOV\n*STEP, NLGEOM=YES", "*LDFCZ BUILTIN", "**LDFCZ BUILTIN, UMAT=LEONOV"),
    ("builtin_elastic_material", "**LDFCZ BUILTIN, UMAT= under a material without *USER MATERIAL",
     "*ELASTIC\n1000., 0.3\n", "*ELASTIC\n1000., 0.3\n**LDFCZ BUILTIN, UMAT=LEONOV\n", "*LDFCZ BUILTIN",
     "**LDFCZ BUILTIN, UMAT=LEONOV"),
    ("builtin_material_undefined", "**LDFCZ BUILTIN, MATERIAL= naming no material", "*BOUNDARY\nBOTTOM",
     "**LDFCZ BUILTIN, UMAT=LEONOV, MATERIAL=NOPE\n*BOUNDARY\nBOTTOM", "*LDFCZ BUILTIN",
     "**LDFCZ BUILTIN, UMAT=LEONOV, MATERIAL=NOPE"),
    ("builtin_uel_no_type", "**LDFCZ BUILTIN, UEL= without a *USER ELEMENT", "*BOUNDARY\nBOTTOM",
     "**LDFCZ BUILTIN, UEL=LDF\n*BOUNDARY\nBOTTOM", "*LDFCZ BUILTIN", "**LDFCZ BUILTIN, UEL=LDF"),
    ("section_controls_deletion", "*SECTION CONTROLS, ELEMENT DELETION=YES", "*MATERIAL, NAME=STEEL",
     "*SECTION CONTROLS, NAME=SC, ELEMENT DELETION=YES\n*MATERIAL, NAME=STEEL", "*SECTION CONTROLS",
     "*SECTION CONTROLS, NAME=SC"),
    ("section_controls_name", "*SECTION CONTROLS without NAME", "*MATERIAL, NAME=STEEL",
     "*SECTION CONTROLS, HOURGLASS=ENHANCED\n*MATERIAL, NAME=STEEL", "*SECTION CONTROLS",
     "*SECTION CONTROLS, HOURGLASS"),
    ("amplitude_spaced_interval", "*AMPLITUDE, DEFINITION=EQUALLY SPACED without FIXED INTERVAL",
     "*STEP, NLGEOM=YES", "*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED\n0., 1.\n*STEP, NLGEOM=YES", "*AMPLITUDE",
     "*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED"),
    ("amplitude_spaced_negative", "*AMPLITUDE, EQUALLY SPACED with a negative FIXED INTERVAL", "*STEP, NLGEOM=YES",
     "*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=-0.5\n0., 1.\n*STEP, NLGEOM=YES",
     "*AMPLITUDE", "*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED, FIXED"),
    ("amplitude_begin_tabular", "*AMPLITUDE, BEGIN= with TABULAR", "*STEP, NLGEOM=YES",
     "*AMPLITUDE, NAME=A, BEGIN=1.\n0., 0., 1., 1.\n*STEP, NLGEOM=YES", "*AMPLITUDE", "*AMPLITUDE, NAME=A, BEGIN"),
    ("output_time_interval", "*OUTPUT, TIME INTERVAL that does not divide the period", "*END STEP",
     "*OUTPUT, FIELD, TIME INTERVAL=0.3\n*END STEP", "*OUTPUT", "*OUTPUT, FIELD, TIME INTERVAL=0.3"),
    ("node_eight_fields", "a *NODE line with 8 fields", "3, 1., 1., 0.", "3, 1., 1., 0., 0., 0., 1., 5.", "*NODE",
     "3, 1., 1., 0., 0."),
    ("solid_section_offset", "*SOLID SECTION, OFFSET=0.5", "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL",
     "*SOLID SECTION, ELSET=CUBE, MATERIAL=STEEL, OFFSET=0.5", "*SOLID SECTION", "*SOLID SECTION, ELSET=CUBE, "
     "MATERIAL=STEEL, OFFSET"),
    ("generate_explicit_gap", "an explicit *NSET member without a node (only GENERATE ranges skip gaps)",
     "*NSET, NSET=TOP\n5, 6, 7, 8", "*NSET, NSET=TOP\n5, 6, 7, 8, 9", "*NSET", "5, 6, 7, 8, 9"),
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
