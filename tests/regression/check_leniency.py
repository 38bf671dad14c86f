#!/usr/bin/env python3
"""Abaqus' lenient input forms against their explicit twins (docs/host.md, "Deck subset"): each pair of decks
must give the same JOB.csv to the bit (and, for *OUTPUT, the same frames).

  check_leniency.py --exe BIN --out DIR

A unit C3D8 cube of the built-in Leonov UMAT (named state variables need a UMAT) pulled by 2 % under NLGEOM in
four increments; each case writes a lenient deck and its explicit twin:
  abbreviated   *STEP, AMPLITUDE=RAM; *STATIC as *STAT...: values abbreviated (Input syntax rules)
  blanks        *SOLIDSECTION, ELSET=E, MATERIAL=M and NL GEOM=YES (blanks on keyword lines are ignored)
  node          '1,' and '2, 1.' (omitted coordinates are 0) against the coordinates written out
  constants     *USER MATERIAL, CONSTANTS=10 with 9 values against the 10th written as 0.
  constants_more  CONSTANTS=10 with an 11th value (not passed: NPROPS = 10, warned) against the 10 values
  depvar        *DEPVAR 11 with CAE's named lines '7, PEEQ, "equivalent plastic strain"': the same results, and
                the VTU frames hold an array SDV_PEEQ equal to the twin's SDV7
  assembly      a lone *END ASSEMBLY after the model data
  generate      *NSET, GENERATE 1, 20 over the 8 nodes of the cube against the list 1..8
  instance      the mesh inside the *INSTANCE of an empty *PART (CAE's independent instance) against the mesh in
                the part
  amplitude     *AMPLITUDE, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5 against the TABULAR points
  step_amp      *AMPLITUDE inside the step (history data in Abaqus) against the same curve in the model data
  field_var     *INITIAL CONDITIONS, TYPE=FIELD without VARIABLE= against VARIABLE=1 (the default)
  controls      *SECTION CONTROL, NAME=SC, HOUR GLASS=ENHANCED (read without effect) and *CONTROLS with Abaqus'
                other time-incrementation fields, against neither
  interval      *OUTPUT, FIELD, TIME INTERVAL=0.25 against NUMBER INTERVAL=4 (the same frames)
  include_file  the material in a file read by *INCLUDE, FILE= (as Abaqus/Standard read it in a published run;
                warned) against the material in the deck
"""
import argparse
import filecmp
import os
import re
import subprocess
import sys

NODES = ["1, 0., 0., 0.", "2, 1., 0., 0.", "3, 1., 1., 0.", "4, 0., 1., 0.", "5, 0., 0., 1.", "6, 1., 0., 1.",
         "7, 1., 1., 1.", "8, 0., 1., 1."]
PET = ["1250., 0.4, 28.4, 0.486, 0.95, 0.047, 28.2, 0.99", "200., -4."]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def deck(**o):
    """The cube deck; keyword arguments replace its pieces (the lenient forms)."""
    nodes = o.get("nodes", NODES)
    mesh = ["*Node"] + nodes + ["*Element, type=C3D8, elset=E", "1, 1, 2, 3, 4, 5, 6, 7, 8"]
    sets = o.get("sets", ["*Nset, nset=ALL", "1, 2, 3, 4, 5, 6, 7, 8"]) + [
        "*Nset, nset=X0", "1, 4, 5, 8", "*Nset, nset=Y0", "1, 2, 5, 6", "*Nset, nset=Z0", "1, 2, 3, 4",
        "*Nset, nset=TOP", "5, 6, 7, 8"]
    section = [o.get("section", "*Solid Section, elset=E, material=M")]
    if "part" in o:
        model = o["part"](mesh + sets + section)
    else:
        model = mesh + sets + section + o.get("after_model", [])
    mat = o.get("material", material(o))
    q = o.get("prefix", "")
    step = [o.get("step", "*Step, nlgeom=YES, inc=100"), "*Static", "0.25, 1., 1e-5, 0.25"] + o.get("amp", []) + [
        "*Boundary", q + "X0, 1, 1", q + "Y0, 2, 2", q + "Z0, 3, 3", o.get("top", q + "TOP, 3, 3, 0.02")] + \
        o.get("controls", []) + ["*Node print, nset=%sTOP" % q, "U, RF", "*Node print, nset=%sALL" % q, "U",
        o.get("output", "*Output, field, number interval=4"), "*Element output", "S, SDV", "*End step"]
    return ["*Heading", "leniency twin"] + o.get("before", []) + model + mat + step


def material(o):
    """The material block (o: the deck's options: umat, depvar)."""
    return ["*Material, name=M", "**LDFCZ BUILTIN, UMAT=LEONOV"] + o.get("umat", [
        "*User Material, constants=10, unsymm"] + PET) + o.get("depvar", ["*Depvar", "11"])


def run(exe, out, job, lines):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, job + ".inp")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    d = os.path.join(out, job)
    p = subprocess.run([exe, "-q", "--threads", "1", "--out", d, path], capture_output=True, text=True)
    if p.returncode != 0:
        fail("%s: exit %d: %s" % (job, p.returncode, p.stderr))
    return d, p.stderr


