#!/usr/bin/env python3
"""Broadband global horizontal irradiance of the models against the pyranometer of the Kider
et al. 2014 measurements (Cornell, 2013-05-27), at every capture time: a Markdown table on
stdout and an SVG plot over the day (docs/building-energy.md "Broadband irradiance and the
pyranometer").

One command (the measurement folder is the kider2014 data set of Kider, Knowlton, Newlin, Li
and Greenberg, ACM TOG 33(6), 2014):

    python3 tools/broadband/pyranometer_validation.py --clearsky build/clearsky \
        --day-folder DATA/kider2014/2013-05-27 --svg docs/figures/broadband-pyranometer-2013-05-27.svg

It starts `clearsky serve` on a free loopback port (its own database and table cache under
--work-dir), asks GET /v1/irradiance for each capture time, and stops the server.
"""
import argparse
import json
import pathlib
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

# The site (Kider et al. 2014): roof of Rhodes Hall, Cornell University, about 250 m above sea
# level; the capture times are EDT (UTC-4).
LAT, LON, ALTITUDE_M = 42.443449, -76.481962, 250.0
DAY = "2013-05-27"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def get_json(url, timeout_s=600):
    """GET with retries while the server builds tables (503 with Retry-After)."""
    deadline = time.monotonic() + timeout_s
    while True:
        try:
            with urllib.request.urlopen(url, timeout=120) as r:
                return json.load(r)
        except urllib.error.HTTPError as e:
            if e.code != 503 or time.monotonic() > deadline:
                raise RuntimeError(f"{url}: {e.code} {e.read().decode(errors='replace')}")
            time.sleep(float(e.headers.get("Retry-After", "2")))
        except urllib.error.URLError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.5)


def captures(day_folder):
    """(HH:MM, mean W/m2, samples) of each per-capture pyranometer file (IRRADIANCE/)."""
    out = []
    for path in sorted((day_folder / "IRRADIANCE").glob("*.txt")):
        values = []
        for line in path.read_text().splitlines():
            parts = line.split()
            if len(parts) == 2:
                values.append(float(parts[0]))
        hh, mm = path.stem.split(".")[3:5]
        out.append((f"{hh}:{mm}", sum(values) / len(values), len(values)))
    return out


