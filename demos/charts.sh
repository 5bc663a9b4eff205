#!/usr/bin/env bash
# Regenerates every chart of docs/measurements.md from scratch: installs what is missing (Debian
# packages: tests/install-deps.sh plus python3-matplotlib), builds bsp_sweep and bsp_truth (Release,
# float), runs the three studies and the truth suite (bsp_truth: every truth case under every solver
# configuration) under nice and plots them with Debian's /usr/bin/python3.
#   results (CSV + JSON): build/sweep/        charts (PNG + SVG): demos/charts/images/
# The speed-against-accuracy sweep runs as two processes over two halves of the scene list (the
# machine has two cores); inside each scene every configuration is stepped in lockstep, so load
# from anything else hits all of them alike. The towers and scaling studies run after it, alone.
# The shape grid (bsp_truth --grid: 105 cases, about 2-3 minutes) gives truth_vs_cost_grid.
#   demos/charts.sh grid   only the shape grid: its run, truth_vs_cost_grid and its results (build/truth-grid/)
# BSP_CHARTS_BUILD names another build directory (default build/float).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tests/install-deps.sh" python3-matplotlib
build="${BSP_CHARTS_BUILD:-$root/build/float}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
# The shape grid under the configurations of truth_vs_cost (bsp_truth's default list) and the ctest
# grid's converged reference, stock SI at 8 sub-steps x 100 iterations; writes DIR/truth_grid.{csv,md}.
grid_configs="si:1,si:2,si:5,si:10,si:20,si:50,si:100,si:200,si2f:10,si-sub2:10,si-sub4:10,si-sub8:10,si-sub8:100,nncg:10,nncg:50,mlcp,"
grid_configs+="sp:5,sp:10,sp:20,sp-solver:5,sp-solver:10,sp-solver:20,sp-classic:10"
run_grid() {
  nice -n 10 "$build/demos/truth/bsp_truth" --grid --configs "$grid_configs" --csv "$1/truth_grid.csv" --md "$1/truth_grid.md"
}
if [ "${1:-}" = grid ]; then
  cmake --build "$build" -j1 --target bsp_truth
  results="$root/build/truth-grid"
  rm -rf "$results"
  mkdir -p "$results" "$root/demos/charts/results"
  run_grid "$results"
  /usr/bin/python3 "$root/demos/charts/plot_charts.py" "$results" "$root/demos/charts/images"
  cp "$results"/truth_grid.* "$root/demos/charts/results/"
  exit 0
fi
cmake --build "$build" -j1 --target bsp_sweep bsp_truth
sweep="$build/demos/sweep/bsp_sweep"
results="$root/build/sweep"
rm -rf "$results"
mkdir -p "$results/pareto-a" "$results/pareto-b"
nice -n 10 "$sweep" pareto --out "$results/pareto-a" --scenes pyramid_30,wall,tower_10,tower_20,mass_ratio_100,mass_ratio_1000,seesaw &
first=$!
nice -n 10 "$sweep" pareto --out "$results/pareto-b" --scenes round_tower,pyramid_20,tower_40
wait "$first"
nice -n 10 "$sweep" scaling --out "$results"
nice -n 10 "$sweep" towers --out "$results"
nice -n 10 "$build/demos/truth/bsp_truth" --csv "$results/truth.csv" --md "$results/truth.md"
run_grid "$results"
/usr/bin/python3 "$root/demos/charts/plot_charts.py" "$results" "$root/demos/charts/images"
# The raw results docs/measurements.md's readings come from, kept next to the charts.
mkdir -p "$root/demos/charts/results"
cp "$results"/scaling.* "$results"/towers.* "$results"/truth.* "$results"/truth_grid.* "$results"/headline.txt "$results"/cheapest.md "$root/demos/charts/results/"
for part in "$results"/pareto-*; do cp "$part/pareto.csv" "$root/demos/charts/results/$(basename "$part").csv"; cp "$part/pareto.json" "$root/demos/charts/results/$(basename "$part").json"; done