def twin(exe, out, name, lenient, explicit, warning=None):
    d1, warn = run(exe, out, name + "_lenient", lenient)
    if warning is not None and warning not in warn:
        fail("%s: no warning '%s' (stderr: %s)" % (name, warning, warn))
    d2, _ = run(exe, out, name + "_explicit", explicit)
    same = filecmp.cmp(os.path.join(d1, name + "_lenient.csv"), os.path.join(d2, name + "_explicit.csv"),
                       shallow=False)
    print("%-12s JOB.csv identical to the explicit twin: %s%s" % (name, same, "" if not warn else
                                                                  "  (warned: %s)" % warn.strip().split("\n")[0]))
    if not same:
        fail(name + ": the lenient deck's results differ from its explicit twin's")
    return d1, d2


def vtu_array(path, name):
    """Values of the cell array name of a VTU file."""
    text = open(path).read()
    m = re.search(r'Name="%s"[^>]*>([^<]*)<' % re.escape(name), text)
    return None if m is None else m.group(1).split()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    exe, out = os.path.abspath(a.exe), os.path.abspath(a.out)
    base = deck()
    twin(exe, out, "abbreviated", deck(step="*Step, nlgeom=YES, inc=100, amplitude=RAM"),
         deck(step="*Step, nlgeom=YES, inc=100, amplitude=RAMP"))
    twin(exe, out, "blanks", deck(section="*SOLIDSECTION, ELSET=E, MATERIAL=M", step="*Step, NL GEOM=YES, inc=100"),
         base)
    twin(exe, out, "node", deck(nodes=["1,", "2, 1."] + NODES[2:]), base)
    twin(exe, out, "constants", deck(umat=["*User Material, constants=10, unsymm", PET[0], "200."]),
         deck(umat=["*User Material, constants=10, unsymm", PET[0], "200., 0."]))
    twin(exe, out, "constants_more", deck(umat=["*User Material, constants=10, unsymm", PET[0], PET[1] + ", 7."]),
         base)
    d1, d2 = twin(exe, out, "depvar", deck(depvar=["*Depvar", "11", '7, PEEQ, "equivalent plastic strain"']), base)
    named = vtu_array(os.path.join(d1, "depvar_lenient_0005.vtu"), "SDV_PEEQ")
    plain = vtu_array(os.path.join(d2, "depvar_explicit_0005.vtu"), "SDV7")
    print("depvar       VTU array SDV_PEEQ = the twin's SDV7: %s" % (named is not None and named == plain))
    if named is None or named != plain:
        fail("the named state variable is not the VTU array SDV_PEEQ holding SDV7")
    twin(exe, out, "assembly", deck(after_model=["*End Assembly"]), base)
    twin(exe, out, "generate", deck(sets=["*Nset, nset=ALL, generate", "1, 20"]), base)

    def part(blocks):
        return ["*Part, name=P"] + blocks + ["*End Part", "*Assembly, name=A", "*Instance, name=I, part=P",
                                            "*End Instance", "*End Assembly"]

    def independent(blocks):
        return ["*Part, name=P", "*End Part", "*Assembly, name=A", "*Instance, name=I, part=P"] + blocks + [
            "*End Instance", "*End Assembly"]
    io = {"prefix": "I."}
    twin(exe, out, "instance", deck(part=independent, **io), deck(part=part, **io))
    twin(exe, out, "amplitude",
         deck(after_model=["*Amplitude, name=A, definition=EQUALLY SPACED, fixed interval=0.5", "0., 1., 0.5"],
              top="*Boundary, amplitude=A\nTOP, 3, 3, 0.02"),
         deck(after_model=["*Amplitude, name=A", "0., 0., 0.5, 1., 1., 0.5"],
              top="*Boundary, amplitude=A\nTOP, 3, 3, 0.02"))
    twin(exe, out, "step_amp", deck(amp=["*Amplitude, name=A", "0., 0., 0.5, 1., 1., 0.5"],
                                    top="*Boundary, amplitude=A\nTOP, 3, 3, 0.02"),
         deck(after_model=["*Amplitude, name=A", "0., 0., 0.5, 1., 1., 0.5"],
              top="*Boundary, amplitude=A\nTOP, 3, 3, 0.02"))
    twin(exe, out, "field_var", deck(after_model=["*Initial conditions, type=FIELD", "ALL, 20."]),
         deck(after_model=["*Initial conditions, type=FIELD, variable=1", "ALL, 20."]))
    twin(exe, out, "controls", deck(after_model=["*Section control, name=SC, hour glass=ENHANCED"],
                                    section="*Solid Section, elset=E, material=M, controls=SC",
                                    controls=["*Controls, parameters=time incrementation", "8, 10, , 16"]),
         deck(controls=["*Controls, parameters=time incrementation", ", , , 16"]))
    d1, d2 = twin(exe, out, "interval", deck(output="*Output, field, time interval=0.25"), base)
    frames = [re.findall(r'timestep="([^"]+)"', open(os.path.join(d, job + ".pvd")).read())
              for d, job in ((d1, "interval_lenient"), (d2, "interval_explicit"))]
    same = frames[0] == frames[1] and len(frames[0]) == 5
    print("interval     the same frames (JOB.pvd times %s): %s" % (", ".join(frames[0]), same))
    if not same:
        fail("TIME INTERVAL=0.25 and NUMBER INTERVAL=4 wrote different frames")
    with open(os.path.join(out, "leniency_material.inp"), "w") as f:
        f.write("\n".join(material({})) + "\n")
    twin(exe, out, "include_file", deck(material=["*Include, file=leniency_material.inp"]), base,
         warning="*INCLUDE: FILE= read as INPUT=")
    print("PASS")


if __name__ == "__main__":
    main()
