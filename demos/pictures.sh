#!/usr/bin/env bash
# Regenerates the pictures of README and docs/measurements.md (docs/pictures/*.png) with
# bsp_viewer --headless: offscreen through EGL on Mesa's software renderer, no display or GPU
# needed. Installs what is missing and builds first (the float build of tests/run.sh, with the
# viewer). Each picture: columns = solvers, rows = moments in time.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tests/install-deps.sh"
build="$root/build/float"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBSP_REQUIRE_VIEWER=ON >/dev/null
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target bsp_viewer
out="$root/docs/pictures"
mkdir -p "$out"
viewer="$build/demos/viewer/bsp_viewer"
picture() {
  local file="$1"
  shift
  echo "bsp_viewer --headless --palette --out docs/pictures/$file $*"
  "$viewer" --headless --palette --out "$out/$file" "$@" >/dev/null
}
# The seed's first figures: after 4 s, stock SI at 10 and 100 iterations, the plugin at 10,
# coloured by drift (red: moved 1 cm or more from the start).
picture wall_4s.png --scene wall --solvers si,si,sp --iterations 10,100,10 --times 4 --colour drift
picture round_tower_4s.png --scene round_tower --solvers si,si,sp --iterations 10,100,10 --times 4 --colour drift
# A 20-box tower at frame 6, coloured by drift, and its sequence.
picture tower_frame6.png --scene tower --param n=20 --solvers si,sp --frames 6 --colour drift --size 260x300
picture tower_sequence.png --scene tower --param n=20 --solvers si,sp --times 2,4,6,8 --size 250x250
# Dense random stacking, coloured by stack layer (the plugin's contact-graph heights).
picture dense_random.png --scene dense_random --solvers si,sp --times 2,8 --colour layers --pitch 50 --frame-at 8 --size 300x240
# Mass ratio: the top box is 1000 times heavier than the three under it.
picture mass_ratio_tower.png --scene mass_ratio_tower --solvers si,si,sp --iterations 10,100,10 --times 0.25,4 --size 260x200
du -ch "$out"/*.png | tail -1
