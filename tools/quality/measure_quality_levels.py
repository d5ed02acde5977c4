#!/usr/bin/env python3
"""Measures the error figures of the quality levels (models/quality/<model>.csv,
docs/quality-levels.md) against a running `clearsky serve`.

For each model and level it asks POST /v1/radiance with the level's options given explicitly
(so it measures any server version, with or without `quality`), on the wavelengths 440, 550 and
680 nm (a point grid: cheap tables), for the suns at zenith 20, 45, 70 and 85 degrees (azimuth
180) and the views every 5 degrees of zenith from 0 to 85 and every 15 degrees of azimuth from 0
to 180 (the sky is symmetric about the sun's vertical plane). The relative error of a value is
|L - L_ref| / L_ref against the model's reference level; the figures are the 95th percentile
(nearest rank) and the maximum over every sun, view and wavelength.

With --build it also times, on a fresh server per model (`--models MODEL`, an empty cache), the
build of each level's tables on the default 40-wavelength grid (standard: the start until
/readyz; draft and reference: their first answer) and reads the tables' bytes from /metrics
(clearsky_table_bytes). This needs a server with --prebuild (this change or later).

  tools/quality/measure_quality_levels.py --binary build/clearsky [--build] [--models bruneton,...]

Prints one CSV row per model and level: model,level,p95,max,build_seconds,table_bytes.
"""

import argparse
import csv
import json
import math
import os
import sys
import tempfile
import time
import http.client

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "hostile"))
import serve_process  # noqa: E402

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
SUNS_DEG = [20.0, 45.0, 70.0, 85.0]
WAVELENGTHS = "440,550,680"
LEVELS = ["draft", "standard", "reference"]
SERVE_LIMITS = ["--build-rate", "0", "--table-capacity", "64", "--table-memory",
                str(8 << 30), "--build-wait-ms", "30000", "--prebuild-three", "false"]


def start_server(binary, workdir, models, extra, cache_dir=None):
    """`binary serve` on a free port, ready once /readyz answers 200 (the default tables of a
    table model take minutes on a loaded machine: 1800 s at most)."""
    return serve_process.start_server(binary, workdir, models, extra, ready_s=1800,
                                      cache_dir=cache_dir)


def levels_of(model):
    with open(os.path.join(ROOT, "models", "quality", model + ".csv")) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    out = {}
    for r in rows:
        options = {}
        for item in filter(None, r["options"].split(";")):
            name, value = item.split("=")
            options[name] = float(value)
        out[r["level"]] = options
    return out


def post(port, path, body, timeout=3600):
    deadline = time.monotonic() + timeout
    while True:
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
        c.request("POST", path, json.dumps(body), {"Content-Type": "application/json"})
        r = c.getresponse()
        data = r.read()
        # A build still under way (503 with Retry-After): ask again.
        if r.status != 503 or time.monotonic() > deadline:
            break
        time.sleep(2)
    if r.status != 200:
        raise RuntimeError("%s %d: %s" % (path, r.status, data[:300]))
    return json.loads(data)


def radiances(port, model, options, sun_zenith_deg, wavelengths=None):
    views = [[z, a] for z in range(0, 90, 5) for a in range(0, 181, 15)]
    body = {"model": model, "sun_zenith": sun_zenith_deg, "sun_azimuth": 180.0,
            "views": views}
    if wavelengths:
        body["wavelengths"] = wavelengths
    elif wavelengths is None:
        body["wavelengths"] = WAVELENGTHS
    body.update(options)
    answer = post(port, "/v1/radiance", body)
    return [v for s in answer["samples"] for v in s["radiance"]]


def errors(port, model, options, reference):
    relative = []
    for sun, ref in zip(SUNS_DEG, reference):
        for value, expected in zip(radiances(port, model, options, sun), ref):
            if expected > 0.0:
                relative.append(abs(value - expected) / expected)
    relative.sort()
    p95 = relative[max(0, math.ceil(0.95 * len(relative)) - 1)]
    return p95, relative[-1]


def table_bytes(port, model):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    c.request("GET", "/metrics")
    text = c.getresponse().read().decode()
    for line in text.splitlines():
        if line.startswith('clearsky_table_bytes{model="%s"}' % model):
            return float(line.split()[-1])
    return 0.0


def build_figures(binary, model, levels):
    """One fresh server (empty cache, only the defaults built at start: --prebuild
    MODEL:standard): the start until /readyz is the standard build; then the first answer of
    draft and of reference on the 40-wavelength grid is each one's build. Bytes: the growth of
    clearsky_table_bytes."""
    out = {}
    with tempfile.TemporaryDirectory() as work:
        start = time.monotonic()
        process, port = start_server(binary, work, model,
                                     SERVE_LIMITS + ["--prebuild", model + ":standard"])
        try:
            out["standard"] = (time.monotonic() - start, table_bytes(port, model))
            for level in ("draft", "reference"):
                before = table_bytes(port, model)
                begin = time.monotonic()
                radiances(port, model, levels[level], 45.0, wavelengths="")
                out[level] = (time.monotonic() - begin, table_bytes(port, model) - before)
        finally:
            process.terminate()
            process.wait()
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--models", default="bruneton,elek,nishita93,nishita96,oneal,haber,"
                        "preetham,hosek")
    parser.add_argument("--build", action="store_true")
    parser.add_argument("--no-errors", action="store_true", help="with --build: the builds only")
    parser.add_argument("--wavelengths", help="instead of 440,550,680 (e.g. 550 for Bruneton's "
                        "reference, whose tables take minutes per wavelength on a loaded machine)")
    parser.add_argument("--serve-option", action="append", default=[],
                        help="passed to clearsky serve (e.g. --serve-option=--prebuild=bruneton:draft)")
    parser.add_argument("--cache-dir", help="a table cache kept between runs (the error run only)")
    args = parser.parse_args()
    models = args.models.split(",")
    global WAVELENGTHS
    if args.wavelengths:
        WAVELENGTHS = args.wavelengths
    SERVE_LIMITS.extend(args.serve_option)
    writer = csv.writer(sys.stdout)
    writer.writerow(["model", "level", "p95_relative_error", "max_relative_error",
                     "build_seconds", "table_bytes"])
    if args.no_errors:
        for model in models:
            builds = build_figures(args.binary, model, levels_of(model))
            for level in LEVELS:
                seconds, size = builds[level]
                writer.writerow([model, level, "", "", "%.3g" % seconds, "%d" % size])
                sys.stdout.flush()
        return
    with tempfile.TemporaryDirectory() as work:
        process, port = start_server(args.binary, work, ",".join(models), SERVE_LIMITS,
                                     args.cache_dir)
        try:
            for model in models:
                levels = levels_of(model)
                reference = [radiances(port, model, levels["reference"], sun) for sun in SUNS_DEG]
                builds = build_figures(args.binary, model, levels) if args.build else {}
                for level in LEVELS:
                    p95, worst = errors(port, model, levels[level], reference)
                    seconds, size = builds.get(level, ("", ""))
                    writer.writerow([model, level, "%.3g" % p95, "%.3g" % worst,
                                     "%.3g" % seconds if seconds != "" else "",
                                     "%d" % size if size != "" else ""])
                    sys.stdout.flush()
        finally:
            process.terminate()
            process.wait()


if __name__ == "__main__":
    main()
