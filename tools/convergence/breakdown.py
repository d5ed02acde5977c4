#!/usr/bin/env python3
"""Breakdown of a per-sample convergence table (tools/convergence/README.md).

    python3 tools/convergence/breakdown.py samples.tsv [FLOOR]

reads the tab-separated output of clearsky_sample_convergence and prints the count, median,
95th percentile (nearest rank, as the atlas: models/atlas/error_summary.cpp) and maximum of the
relative difference overall and grouped by sun zenith, altitude, view zenith and the view's
place (above the horizon, within 2 degrees of it, below it), then the 15 largest samples.
FLOOR (a fraction, e.g. 0.01): also the same statistics of the difference relative to
max(radiance, FLOOR x the mean radiance of the sky at that sun and altitude).
"""
import csv
import math
import sys


def summary(values):
    if not values:
        return "      0"
    v = sorted(values)

    def rank(q):
        return v[min(max(math.ceil(q * len(v)), 1), len(v)) - 1]

    return f"{len(v):7d} median {rank(0.5):10.3g} p95 {rank(0.95):10.3g} max {v[-1]:10.3g}"


def place(view_zenith):
    if view_zenith > 90.0:
        return "below"
    return "horizon" if view_zenith >= 88.0 else "above"


def main():
    rows = list(csv.DictReader(open(sys.argv[1], encoding="utf-8"), delimiter="\t"))
    floor = float(sys.argv[2]) if len(sys.argv) > 2 else None
    for r in rows:
        for k in r:
            r[k] = float(r[k])
        if floor is not None:
            # rel_l2 is |diff| / |fine| in the L2 norm over the bins; the mean over the bins
            # stands for the spectrum's size when the floor replaces it.
            r["floored"] = r["rel_l2"] * r["mean_fine"] / max(r["mean_fine"],
                                                             floor * r["mean_sky_fine"])
    keys = ["rel_l2"] + (["floored"] if floor is not None else [])
    for key in keys:
        print(f"== {key}")
        print("all        ", summary([r[key] for r in rows]))
        for name, group in (("sun", lambda r: r["sun_zenith_deg"]),
                            ("altitude", lambda r: r["altitude_m"]),
                            ("view", lambda r: r["view_zenith_deg"]),
                            ("place", lambda r: place(r["view_zenith_deg"]))):
            for g in sorted({group(r) for r in rows}, key=str):
                print(f"{name:8s} {g!s:>8}", summary([r[key] for r in rows if group(r) == g]))
    print("== largest")
    for r in sorted(rows, key=lambda r: -r["rel_l2"])[:15]:
        print("\t".join(f"{r[k]:.4g}" for k in r))


if __name__ == "__main__":
    main()
