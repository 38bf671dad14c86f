#!/usr/bin/env python3
"""Writes the malformed decks of the model-structure, *PARAMETER and mesh-generation keywords into decks/bad/
(parts, assemblies, instances, qualified names, *PARAMETER, *NGEN, *NFILL, *NCOPY, *ELGEN, *SYSTEM, *ORIENTATION,
*TRANSFORM), each with one defect.

Each deck's first line is `** EXPECT line=N keyword=*KW` (check_run.py --bad reads it). Run from anywhere:
python3 tests/regression/make_structure_bad_decks.py
"""
import os

os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "decks", "bad"))
part = ["*PART, NAME=CUBE", "*NODE", "1, 0., 0., 0.", "2, 1., 0., 0.", "3, 1., 1., 0.", "4, 0., 1., 0.",
        "5, 0., 0., 1.", "6, 1., 0., 1.", "7, 1., 1., 1.", "8, 0., 1., 1.",
        "*ELEMENT, TYPE=C3D8, ELSET=ALL", "1, 1, 2, 3, 4, 5, 6, 7, 8", "*NSET, NSET=BOTTOM", "1, 2, 3, 4",
        "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL", "*END PART"]
mat = ["*MATERIAL, NAME=STEEL", "*ELASTIC", "1000., 0.3"]
step = ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY", "C-1.BOTTOM, ENCASTRE", "*END STEP"]
asm = ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE", "*END ASSEMBLY"]
def deck(name, what, lines, kw, match, nth=0):
    body = ["*HEADING", "malformed deck: " + what] + lines
    line = [i for i, l in enumerate(body) if l == match][nth] + 2
    open(name + ".inp", "w").write("\n".join(["** EXPECT line=%d keyword=%s" % (line, kw)] + body) + "\n")
deck("bad_part_no_end", "a *PART without *END PART (a material follows its mesh)", part[:-1] + mat + step, "*MATERIAL",
     "*MATERIAL, NAME=STEEL")
deck("bad_part_keyword", "a material inside a part", part[:-1] + ["*MATERIAL, NAME=X"] + part[-1:] + mat + asm + step,
     "*MATERIAL", "*MATERIAL, NAME=X")
deck("bad_instance_undefined_part", "an instance of an undefined part",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=BLOCK", "*END INSTANCE", "*END ASSEMBLY"] + step,
     "*INSTANCE", "*INSTANCE, NAME=C-1, PART=BLOCK")
deck("bad_instance_axis", "an instance rotated about an axis whose two points coincide",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "0., 0., 0.",
                   "1., 1., 1., 1., 1., 1., 90.", "*END INSTANCE", "*END ASSEMBLY"] + step,
     "*INSTANCE", "1., 1., 1., 1., 1., 1., 90.")
deck("bad_instance_twice", "two instances of the same name",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE",
                   "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE", "*END ASSEMBLY"] + step,
     "*INSTANCE", "*INSTANCE, NAME=C-1, PART=CUBE", 1)
deck("bad_instance_label_undefined", "a boundary on an instance node the part does not have",
     part + mat + asm + ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY", "C-1.99, 1, 3", "*END STEP"],
     "*BOUNDARY", "C-1.99, 1, 3")
deck("bad_instance_set_undefined", "a qualified set name the instance does not have",
     part + mat + asm + ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY", "C-1.TOP, 1, 3", "*END STEP"],
     "*BOUNDARY", "C-1.TOP, 1, 3")
deck("bad_assembly_mesh_outside", "a node outside the parts and the assembly of a deck with an assembly",
     part + ["*NODE", "100, 5., 5., 5."] + mat + asm + step, "*NODE", "*NODE", 1)
deck("bad_assembly_keyword", "a material inside the assembly",
     part + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE"] + mat + ["*END ASSEMBLY"] + step,
     "*MATERIAL", "*MATERIAL, NAME=STEEL")
deck("bad_assembly_no_end", "an assembly without *END ASSEMBLY",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE"] + step,
     "*ASSEMBLY", "*ASSEMBLY, NAME=A")
