#!/usr/bin/env python3
"""Resident memory and readiness of `clearsky serve` (docs/tables-and-memory.md "The server with
every default ready").

Starts BINARY serve on an empty table cache folder, polls /readyz every 0.1 s and records when
each model's quality level turns ready, reads VmRSS/VmHWM (/proc/PID/status) once /readyz
answers 200, asks one /v1/radiance per served model (polling 503 model_not_ready until 200, at
most --answer-timeout s) and reads them again, with /metrics' table bytes; then stops the server
and starts it again on the same, now warm, cache folder and measures the same.

  nice -n 19 python3 tools/bench/serve_memory.py build/clearsky /tmp/res19 [-- serve options]

WORKDIR is emptied first; it holds db.sqlite, cache/ and the servers' logs.
"""
import argparse, json, os, shutil, subprocess, sys, time, urllib.error, urllib.request

QUERY = "sun_zenith=40&sun_azimuth=135&view_zenith=50&view_azimuth=200"


def get(base, path, timeout=30):
    try:
        with urllib.request.urlopen(base + path, timeout=timeout) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.read()
    except Exception:
        return None, b""


def memory(pid):
    out = {}
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            key, value = line.split(":", 1)
            if key in ("VmRSS", "VmHWM"):
                out[key] = int(value.split()[0]) // 1024
    return out


def run(binary, workdir, port, extra, label, answer_timeout):
    base = f"http://127.0.0.1:{port}"
    log = open(os.path.join(workdir, f"serve-{label}.log"), "w")
    t0 = time.monotonic()
    proc = subprocess.Popen([binary, "serve", "--port", str(port), "--db",
                             os.path.join(workdir, "db.sqlite"), "--cache-dir",
                             os.path.join(workdir, "cache")] + extra, stdout=log, stderr=log)
    try:
        seen, levels = {}, {}
        while True:
            code, body = get(base, "/readyz", timeout=2)
            now = time.monotonic() - t0
            if code is not None and body:
                try:
                    models = json.loads(body).get("models") or {}
                except ValueError:
                    models = {}
                for model, m in models.items():
                    for level, state in (m.get("levels") or {}).items():
                        levels[f"{model}:{level}"] = state.get("status")
                        if state.get("status") == "ready":
                            seen.setdefault(f"{model}:{level}", now)
                if code == 200:
                    break
            if proc.poll() is not None or now > 1800:
                sys.exit(f"{label}: server ended or not ready after {now:.0f} s")
            time.sleep(0.1)
        ready_s = time.monotonic() - t0
        at_ready = memory(proc.pid)
        print(f"[{label}] /readyz 200 after {ready_s:.2f} s; resident (MiB) {at_ready}")
        for key, at in sorted(seen.items(), key=lambda kv: kv[1]):
            print(f"    {key:28s} ready at {at:7.2f} s")
        not_built = sorted(k for k, s in levels.items() if s != "ready")
        print(f"    not ready at 200: {', '.join(not_built) or 'none'} "
              f"({', '.join(levels[k] for k in not_built)})")
        code, body = get(base, "/v1/models")
        ids = [m["id"] for m in json.loads(body)["models"]]
        for model in ids:
            start = time.monotonic()
            while True:
                code, body = get(base, f"/v1/radiance?model={model}&{QUERY}", timeout=120)
                if code != 503 or time.monotonic() - start > answer_timeout:
                    break
                time.sleep(0.2)
            served = json.loads(body).get("served_quality") if code == 200 else body[:120]
            print(f"    radiance {model:18s} {code} in {time.monotonic() - start:6.2f} s "
                  f"served_quality {served}")
        print(f"[{label}] resident after one radiance per model (MiB) {memory(proc.pid)}")
        code, body = get(base, "/metrics")
        for line in body.decode().splitlines():
            if line.startswith("clearsky_table_bytes"):
                print("    " + line)
    finally:
        proc.terminate()
        proc.wait(timeout=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("binary")
    parser.add_argument("workdir")
    parser.add_argument("--port", type=int, default=8097)
    parser.add_argument("--answer-timeout", type=float, default=600,
                        help="seconds a radiance may answer 503 before it is reported as is")
    parser.add_argument("serve_options", nargs="*", help="after --: passed to serve")
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    with open("/proc/loadavg") as f:
        print("load average:", f.read().strip())
    run(args.binary, args.workdir, args.port, args.serve_options, "cold", args.answer_timeout)
    run(args.binary, args.workdir, args.port, args.serve_options, "warm", args.answer_timeout)
    with open("/proc/loadavg") as f:
        print("load average:", f.read().strip())


if __name__ == "__main__":
    main()
