#!/usr/bin/env bash
# Install what is missing, build (Release) and run the main job: the plane-strain peel scene of reading B of Fig. 10
# (decks/peel/peel_ps_flap90.inp: the flap lifted and pulled at 90 degrees; paper sections 7-9, docs/scenes.md; add
# --scene A for the 0-degree bridge, decks/peel/peel_ps.inp). It prints the steady peel force per unit width and
# writes the force-displacement CSV, a PNG plot (out/main/report/main/) and ParaView frames (out/main/run/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/tools/setup.sh" Release
build_dir=${LDFCZ_BUILD_DIR:-$root/build}
cd "$root"
/usr/bin/python3 tools/peel_study.py main --ldfcz "$build_dir/bin/ldfcz" \
  --reports "$root/out/main/report" --work "$root/out/main/run" "$@"