deck("bad_set_instance_undefined", "INSTANCE= naming no instance",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*END INSTANCE",
                   "*NSET, NSET=FIX, INSTANCE=C-2", "1, 2", "*END ASSEMBLY"] + step, "*NSET", "*NSET, NSET=FIX, INSTANCE=C-2")
deck("bad_instance_body", "a keyword inside *INSTANCE ... *END INSTANCE",
     part + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=CUBE", "*NODE", "9, 2., 2., 2.",
                   "*END INSTANCE", "*END ASSEMBLY"] + step, "*INSTANCE", "*INSTANCE, NAME=C-1, PART=CUBE")
flat = ["*NODE", "1, 0., 0., 0.", "2, 1., 0., 0.", "3, 1., 1., 0.", "4, 0., 1., 0.",
        "5, 0., 0., 1.", "6, 1., 0., 1.", "7, 1., 1., 1.", "8, 0., 1., 1.",
        "*ELEMENT, TYPE=C3D8, ELSET=ALL", "1, 1, 2, 3, 4, 5, 6, 7, 8", "*NSET, NSET=BOTTOM", "1, 2, 3, 4",
        "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL"]
fstep = ["*STEP", "*STATIC", "1., 1.", "*BOUNDARY", "BOTTOM, ENCASTRE", "*END STEP"]
deck("bad_parameter_undefined", "a parameter used but not defined",
     ["*PARAMETER", "E = 1000."] + flat + ["*MATERIAL, NAME=STEEL", "*ELASTIC", "<Emod>, 0.3"] + fstep,
     "*ELASTIC", "<Emod>, 0.3")
deck("bad_parameter_expression", "a parameter expression that does not parse",
     ["*PARAMETER", "E = 1000. * (2 + "] + flat + mat + fstep, "*PARAMETER", "E = 1000. * (2 + ")
deck("bad_parameter_division", "a parameter divided by zero",
     ["*PARAMETER", "z = 0", "E = 1000. / z"] + flat + mat + fstep, "*PARAMETER", "E = 1000. / z")
deck("bad_ngen_undefined_end", "*NGEN from a node not defined before",
     flat + ["*NGEN", "1, 30, 1"] + mat + fstep, "*NGEN", "1, 30, 1")
deck("bad_nfill_sizes", "*NFILL between node sets of different sizes",
     flat + ["*NSET, NSET=TOP", "5, 6, 7", "*NFILL", "BOTTOM, TOP, 2, 10"] + mat + fstep, "*NFILL", "BOTTOM, TOP, 2, 10")
deck("bad_ncopy_pole", "*NCOPY with POLE (not supported)",
     flat + ["*NCOPY, OLD SET=BOTTOM, CHANGE NUMBER=10, POLE"] + mat + fstep, "*NCOPY",
     "*NCOPY, OLD SET=BOTTOM, CHANGE NUMBER=10, POLE")
deck("bad_ncopy_reflect_line", "*NCOPY, REFLECT=LINE through two coinciding points",
     flat + ["*NCOPY, OLD SET=BOTTOM, CHANGE NUMBER=10, REFLECT=LINE", "1., 1., 1., 1., 1., 1."] + mat + fstep,
     "*NCOPY", "1., 1., 1., 1., 1., 1.")
deck("bad_ncopy_reflect_fields", "*NCOPY, REFLECT=MIRROR with six coordinates",
     flat + ["*NCOPY, OLD SET=BOTTOM, CHANGE NUMBER=10, REFLECT=MIRROR", "0., 0., 0., 1., 0., 0."] + mat + fstep,
     "*NCOPY", "0., 0., 0., 1., 0., 0.")
deck("bad_ngen_arc_half", "*NGEN, LINE=C over 180 degrees without a normal",
     flat + ["*NODE", "20, 2., 0., 0.", "24, -2., 0., 0.", "30, 0., 0., 0.", "*NGEN, LINE=C", "20, 24, 1, 30"]
     + mat + fstep, "*NGEN", "20, 24, 1, 30")
deck("bad_ngen_line", "*NGEN with an unknown LINE",
     flat + ["*NGEN, LINE=S", "1, 2, 1"] + mat + fstep, "*NGEN", "*NGEN, LINE=S")
