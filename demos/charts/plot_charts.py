#!/usr/bin/python3
"""Charts for docs/measurements.md from bsp_sweep's and bsp_truth's raw results (demos/charts.sh runs it).

usage: plot_charts.py RESULTS_DIR CHARTS_DIR

Reads RESULTS_DIR/{pareto,towers,scaling,truth,truth_grid}.csv (pareto also from RESULTS_DIR/pareto-*/), writes PNG and SVG charts to CHARTS_DIR and prints
the headline figures (also written to RESULTS_DIR/headline.txt). Needs Debian's python3-matplotlib.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Statuses of a configuration that ran the full 10 s and did what the scene asks (a seesaw's "did not
# tip" counts as stopped: statics says it must tip).
FINISHED = ("standing", "moved", "tipped")
STOCK = ["si", "si2f", "si-sub2", "si-sub4", "si-sub8", "nncg", "mlcp"]
# One style per solver variant: colour, marker. Plugin variants share a red ramp and a marker shape family.
STYLE = {
    "si": ("#1f77b4", "o"),
    "si2f": ("#17becf", "s"),
    "si-sub2": ("#2ca02c", "^"),
    "si-sub4": ("#006400", "v"),
    "si-sub8": ("#00441b", "<"),
    "nncg": ("#9467bd", "D"),
    "mlcp": ("#7f7f7f", "P"),
    "sp f=0": ("#fdae61", "p"),
    "sp f=0.05": ("#f46d43", "h"),
    "sp f=0.1": ("#d73027", "X"),
    "sp f=0.25": ("#e7298a", "d"),
    "sp f=0.5": ("#67001f", "*"),
    "sp-classic f=0.5": ("#000000", "*"),
}
SCENE_TITLES = {
    "tower_10": "tower of 10 boxes",
    "tower_20": "tower of 20 boxes",
    "tower_40": "tower of 40 boxes",
    "pyramid_20": "pyramid, base 20 (210 boxes)",
    "pyramid_30": "pyramid, base 30 (465 boxes)",
    "wall": "wall, 200 pieces",
    "round_tower": "round tower, 320 bricks",
    "mass_ratio_100": "4-box tower, top 100x heavier",
    "mass_ratio_1000": "4-box tower, top 1000x heavier",
    "seesaw": "seesaw with a stack on one end",
}
METRICS = [
    # column, y label, floor for the log axis, file name
    ("max_drift_m", "max drift over 10 s (m)", 1e-8, "pareto_drift"),
    ("max_penetration_m", "max penetration over 10 s (m)", 1e-6, "pareto_penetration"),
    ("ground_error", "ground reaction error |F/W - 1| (last second)", 1e-6, "pareto_ground"),
    ("residual_end", "complementarity residual, last step (relative)", 1e-6, "pareto_residual"),
    ("distance_end", "distance from reference |x - x*|_A / |x*|_A, last step", 1e-6, "pareto_distance"),
    ("residual", "complementarity residual, first step, cold (relative)", 1e-6, "pareto_residual_first"),
]


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def num(text):
    return float(text) if text not in ("", None) else math.nan


def log_ticks(axis):
    """Plain numbers on a log axis, with 2 and 5 between the powers of ten."""
    fmt = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    axis.set_major_formatter(fmt)
    axis.set_minor_locator(matplotlib.ticker.LogLocator(subs=(2.0, 5.0)))
    axis.set_minor_formatter(fmt)


def save(fig, out_dir, name):
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=80, bbox_inches="tight")
    plt.close(fig)


def pareto_front(points):
    """Points (x, y) not beaten on both cost and error by another, sorted by cost."""
    front, best = [], math.inf
    for x, y in sorted(points):
        if y < best:
            front.append((x, y))
            best = y
    return front


def plot_pareto(rows, out_dir):
    all_scenes = [s for s in SCENE_TITLES if any(r["scene"] == s for r in rows)]
    for column, ylabel, floor, name in METRICS:
        # Only the scenes that have this measure (the warm-started reference is run on small scenes only).
        scenes = [s for s in all_scenes if any(r["scene"] == s and not math.isnan(num(r.get(column))) for r in rows)]
        if not scenes:
            continue
        ncols = 2
        nrows = math.ceil(len(scenes) / ncols)
        fig, axes = plt.subplots(nrows, ncols, figsize=(12, 3.4 * nrows), squeeze=False)
        for ax, scene in zip(axes.flat, scenes):
            mine = [r for r in rows if r["scene"] == scene]
            points = []
            for solver, (color, marker) in STYLE.items():
                series = sorted((r for r in mine if r["solver"] == solver), key=lambda r: int(r["iterations"]))
                xs, ys, full = [], [], []
                for r in series:
                    x, y = num(r["ms_per_step"]), num(r.get(column))
                    if math.isnan(x) or math.isnan(y):
                        continue
                    xs.append(x)
                    ys.append(max(y, floor))
                    full.append(r["status"] in FINISHED)
                    if r["status"] in FINISHED:
                        points.append((x, max(y, floor)))
                if not xs:
                    continue
                ax.plot(xs, ys, color=color, linewidth=0.8, alpha=0.6)
                ax.scatter([x for x, f in zip(xs, full) if f], [y for y, f in zip(ys, full) if f], color=color,
                           marker=marker, s=36, label=solver, zorder=3)
                ax.scatter([x for x, f in zip(xs, full) if not f], [y for y, f in zip(ys, full) if not f],
                           facecolors="none", edgecolors=color, marker=marker, s=36, zorder=3)
            meant_to_move = any(r.get("expect_standing") == "0" for r in mine)
            # Drift is the motion of a scene meant to move, not an error: no front there.
            front = [] if (meant_to_move and column == "max_drift_m") else pareto_front(points)
            if front:
                fx, fy = zip(*front)
                ax.step(fx, fy, where="post", color="black", linestyle="--", linewidth=1, label="Pareto front", zorder=2)
            if column == "max_drift_m" and not meant_to_move:
                ax.axhline(0.01, color="grey", linestyle=":", linewidth=1)
                ax.text(ax.get_xlim()[0] if False else 1.02, 0.01, " 1 cm", color="grey", fontsize=8,
                        transform=ax.get_yaxis_transform(), va="center")
            ax.set_xscale("log")
            ax.set_yscale("log")
            log_ticks(ax.xaxis)
            ax.tick_params(axis="x", which="minor", labelsize=7)
            low, high = ax.get_ylim()
            if high < 100 * low:  # under two decades: few powers of ten to label, so label 2 and 5 too
                log_ticks(ax.yaxis)
                ax.tick_params(axis="y", which="minor", labelsize=7)
            title = SCENE_TITLES[scene]
            if meant_to_move:
                title += "\n(must tip: drift is its motion; hollow: did not tip)" if column == "max_drift_m" else \
                    "\n(must tip; hollow: did not tip)"
            ax.set_title(title, fontsize=10)
            ax.set_xlabel("ms per step (60 Hz, this machine)", fontsize=9)
            ax.set_ylabel(ylabel, fontsize=9)
            ax.grid(True, which="major", alpha=0.3)
            ax.tick_params(labelsize=8)
        for ax in list(axes.flat)[len(scenes):]:
            ax.axis("off")
        handles, labels = axes.flat[0].get_legend_handles_labels()
        for ax in axes.flat:
            h, l = ax.get_legend_handles_labels()
            for hh, ll in zip(h, l):
                if ll not in labels:
                    handles.append(hh)
                    labels.append(ll)
        fig.tight_layout()
        fig.legend(handles, labels, loc="lower center", ncol=6, fontsize=9, bbox_to_anchor=(0.5, 1.0),
                   title="one marker per iteration count (1, 2, 5, 10, 20, 50, 100, 200, left to right; plugin f = 0.05-0.25 and "
                         "sp-classic up to 200); hollow: stopped early (a body past 0.1 m, NaN, or MLCP did not finish)", title_fontsize=9)
        save(fig, out_dir, name)


def plot_towers(rows, out_dir):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    limit = max(int(r["max_iterations_tried"]) for r in rows)
    for solver in dict.fromkeys(r["solver"] for r in rows):
        color, marker = STYLE.get(solver, ("black", "o"))
        mine = sorted((r for r in rows if r["solver"] == solver), key=lambda r: int(r["boxes"]))
        ns = [int(r["boxes"]) for r in mine if r["iterations_needed"]]
        ks = [num(r["iterations_needed"]) for r in mine if r["iterations_needed"]]
        ax.plot(ns, ks, color=color, marker=marker, label=solver)
        missing = [int(r["boxes"]) for r in mine if not r["iterations_needed"]]
        if missing:
            ax.scatter(missing, [limit * 1.6] * len(missing), color=color, marker="^", s=50,
                       label=f"{solver}: none up to {limit}")
    si = [(int(r["boxes"]), num(r["iterations_needed"])) for r in rows if r["solver"] == "si" and r["iterations_needed"]]
    if si:
        n0, k0 = max(si)
        ns = [2, 40]
        ax.plot(ns, [k0 * (n / n0) ** 2 for n in ns], color="grey", linestyle=":", label="~ N^2 (seed: O(k n^2))")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks([2, 4, 6, 10, 20, 40])
    ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.set_ylim(0.7, limit * 3)
    ax.set_xlabel("boxes in the tower, N")
    ax.set_ylabel("iterations needed (within 1 cm for 10 s)")
    ax.set_title("Iterations to keep a tower of N standing")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save(fig, out_dir, "towers_iterations")


PHASES = [
    ("collision_ms", "collision detection (both CDs)", "#bdbdbd"),
    ("graph_ms", "contact graph + layers", "#e41a1c"),
    ("setup_ms", "Bullet's row setup (once per step)", "#fb9a99"),
    ("predictor_ms", "predictor (shock propagation)", "#4daf4a"),
    ("corrector_ms", "corrector (ceil(f N) sweeps at most)", "#377eb8"),
    ("correction_ms", "finish and position correction", "#984ea3"),
    ("other_ms", "other (islands, integration)", "#ff7f00"),
]


def plot_scaling(rows, out_dir):
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(16, 4.8))
    for solver in dict.fromkeys(r["solver"] for r in rows):
        color, marker = STYLE.get(solver, ("black", "o"))
        mine = sorted((r for r in rows if r["solver"] == solver), key=lambda r: int(r["bodies"]))
        bodies = [int(r["bodies"]) for r in mine]
        ms = [num(r["ms_per_step"]) for r in mine]
        ax1.plot(bodies, ms, color=color, marker=marker, label=solver)
        ax3.plot(bodies, [1e3 * m / b for m, b in zip(ms, bodies)], color=color, marker=marker, label=f"{solver}: whole step")
        if solver.startswith("sp"):
            ax3.plot(bodies, [1e3 * num(r["graph_ms"]) / b for r, b in zip(mine, bodies)], color=color, marker=marker,
                     linestyle="--", label=f"{solver}: graph + layers")
    last = max(rows, key=lambda r: int(r["bodies"]))
    b_max = int(last["bodies"])
    for r in rows:
        if int(r["bodies"]) == b_max:
            ax1.plot([55, b_max], [num(r["ms_per_step"]) * 55 / b_max, num(r["ms_per_step"])], color="grey", linestyle=":",
                     linewidth=1)
    ax1.plot([], [], color="grey", linestyle=":", label="linear in bodies")
    ax1.set_xscale("log")
    ax1.set_yscale("log")
    ax1.set_xlabel("bodies (pyramid boxes)")
    ax1.set_ylabel("ms per step")
    ax1.set_title("Cost per step, 10 iterations")
    ax1.legend(fontsize=8)
    ax1.grid(True, which="major", alpha=0.3)

    plugin = sorted((r for r in rows if r["solver"].startswith("sp")), key=lambda r: int(r["bodies"]))
    labels = [r["bodies"] for r in plugin]
    bottom = [0.0] * len(plugin)
    for column, label, color in PHASES:
        share = [100 * num(r.get(column, 0)) / num(r["ms_per_step"]) for r in plugin]
        ax2.bar(labels, share, bottom=bottom, color=color, label=label)
        bottom = [b + s for b, s in zip(bottom, share)]
    ax2.axhline(10, color="black", linestyle=":", linewidth=1, label="10% (target for graph + layers)")
    ax2.set_xlabel("bodies (pyramid boxes)")
    ax2.set_ylabel("share of a plugin step (%)")
    ax2.set_title(f"Plugin step by phase ({plugin[0]['solver'] if plugin else ''})")
    ax2.tick_params(axis="x", labelrotation=45, labelsize=8)
    ax2.set_ylim(0, 100)
    ax2.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=2)

    ax3.set_xscale("log")
    ax3.set_yscale("log")
    ax3.set_xlabel("bodies (pyramid boxes)")
    ax3.set_ylabel("microseconds per body per step")
    ax3.set_title("Cost per body (flat = linear growth)")
    ax3.legend(fontsize=8)
    ax3.grid(True, which="major", alpha=0.3)
    fig.tight_layout()
    save(fig, out_dir, "scaling")


# truth_vs_cost: one colour per solver family; stock families in cool colours, plugin modes in reds.
TRUTH_STYLE = {
    "si": ("#1f77b4", "o"),
    "si2f": ("#17becf", "s"),
    "si-sub2": ("#2ca02c", "^"),
    "si-sub4": ("#006400", "v"),
    "si-sub8": ("#00441b", "<"),
    "nncg": ("#9467bd", "D"),
    "mlcp": ("#7f7f7f", "P"),
    "sp": ("#d73027", "*"),
    "sp-solver": ("#f46d43", "X"),
    "sp-classic": ("#000000", "p"),
    "sp-solver-classic": ("#67001f", "h"),
}


def truth_points(rows):
    """Per configuration (in the CSV's order): config, iterations, truths passed, mean ms per step over the cases
    that ran, cases skipped."""
    points = []
    for config, iterations in dict.fromkeys((r["config"], int(r["iterations"])) for r in rows):
        mine = [r for r in rows if r["config"] == config and int(r["iterations"]) == iterations]
        ran = [r for r in mine if r["pass"] != "skipped" and not math.isnan(num(r["msPerStep"]))]
        if not ran:
            continue
        passed = sum(1 for r in ran if r["pass"] == "1")
        ms = sum(num(r["msPerStep"]) for r in ran) / len(ran)
        points.append((config, iterations, passed, ms, len(mine) - len(ran)))
    return points


def overlaps(box, boxes):
    return any(box.x0 < b.x1 and b.x0 < box.x1 and box.y0 < b.y1 and b.y0 < box.y1 for b in boxes)


# The converged reference of tests/truth/ShapeGridTest.cpp and PushedGridTest.cpp (stock SI, 8 sub-steps x 100
# iterations): demos/charts.sh runs it on the grid beside truth_vs_cost's configurations.
GRID_REFERENCE = ("si-sub8", 100)


def plot_truth_grid(rows, out_dir):
    """The shape grid (bsp_truth --grid): truths held of the grid's cases against mean ms per step over them, one point
    per configuration, as truth_vs_cost; the counts are far apart in the markers' units, so labels are placed where
    they overlap no other label or marker (display coordinates) rather than stacked by count."""
    cases = list(dict.fromkeys(r["case"] for r in rows))
    groups = list(dict.fromkeys(r["group"] for r in rows))
    points = truth_points(rows)
    fig, ax = plt.subplots(figsize=(10, 7))
    seen = set()
    for config, iterations, passed, ms, skipped in points:
        color, marker = TRUTH_STYLE.get(config, ("black", "o"))
        ax.scatter([ms], [passed], color=color if not skipped else "white", edgecolors=color, marker=marker, s=70, zorder=3,
                   label=config if config not in seen else None)
        seen.add(config)
    ax.set_xscale("log")
    log_ticks(ax.xaxis)
    top = len(cases)
    ax.set_ylim(-0.08 * top, 1.1 * top)
    ax.set_yticks(range(0, top + 1, 5))
    ax.axhline(top, color="grey", linestyle=":", linewidth=1)
    ax.set_xlabel("mean ms per step over the cases (log)")
    ax.set_ylabel(f"truths held (of {top})")
    per = ", ".join(f"{sum(1 for c in dict.fromkeys((r['case'], r['group']) for r in rows) if c[1] == g)} {g}" for g in groups)
    ax.set_title(f"Shape grid (shapes and structures x 5 grounds): physics statements held against cost per step\n({per})", fontsize=11)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", title="hollow: some cases skipped (MLCP over its time limit)", title_fontsize=7)
    low, high = ax.get_xlim()
    ax.set_xlim(low, high * 1.3)  # room for the labels of the costliest points
    fig.tight_layout()  # before the labels are placed: it moves the axes
    # Labels: for each point (highest count first) the first offset whose text box overlaps no placed label or marker.
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    taken = [ax.get_legend().get_window_extent(renderer)]
    inside = ax.get_window_extent(renderer)
    for _, _, passed, ms, _ in points:
        x, y = ax.transData.transform((ms, passed))
        taken.append(matplotlib.transforms.Bbox.from_extents(x - 7, y - 7, x + 7, y + 7))
    offsets = [(6, 3, "left"), (6, -10, "left"), (-6, 3, "right"), (-6, -10, "right")] + \
        [(dx, dy, ha) for k in range(1, 8) for dy in (3 + 10 * k, -10 - 10 * k) for dx, ha in ((6, "left"), (-6, "right"))]
    for config, iterations, passed, ms, skipped in sorted(points, key=lambda p: -p[2]):
        color, _ = TRUTH_STYLE.get(config, ("black", "o"))
        text = config if config == "mlcp" else f"{config} {iterations}"
        if (config, iterations) == GRID_REFERENCE:
            text += " (the ctest grid's reference)"
        if skipped:
            text += f" ({skipped} skipped)"
        text += f": {passed}"
        for dx, dy, ha in offsets:
            label = ax.annotate(text, (ms, passed), textcoords="offset points", xytext=(dx, dy), fontsize=7, color=color, ha=ha,
                                arrowprops=None if abs(dy) <= 10 else dict(arrowstyle="-", color=color, linewidth=0.5, alpha=0.6))
            label.update_positions(renderer)
            box = matplotlib.text.Text.get_window_extent(label, renderer)  # the text alone, not its leader line
            if inside.x0 <= box.x0 and box.x1 <= inside.x1 and inside.y0 <= box.y0 and box.y1 <= inside.y1 and not overlaps(box, taken):
                break
            label.remove()
        else:
            label = ax.annotate(text, (ms, passed), textcoords="offset points", xytext=(6, 3), fontsize=7, color=color)
            box = matplotlib.text.Text.get_window_extent(label, renderer)
        taken.append(box)
    save(fig, out_dir, "truth_vs_cost_grid")


def plot_truth(rows, out_dir):
    """Truths passed against mean ms per step over the cases, one point per configuration."""
    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, ax = plt.subplots(figsize=(9, 5.5))
    seen = set()
    placed = {}  # truths passed -> log10(ms) of the labels already at that height
    for config, iterations, passed, ms, skipped in truth_points(rows):
        color, marker = TRUTH_STYLE.get(config, ("black", "o"))
        ax.scatter([ms], [passed], color=color if not skipped else "white", edgecolors=color, marker=marker, s=70, zorder=3,
                   label=config if config not in seen else None)
        seen.add(config)
        text = config if config == "mlcp" else f"{config} {iterations}"
        if skipped:
            text += f" ({skipped} skipped)"
        # Labels of configurations at the same count and nearly the same cost are stacked, not overdrawn:
        # the first above its point, the others downwards below it (upwards they reach the title).
        near = sum(1 for x in placed.get(passed, []) if abs(x - math.log10(ms)) < 0.25)
        placed.setdefault(passed, []).append(math.log10(ms))
        ax.annotate(text, (ms, passed), textcoords="offset points", xytext=(5, 4 if near == 0 else -4 - 8 * near), fontsize=7,
                    rotation=30 if near == 0 else 0, color=color)
    ax.set_xscale("log")
    log_ticks(ax.xaxis)
    ax.set_ylim(-0.5, len(cases) + 1.8)
    ax.set_yticks(range(len(cases) + 1))
    ax.set_xlabel("mean ms per step over the cases (log)")
    ax.set_ylabel(f"truths passed (of {len(cases)})")
    ax.set_title("Truth suite: physics statements held against cost per step")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right", title="hollow: some cases skipped (MLCP over its time limit)", title_fontsize=7)
    fig.tight_layout()
    save(fig, out_dir, "truth_vs_cost")


# The plugin's defaults (btShockPropagationSettings::m_weighting): bsp_truth's "sp" configuration is this
# pareto solver label.
PLUGIN_DEFAULT = "sp f=0.5"


def truth_passing(truth):
    """(config, iterations) of every truth-suite configuration that passed all its cases."""
    cases, passed = {}, {}
    for r in truth:
        key = (r["config"], r["iterations"])
        cases[key] = cases.get(key, 0) + 1
        passed[key] = passed.get(key, 0) + (1 if r["pass"] == "1" else 0)
    return {key for key, n in cases.items() if n > 0 and passed[key] == n}


def plugin_qualifies(r, passing):
    """Issue 16's plugin side: a run of the default plugin at an iteration count that passes the truth suite."""
    return r["solver"] == PLUGIN_DEFAULT and ("sp", r["iterations"]) in passing


def scene_cheapest(pareto, scene, is_plugin):
    """For one scene: the runs that held it, the cheapest plugin run among them (is_plugin picks which
    plugin runs count), the cheapest stock run among them, and the costliest stock run tried (held or
    not; nan if none ran): the lower bound on stock's cost where no stock run holds."""
    mine = [r for r in pareto if r["scene"] == scene and r["status"] == "standing"]
    best_sp = min((r for r in mine if is_plugin(r)), key=lambda r: num(r["ms_per_step"]), default=None)
    best_stock = min((r for r in mine if r["family"] in STOCK), key=lambda r: num(r["ms_per_step"]), default=None)
    tried = [num(r["ms_per_step"]) for r in pareto if r["scene"] == scene and r["family"] in STOCK]
    costliest = max((t for t in tried if not math.isnan(t)), default=math.nan)
    return mine, best_sp, best_stock, costliest


def cheapest_table(pareto, truth):
    """Markdown: per scene, the cheapest plugin run that holds (within 1 cm for 10 s) and passes the truth
    suite, and per stock family the cheapest run that holds, with its cost over the plugin's."""
    passing = truth_passing(truth)
    scenes = []
    for r in pareto:
        if r["scene"] not in scenes and r["scene"] != "seesaw":  # the seesaw must tip: no holding to compare
            scenes.append(r["scene"])
    lines = ["| scene | plugin (truths passed, holds) | " + " | ".join(STOCK) + " | cheapest stock / plugin |",
             "|---|---|" + "---|" * (len(STOCK) + 1)]
    for scene in scenes:
        mine, sp, best_stock, costliest = scene_cheapest(pareto, scene, lambda r: plugin_qualifies(r, passing))
        cells = [scene, f"{sp['iterations']} it, {num(sp['ms_per_step']):.3g} ms" if sp else "none"]
        for family in STOCK:
            best = min((r for r in mine if r["family"] == family), key=lambda r: num(r["ms_per_step"]), default=None)
            ran = [r for r in pareto if r["scene"] == scene and r["family"] == family and not math.isnan(num(r["ms_per_step"]))]
            if best is None:
                cells.append("none" if ran else "not run")
                continue
            text = f"{best['iterations']} it, {num(best['ms_per_step']):.3g} ms" if family != "mlcp" else f"{num(best['ms_per_step']):.3g} ms"
            if sp:
                text += f" ({num(best['ms_per_step']) / num(sp['ms_per_step']):.1f}x)"
            cells.append(text)
        # The cheapest stock run that holds over the plugin's; where none holds, the costliest stock run
        # tried (which does not hold) over the plugin's is a lower bound.
        if not sp:
            cells.append("-")
        elif best_stock:
            cells.append(f"{num(best_stock['ms_per_step']) / num(sp['ms_per_step']):.1f}x")
        else:
            cells.append(f"> {costliest / num(sp['ms_per_step']):.1f}x (none holds)")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def headline(pareto, scaling, truth):
    lines = []
    passing = truth_passing(truth)
    for scene in ("wall", "round_tower", "pyramid_30"):
        # Issue 16: the plugin's configuration must also pass the truth suite (f = 0, say, holds stacks
        # but fails truths); without truth results every plugin run counts.
        _, best_sp, best_stock, costliest = scene_cheapest(
            pareto, scene, lambda r: r["family"] == "sp" and (not passing or plugin_qualifies(r, passing)))

        def describe(r):
            return f"{r['solver']} it={r['iterations']} {num(r['ms_per_step']):.3f} ms/step" if r else "none"

        if best_sp and best_stock:
            ratio = num(best_stock["ms_per_step"]) / num(best_sp["ms_per_step"])
            verdict = f"stock/plugin = {ratio:.2f}x (target >= 10x: {'met' if ratio >= 10 else 'not met'})"
        elif best_sp:
            # No stock configuration holds: stock needs more than the costliest one tried.
            ratio = costliest / num(best_sp["ms_per_step"])
            verdict = (f"stock/plugin > {ratio:.1f}x (no stock configuration holds; the costliest tried, "
                       f"{costliest:.3f} ms/step, does not) (target >= 10x: {'met' if ratio >= 10 else 'not shown'})")
        else:
            verdict = "the plugin holds it in no configuration (target: not met)"
        which = "plugin (passing the truth suite)" if passing else "plugin"
        lines.append(f"{scene}: cheapest within 1 cm for 10 s: {which} {describe(best_sp)}; stock {describe(best_stock)}; {verdict}")
    plugin = sorted((r for r in scaling if r["solver"].startswith("sp")), key=lambda r: int(r["bodies"]))
    if plugin:
        big = plugin[-1]
        share = 100 * num(big["graph_ms"]) / num(big["ms_per_step"])
        lines.append(f"graph + layers at {big['bodies']} bodies: {num(big['graph_ms']):.2f} of {num(big['ms_per_step']):.1f} ms "
                     f"= {share:.1f}% of a plugin step (target < 10%: {'met' if share < 10 else 'not met'})")
        small = next((r for r in plugin if int(r["bodies"]) >= 800), plugin[0])
        for column, name in (("ms_per_step", "plugin step"), ("graph_ms", "graph + layers")):
            b0, b1 = int(small["bodies"]), int(big["bodies"])
            if b1 <= b0:
                continue
            slope = math.log(num(big[column]) / num(small[column])) / math.log(b1 / b0)
            lines.append(f"{name}: cost ~ bodies^{slope:.2f} from {b0} to {b1} bodies (1.00 = linear)")
    return lines


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    results, charts = sys.argv[1], sys.argv[2]
    os.makedirs(charts, exist_ok=True)
    # pareto.csv, or the parts of demos/charts.sh's two processes (pareto-*/pareto.csv)
    parts = [os.path.join(results, "pareto.csv")] + sorted(
        os.path.join(results, d, "pareto.csv") for d in os.listdir(results) if d.startswith("pareto-"))
    pareto = [row for path in parts if os.path.exists(path) for row in read(path)]
    towers_csv, scaling_csv = os.path.join(results, "towers.csv"), os.path.join(results, "scaling.csv")
    towers = read(towers_csv) if os.path.exists(towers_csv) else []
    scaling = read(scaling_csv) if os.path.exists(scaling_csv) else []
    truth_csv = os.path.join(results, "truth.csv")
    truth = read(truth_csv) if os.path.exists(truth_csv) else []
    grid_csv = os.path.join(results, "truth_grid.csv")  # bsp_truth --grid: the shape grid's cases
    grid = read(grid_csv) if os.path.exists(grid_csv) else []
    if pareto:
        plot_pareto(pareto, charts)
    if towers:
        plot_towers(towers, charts)
    if scaling:
        plot_scaling(scaling, charts)
    if truth:
        plot_truth(truth, charts)
    if grid:
        plot_truth_grid(grid, charts)
    if not pareto and not scaling:
        return  # only other results (e.g. truth.csv): no headline to state
    lines = headline(pareto, scaling, truth)
    with open(os.path.join(results, "headline.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    if pareto and truth:
        # Issue 16's table: the cheapest plugin run that holds and passes the truth suite, against each stock family.
        table = cheapest_table(pareto, truth)
        with open(os.path.join(results, "cheapest.md"), "w") as f:
            f.write("\n".join(table) + "\n")
        print("\n".join(table))


if __name__ == "__main__":
    main()