def full_day(day_folder):
    """(hours after midnight EDT, W/m2) of pyranometer_full_day.txt. Its first column counts
    minutes from its first record (09:30:00 EDT, the first capture's first sample: the values
    repeat the per-capture files' 4 s samples), whatever its header calls it."""
    rows = []
    for line in (day_folder / "pyranometer_full_day.txt").read_text().splitlines():
        parts = line.split()
        if len(parts) == 2:
            rows.append((9.5 + float(parts[0]) / 60.0, float(parts[1])))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--clearsky", required=True, help="the clearsky executable")
    ap.add_argument("--day-folder", required=True, type=pathlib.Path,
                    help="kider2014/2013-05-27 (IRRADIANCE/ and pyranometer_full_day.txt)")
    ap.add_argument("--models", default="bruneton,elek,nishita93,oneal")
    ap.add_argument("--svg", type=pathlib.Path, help="write the plot here")
    ap.add_argument("--json", type=pathlib.Path, help="write the numbers here")
    ap.add_argument("--work-dir", type=pathlib.Path, help="database and table cache (default: temporary)")
    ap.add_argument("--extra", default="", help="more query parameters, e.g. precipitable_water_cm=2")
    args = ap.parse_args()

    models = args.models.split(",")
    work = args.work_dir or pathlib.Path(tempfile.mkdtemp(prefix="clearsky-broadband-"))
    work.mkdir(parents=True, exist_ok=True)
    port = free_port()
    server = subprocess.Popen(
        [args.clearsky, "serve", "--host", "127.0.0.1", "--port", str(port), "--db",
         str(work / "clearsky.db"), "--cache-dir", str(work / "cache"), "--prebuild-three", "false",
         "--models", *models],
        stdout=subprocess.DEVNULL, stderr=open(work / "serve.log", "ab"))
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 600
        while True:
            try:
                with urllib.request.urlopen(base + "/readyz", timeout=10) as r:
                    if r.status == 200:
                        break
            except (urllib.error.URLError, ConnectionError):
                pass
            if server.poll() is not None or time.monotonic() > deadline:
                sys.exit(f"clearsky serve did not become ready (see {work / 'serve.log'})")
            time.sleep(0.5)
        rows = []
        for hhmm, measured, samples in captures(args.day_folder):
            row = {"time": hhmm, "measured_w_m2": measured, "samples": samples}
            for model in models:
                query = (f"/v1/irradiance?model={model}&lat={LAT}&lon={LON}&altitude={ALTITUDE_M:g}"
                         f"&time={DAY}T{hhmm}:00-04:00&component=global")
                if args.extra:
                    query += "&" + args.extra
                j = get_json(base + query)
                row["sun_zenith_deg"] = j["sun"]["zenith_deg"]
                row[model] = {"broadband_w_m2": j["global"]["broadband_irradiance_w_m2"],
                              "model_range_w_m2": j["global"]["model_range_irradiance_w_m2"],
                              "range_nm": j["integrated_range_nm"]}
            rows.append(row)
    finally:
        server.terminate()
        server.wait(timeout=60)

    print("| time (EDT) | sun zenith | pyranometer (W/m2) | " +
          " | ".join(f"{m} broadband (W/m2, diff.)" for m in models) + f" | {models[0]} model range |")
    print("|---|---|---|" + "---|" * len(models) + "---|")
    worst = {m: 0.0 for m in models}
    for r in rows:
        cells = []
        for m in models:
            bb = r[m]["broadband_w_m2"]
            d = 100.0 * (bb - r["measured_w_m2"]) / r["measured_w_m2"]
            worst[m] = max(worst[m], abs(d), key=abs)
            cells.append(f"{bb:.0f} ({d:+.1f}%)")
        print(f"| {r['time']} | {r['sun_zenith_deg']:.1f} | {r['measured_w_m2']:.0f} | " +
              " | ".join(cells) + f" | {r[models[0]]['model_range_w_m2']:.0f} |")
    print()
    print("worst |difference|: " + ", ".join(f"{m} {worst[m]:.1f}%" for m in models))
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1) + "\n")
    if args.svg:
        import matplotlib
        matplotlib.use("svg")
        matplotlib.rcParams["svg.hashsalt"] = "clearsky-broadband"
        import matplotlib.pyplot as plt
        day = full_day(args.day_folder)
        hours = [int(r["time"][:2]) + int(r["time"][3:]) / 60.0 for r in rows]
        fig, ax = plt.subplots(figsize=(8, 4.5))
        ax.plot([h for h, _ in day], [w for _, w in day], color="0.6", lw=0.8,
                label="pyranometer (every 4 s)")
        ax.plot(hours, [r["measured_w_m2"] for r in rows], "ko", ms=4, label="pyranometer, capture mean")
        for m, marker in zip(models, "s^vD<>"):
            ax.plot(hours, [r[m]["broadband_w_m2"] for r in rows], marker, ms=5, mfc="none",
                    label=f"{m}, broadband 300-4000 nm")
        ax.plot(hours, [r[models[0]]["model_range_w_m2"] for r in rows], "x", color="C7",
                label=f"{models[0]}, own range {rows[0][models[0]]['range_nm'][0]:g}-"
                      f"{rows[0][models[0]]['range_nm'][1]:g} nm")
        ax.set_xlabel(f"hour, EDT, {DAY} (Ithaca NY)")
        ax.set_ylabel("global horizontal irradiance (W/m2)")
        ax.set_ylim(0, None)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")
        fig.tight_layout()
        fig.savefig(args.svg, metadata={"Date": None})


if __name__ == "__main__":
    main()