deck("bad_nfill_bias", "*NFILL with a negative BIAS",
     flat + ["*NSET, NSET=TOP", "5, 6, 7, 8", "*NFILL, BIAS=-2.", "BOTTOM, TOP, 2, 10"] + mat + fstep, "*NFILL",
     "*NFILL, BIAS=-2.")
deck("bad_system_fields", "*SYSTEM with a and b but no c",
     ["*SYSTEM", "0., 0., 0., 1., 0., 0."] + flat + mat + fstep, "*SYSTEM", "0., 0., 0., 1., 0., 0.")
deck("bad_system_in_step", "*SYSTEM inside a step",
     flat + mat + ["*STEP", "*STATIC", "1., 1.", "*SYSTEM", "*BOUNDARY", "BOTTOM, ENCASTRE", "*END STEP"], "*SYSTEM",
     "*SYSTEM")
deck("bad_elgen_master", "*ELGEN of an undefined master element",
     flat + ["*ELGEN, ELSET=ALL", "7, 2, 4, 1"] + mat + fstep, "*ELGEN", "7, 2, 4, 1")
ori_flat = flat[:-1]
deck("bad_orientation_undefined", "a section naming an undefined orientation",
     ori_flat + ["*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, ORIENTATION=ORI"] + mat + fstep, "*SOLID SECTION",
     "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, ORIENTATION=ORI")
deck("bad_orientation_system", "an orientation system that is not supported",
     ori_flat + ["*ORIENTATION, NAME=ORI, SYSTEM=SPHERICAL", "0., 0., 0., 0., 0., 1.",
                 "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, ORIENTATION=ORI"] + mat + fstep, "*ORIENTATION",
     "*ORIENTATION, NAME=ORI, SYSTEM=SPHERICAL")
deck("bad_orientation_points", "orientation points a and b on one line through the origin",
     ori_flat + ["*ORIENTATION, NAME=ORI", "1., 0., 0., 2., 0., 0.",
                 "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, ORIENTATION=ORI"] + mat + fstep, "*ORIENTATION",
     "*ORIENTATION, NAME=ORI")
deck("bad_orientation_axis", "an additional rotation about axis 4",
     ori_flat + ["*ORIENTATION, NAME=ORI", "1., 0., 0., 0., 1., 0.", "4, 30.",
                 "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL, ORIENTATION=ORI"] + mat + fstep, "*ORIENTATION", "4, 30.")
deck("bad_monitor_node", "*MONITOR of an undefined node",
     flat + mat + ["*STEP", "*STATIC", "1., 1.", "*MONITOR, NODE=99, DOF=1", "*BOUNDARY", "BOTTOM, ENCASTRE", "*END STEP"],
     "*MONITOR", "*MONITOR, NODE=99, DOF=1")
part2d = ["*PART, NAME=SQ", "*NODE", "1, 0., 0.", "2, 1., 0.", "3, 1., 1.", "4, 0., 1.",
          "*ELEMENT, TYPE=CPE4, ELSET=ALL", "1, 1, 2, 3, 4", "*NSET, NSET=BOTTOM", "1, 2",
          "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL", "*END PART"]
deck("bad_instance_plane_tilt", "an instance of a plane model turned out of the x-y plane",
     part2d + mat + ["*ASSEMBLY, NAME=A", "*INSTANCE, NAME=C-1, PART=SQ", "0., 0., 0.", "0., 0., 0., 1., 0., 0., 30.",
                     "*END INSTANCE", "*END ASSEMBLY"] + step, "*INSTANCE", "*INSTANCE, NAME=C-1, PART=SQ")
# *TRANSFORM
deck("bad_transform_no_nset", "*TRANSFORM without NSET",
     flat + ["*TRANSFORM", "1., 0., 0., 0., 1., 0."] + mat + fstep, "*TRANSFORM", "*TRANSFORM")
deck("bad_transform_type", "*TRANSFORM of an unknown TYPE",
     flat + ["*TRANSFORM, NSET=BOTTOM, TYPE=X", "1., 0., 0., 0., 1., 0."] + mat + fstep, "*TRANSFORM",
     "*TRANSFORM, NSET=BOTTOM, TYPE=X")
