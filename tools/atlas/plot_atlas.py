#!/usr/bin/env python3
"""Plots and tables of the run-time-vs-error atlas (docs/performance.md).

    python3 tools/atlas/plot_atlas.py docs/performance/atlas.json docs/figures/atlas/

reads the JSON of `clearsky atlas --json` (one or more files; models of later files replace
those of earlier ones) and writes into the output folder, as SVG: one chart per model (95th
percentile spectral error against the build cost and against the time of an 81-view batch,
the Pareto front drawn, the standard and draft settings marked), all.svg with every model, and
tables.md with the per-model tables and the "Quality levels" table of docs/performance.md.
Needs python3-matplotlib (deploy/install-deps.sh).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402

# Zero errors (a setting equal to its reference) and zero costs cannot be drawn on log axes.
ERROR_FLOOR = 1e-6
COST_FLOOR = 1e-6
DRAFT_MAX_P95 = 0.02
# SVGs that do not change when the data do not: no date, fixed ids.
matplotlib.rcParams["svg.hashsalt"] = "clearsky-atlas"
matplotlib.rcParams["svg.fonttype"] = "none"


def load(paths):
    """The models of every file, a later file's model replacing an earlier one's (a re-run after
    a model changed); each model keeps its own run's scope, dataset and threads."""
    models = {}
    for path in paths:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        meta = {k: v for k, v in doc.items() if k != "models"}
        meta["file"] = os.path.basename(path)
        for m in doc["models"]:
            models[m["model"]] = dict(m, run=meta)
    return list(models.values())


def build_cost(s):
    return s["build_cpu_s"] + s["sun_state_wall_s"]


def p95(s):
    return s["spectral_error"]["p95"]


def chart(ax, m, cost, label, front_key):
    settings = m["settings"]
    xs = [max(cost(s), COST_FLOOR) for s in settings]
    ys = [max(p95(s), ERROR_FLOOR) for s in settings]
    ax.scatter(xs, ys, s=18, color="tab:blue", zorder=3)
    for s, x, y in zip(settings, xs, ys):
        ax.annotate(s["name"], (x, y), fontsize=6, xytext=(3, 2), textcoords="offset points")
    front = [s for name in m[front_key] for s in settings if s["name"] == name]
    ax.plot([max(cost(s), COST_FLOOR) for s in front], [max(p95(s), ERROR_FLOOR) for s in front],
            color="tab:orange", lw=1, label="Pareto front", zorder=2)
    for s in settings:
        if s["name"] == "standard":
            ax.scatter([max(cost(s), COST_FLOOR)], [max(p95(s), ERROR_FLOOR)], s=60,
                       facecolors="none", edgecolors="black", label="standard", zorder=4)
        if s["name"] == m.get("draft"):
            ax.scatter([max(cost(s), COST_FLOOR)], [max(p95(s), ERROR_FLOOR)], s=90, marker="s",
                       facecolors="none", edgecolors="tab:green", label="draft", zorder=4)
    ax.axhline(DRAFT_MAX_P95, color="grey", lw=0.6, ls="--")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(label)
    ax.set_ylabel("95th percentile relative spectral error")
    ax.grid(True, which="both", lw=0.3)


def batch_cost(s):
    return s["batch_81_s"]


def model_figure(m, out):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    chart(axes[0], m, build_cost, "build CPU s (+ one per-sun preparation, wall s)",
          "pareto_build")
    chart(axes[1], m, batch_cost, "81-view batch, s", "pareto_query")
    axes[1].legend(fontsize=7, loc="best")
    ref = m["reference"]["name"]
    fig.suptitle(f"{m['model']} (version {m['version']}): error against its reference ({ref})",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"{m['model']}.svg"), metadata={"Date": None})
    plt.close(fig)


def all_figure(models, out):
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    colours = plt.get_cmap("tab10")
    for i, m in enumerate(models):
        for ax, cost, key in ((axes[0], build_cost, "pareto_build"),
                              (axes[1], batch_cost, "pareto_query")):
            xs = [max(cost(s), COST_FLOOR) for s in m["settings"]]
            ys = [max(p95(s), ERROR_FLOOR) for s in m["settings"]]
            ax.scatter(xs, ys, s=12, color=colours(i), label=m["model"])
            front = [s for n in m[key] for s in m["settings"] if s["name"] == n]
            ax.plot([max(cost(s), COST_FLOOR) for s in front],
                    [max(p95(s), ERROR_FLOOR) for s in front], color=colours(i), lw=1)
    for ax, label in ((axes[0], "build CPU s (+ one per-sun preparation)"),
                      (axes[1], "81-view batch, s")):
        ax.axhline(DRAFT_MAX_P95, color="grey", lw=0.6, ls="--")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("95th percentile relative spectral error")
        ax.grid(True, which="both", lw=0.3)
    axes[1].legend(fontsize=7)
    fig.suptitle("All models: error against each model's own reference; lines: Pareto fronts",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "all.svg"), metadata={"Date": None})
    plt.close(fig)


