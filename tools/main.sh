#!/usr/bin/env bash
# Install what is missing, build (Release) and run the main job.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/tools/setup.sh" Release
build_dir=${LDFCZ_BUILD_DIR:-$root/build}
# Until the host's peel scene lands, the main job is the single-element cohesive demo: it calls the UEL exactly as
# Abaqus would and prints the traction-separation table of the three unloading behaviours (paper Fig. 6).
"$build_dir/bin/cohesive_demo"
