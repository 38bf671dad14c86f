#!/usr/bin/env bash
# Install what is missing, build (Release) and run the main job: the plane-strain peel scene of the paper's text
# (reading A of Fig. 10: "a displacement u_x on one end of the polymer coating"; decks/peel/peel_main.inp, l_e = 5 um,
# n_z = 9; paper sections 7-9, docs/scenes.md; add --scene B for the flap lifted and pulled at 90 degrees,
# decks/peel/peel_ps_flap90.inp). It prints the steady peel force per unit width with its averaging uncertainty and
# its discretisation band (reports/main-mesh/), and writes the force-displacement CSV, a PNG plot
# (out/main/report/main/) and ParaView frames (out/main/run/). One thread: the band was measured with one.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/tools/setup.sh" Release
build_dir=${LDFCZ_BUILD_DIR:-$root/build}
cd "$root"
/usr/bin/python3 tools/peel_study.py main --scene A --threads 1 --ldfcz "$build_dir/bin/ldfcz" \
  --reports "$root/out/main/report" --work "$root/out/main/run" "$@"