def fmt_bytes(b):
    return f"{b / 1e6:.1f} MB" if b >= 1e5 else f"{b / 1e3:.1f} kB" if b else "0"


def pct(x):
    return "-" if x is None else f"{100 * x:.3g}%"


def options_text(s):
    opts = ", ".join(f"{k}={v:g}" for k, v in sorted(s["options"].items()))
    grid = "" if s["grid"] == "paper_bins" else f" [{s['grid']}, {s['wavelengths']} wl]"
    return (opts or "defaults") + grid


def row(m, s, level=None):
    rmse = "-" if s["rmse"] is None else f"{s['rmse']:.3f}"
    first = [m["model"], level] if level else [s["name"]]
    return "| " + " | ".join(first + [
        options_text(s) if level else f"{s['build_wall_s']:.3g} / {s['build_cpu_s']:.3g}",
        f"{build_cost(s):.3g}" if level else fmt_bytes(s["table_bytes"]),
        fmt_bytes(s["table_bytes"]) if level else f"{1e6 * s['sun_state_wall_s']:.4g}",
        f"{1e6 * s['radiance_s']:.3g}",
        f"{1e6 * s['batch_81_s']:.4g}" if not level else
        f"{pct(s['spectral_error']['p95'])} / {pct(s['spectral_error']['max'])}",
        (f"{1e6 * s['sky_irradiance_s']:.4g}" if not level else rmse),
    ] + ([] if level else [
        f"{pct(s['spectral_error']['median'])} / {pct(s['spectral_error']['p95'])} / "
        f"{pct(s['spectral_error']['max'])}",
        f"{pct(s['luminance_error']['p95'])} / {pct(s['luminance_error']['max'])}", rmse])) + " |"


def tables(models):
    lines = []
    for m in models:
        g = m["geometry"]
        run = m["run"]
        lines += [f"### {m['model']}", "",
                  f"Run: `{run['file']}`, scope `{run.get('scope')}`, dataset "
                  f"`{run.get('dataset') or '-'}`, precompute threads "
                  f"{run.get('precompute_threads')}. "
                  f"Reference: {options_text(m['reference'])} ({m['reference_reason']}). "
                  f"Geometry: suns {g['sun_zeniths_deg']} deg, altitudes {g['altitudes_m']} m, "
                  f"{g['views']} views."]
        c = m.get("reference_check")
        if c:
            lines.append(f"Reference against one step finer ({options_text(c)}): median "
                         f"{pct(c['spectral_error']['median'])}, p95 "
                         f"{pct(c['spectral_error']['p95'])}, max "
                         f"{pct(c['spectral_error']['max'])}.")
        lines += [f"Pareto (build): {', '.join(m['pareto_build'])}; Pareto (query): "
                  f"{', '.join(m['pareto_query'])}; draft: {m.get('draft') or 'none'}.", "",
                  "| setting | build s wall / CPU | tables | sun state us | radiance us | "
                  "81 views us | sky irradiance us | spectral error median / p95 / max | "
                  "luminance p95 / max | RMSE |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        lines += [row(m, s) for s in m["settings"]]
        lines.append("")
    lines += ["### Quality levels", "",
              "| model | level | options | build s (CPU + sun) | bytes | radiance us | "
              "p95 / max error | RMSE |", "|---|---|---|---|---|---|---|---|"]
    for m in models:
        draft = next((s for s in m["settings"] if s["name"] == m.get("draft")), None)
        std = m["settings"][0]
        if draft:
            lines.append(row(m, draft, "draft"))
        lines.append(row(m, std, "standard"))
        # The reference's error is its difference to the check one step finer, when checked.
        ref = dict(m["reference"])
        check = m.get("reference_check")
        if check:
            ref["spectral_error"] = check["spectral_error"]
            lines.append(row(m, ref, "reference"))
        else:
            lines.append(row(m, ref, "reference").replace(
                f"| {pct(0.0)} / {pct(0.0)} |", "| unchecked |"))
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    out = argv[-1]
    os.makedirs(out, exist_ok=True)
    models = load(argv[1:-1])
    for m in models:
        model_figure(m, out)
    all_figure(models, out)
    with open(os.path.join(out, "tables.md"), "w", encoding="utf-8") as f:
        f.write(tables(models))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
