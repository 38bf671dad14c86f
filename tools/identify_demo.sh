#!/usr/bin/env bash
# The identification demonstration of docs/identify.md and the README (issue 21): synthetic "measured" peel curves
# from the project's scene at known parameters with noise, identified by tools/identify.py on the main scene's mesh
# (plane strain, l_e = 10 um, n_z = 3, rigid substrate, 1 um/s). Reports land in reports/identify/.
#   tools/identify_demo.sh [--ldfcz PATH]     (default build/bin/ldfcz: build Release first, tools/setup.sh)
# Runs are cached in out/identify/cache (delete it for fresh run times).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
py=/usr/bin/python3
tool="$root/tools/identify.py"
rep="$root/reports/identify"
mkdir -p "$rep"
cache="$root/out/identify/cache"
rm -rf "$cache"
opts=(--cache "$cache" --jobs 2 "$@")
mesh=(--le 0.01 --nz 3)
fine=(--le 0.005 --nz 3)

# 1. The whole curve (50 um of pull): phi = 0.25 N/mm, T_max = 15 MPa, noise 0.01 N/mm (0.8 % of the peak),
#    fitted from the paper's values phi = 0.2, T_max = 20.
"$py" "$tool" synth -o "$rep/demo_curve.csv" --phi 0.25 --tmax 15 --noise 0.01 --seed 11 --points 60 \
  --u-max 0.05 "${mesh[@]}" "${opts[@]}"
"$py" "$tool" fit "$rep/demo_curve.csv" --force-unit N/mm --fit phi,tmax --start phi=0.2,tmax=20 \
  --name demo_fit "${mesh[@]}" "${opts[@]}"

# 2. Only the steady part of the curve (30-50 um of pull), Table 1 as printed, T_max = 20 MPa, noise 0.02 N/mm,
#    on the finer mesh l_e = 5 um (mesh-x study: 0.16 % from the converged force; on 10 um a doubled T_max still
#    moves the plateau by mesh ripple): T_max does not move the plateau measurably; the command says so.
"$py" "$tool" synth -o "$rep/demo_plateau.csv" --phi 0.2 --tmax 20 --noise 0.02 --seed 12 --points 30 \
  --u-min 0.03 --u-max 0.05 "${fine[@]}" "${opts[@]}"
"$py" "$tool" fit "$rep/demo_plateau.csv" --force-unit N/mm --fit phi,tmax --start phi=0.15,tmax=25 \
  --name demo_plateau "${fine[@]}" "${opts[@]}"

# 3. A "measured" 3D curve (3D quarter model, b = 0.04 mm, n_y = 2) as a force in N on a 0.08 mm wide specimen,
#    fitted in plane strain with the plane-strain/3D ratio of this mesh over 50 um of pull (1.1963 / 1.0913 =
#    1.0962, measured by an earlier study; stmt-3d-fine gives 1.0984 over 0.1 mm), then one confirming 3D run at
#    the fitted values.
"$py" "$tool" synth -o "$rep/demo_3d_curve.csv" --3d --model-width 0.04 --ny 2 --phi 0.25 --tmax 15 \
  --noise 0.01 --seed 13 --points 60 --u-max 0.05 --force-unit N --width 0.08 "${mesh[@]}" "${opts[@]}"
"$py" "$tool" fit "$rep/demo_3d_curve.csv" --force-unit N --width 0.08 --fit phi,tmax --start phi=0.2,tmax=20 \
  --ps3d-ratio 1.0962 --confirm-3d --model-width 0.04 --ny 2 --name demo_3d "${mesh[@]}" "${opts[@]}"
echo "identify_demo: reports in $rep (demo_fit.md, demo_plateau.md, demo_3d.md)"