deck("bad_transform_set", "*TRANSFORM of an undefined node set",
     flat + ["*TRANSFORM, NSET=NOSUCH", "1., 0., 0., 0., 1., 0."] + mat + fstep, "*TRANSFORM",
     "*TRANSFORM, NSET=NOSUCH")
deck("bad_transform_fields", "*TRANSFORM with five coordinates",
     flat + ["*TRANSFORM, NSET=BOTTOM", "1., 0., 0., 0., 1."] + mat + fstep, "*TRANSFORM", "1., 0., 0., 0., 1.")
deck("bad_transform_parallel", "*TRANSFORM, TYPE=R with a and b parallel",
     flat + ["*TRANSFORM, NSET=BOTTOM", "1., 1., 0., 2., 2., 0."] + mat + fstep, "*TRANSFORM", "1., 1., 0., 2., 2., 0.")
deck("bad_transform_points", "*TRANSFORM, TYPE=C with coinciding axis points",
     flat + ["*TRANSFORM, NSET=BOTTOM, TYPE=C", "0., 0., 1., 0., 0., 1."] + mat + fstep, "*TRANSFORM",
     "0., 0., 1., 0., 0., 1.")
deck("bad_transform_twice", "a node in two *TRANSFORM sets",
     flat + ["*NSET, NSET=CORNER", "1", "*TRANSFORM, NSET=BOTTOM", "1., 0., 0., 0., 1., 0.",
             "*TRANSFORM, NSET=CORNER, TYPE=C", "5., 5., 0., 5., 5., 1."] + mat + fstep, "*TRANSFORM",
     "*TRANSFORM, NSET=CORNER, TYPE=C")
deck("bad_transform_axis", "*TRANSFORM, TYPE=C with a node on the axis",
     flat + ["*TRANSFORM, NSET=BOTTOM, TYPE=C", "0., 0., 0., 0., 0., 1."] + mat + fstep, "*TRANSFORM",
     "*TRANSFORM, NSET=BOTTOM, TYPE=C")
deck("bad_transform_in_step", "*TRANSFORM inside a step",
     flat + mat + ["*STEP", "*STATIC", "1., 1.", "*TRANSFORM, NSET=BOTTOM", "1., 0., 0., 0., 1., 0.",
                   "*BOUNDARY", "BOTTOM, ENCASTRE", "*END STEP"], "*TRANSFORM", "*TRANSFORM, NSET=BOTTOM")
deck("bad_transform_lines", "*TRANSFORM with two data lines",
     flat + ["*TRANSFORM, NSET=BOTTOM", "1., 0., 0., 0., 1., 0.", "0., 0., 1., 0., 1., 0."] + mat + fstep,
     "*TRANSFORM", "*TRANSFORM, NSET=BOTTOM")
deck("bad_boundary_user_model", "*BOUNDARY, USER in model data",
     flat + mat + ["*BOUNDARY, USER", "BOTTOM, 3, 3, 0.1"] + fstep, "*BOUNDARY", "*BOUNDARY, USER")
deck("bad_transform_plane", "a *TRANSFORM of a plane model whose local 3 is not global Z",
     ["*NODE", "1, 0., 0.", "2, 1., 0.", "3, 1., 1.", "4, 0., 1.", "*ELEMENT, TYPE=CPE4, ELSET=ALL", "1, 1, 2, 3, 4",
      "*NSET, NSET=BOTTOM", "1, 2", "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL",
      "*TRANSFORM, NSET=BOTTOM", "1., 0., 0., 0., 0., 1."] + mat + fstep, "*TRANSFORM", "*TRANSFORM, NSET=BOTTOM")
deck("bad_transform_mpc", "an *MPC tie on a node with a *TRANSFORM",
     flat + ["*TRANSFORM, NSET=BOTTOM", "1., 1., 0., -1., 1., 0.", "*MPC", "TIE, 5, 1"] + mat + fstep, "*MPC",
     "TIE, 5, 1")
