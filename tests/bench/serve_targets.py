#!/usr/bin/env python3
"""The service's start, memory and evaluation targets, measured on a real `clearsky serve`
(docs/performance.md "The speed targets").

Starts the server on an empty table cache and reports:
- when each model's level became ready (/readyz polled every 0.1 s) and when /readyz answered 200;
- the first Bruneton radiance asked as soon as its draft is ready: its status, time and the level
  that served it;
- the server's resident memory (VmRSS, VmHWM of /proc/PID/status) when ready and after one
  /v1/radiance per served model;
- with --dataset-db, an all-model evaluation of its dataset three times (the first builds the
  per-sun states, the next ones find everything warm): the wall time of each, from the request to
  the ticket's end;
- with --warm-restart, the same start again on the table cache the first server filled: when it
  was ready and its resident memory then and after one radiance per model.

    tests/bench/serve_targets.py --binary build/clearsky [--dataset-db kider.db --dataset kider2014]
                                 [--models M,...] [--warm-restart] [--json]

The dataset database is copied, never written. Prints text, or one JSON object with --json.
"""
import argparse
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

TOKEN = "serve-targets-token"
ONE_VIEW = "sun_zenith=40&sun_azimuth=135&view_zenith=50&view_azimuth=200"


class Server:
    def __init__(self, binary, workdir, port, extra):
        self.base = f"http://127.0.0.1:{port}"
        self.db = os.path.join(workdir, "db.sqlite")
        self.log = open(os.path.join(workdir, "serve.log"), "w", encoding="utf-8")
        self.start = time.monotonic()
        self.proc = subprocess.Popen(
            [binary, "serve", "--port", str(port), "--db", self.db,
             "--cache-dir", os.path.join(workdir, "cache")] + extra,
            stdout=self.log, stderr=self.log, env=dict(os.environ, CLEARSKY_TOKEN=TOKEN))

    def since_start(self):
        return time.monotonic() - self.start

    def get(self, path, timeout=30.0):
        try:
            with urllib.request.urlopen(self.base + path, timeout=timeout) as r:
                return r.status, r.read()
        except urllib.error.HTTPError as e:
            return e.code, e.read()
        except OSError:
            return None, b""

    def post(self, path, body):
        request = urllib.request.Request(
            self.base + path, data=json.dumps(body).encode(), method="POST",
            headers={"Content-Type": "application/json", "Authorization": "Bearer " + TOKEN})
        try:
            with urllib.request.urlopen(request, timeout=30) as r:
                return r.status, json.loads(r.read())
        except urllib.error.HTTPError as e:
            return e.code, json.loads(e.read() or b"{}")

    def resident_mib(self):
        out = {}
        with open(f"/proc/{self.proc.pid}/status", encoding="utf-8") as f:
            for line in f:
                key, value = line.split(":", 1)
                if key in ("VmRSS", "VmHWM"):
                    out[key] = int(value.split()[0]) // 1024
        return out

    def stop(self):
        self.proc.terminate()
        try:
            self.proc.wait(timeout=60)
        except subprocess.TimeoutExpired:
            self.proc.kill()


def wait_ready(server, timeout_s):
    """Polls /readyz: {"model:level": seconds since start}, the first Bruneton answer, and the
    time of the 200."""
    levels = {}
    first_bruneton = None
    while server.since_start() < timeout_s:
        if server.proc.poll() is not None:
            raise RuntimeError(f"clearsky serve exited with {server.proc.returncode}")
        code, body = server.get("/readyz", timeout=2)
        now = server.since_start()
        try:
            ready = json.loads(body) if body else {}
        except ValueError:
            ready = {}
        for model, m in (ready.get("models") or {}).items():
            for level, state in (m.get("levels") or {}).items():
                if state.get("status") == "ready":
                    levels.setdefault(f"{model}:{level}", round(now, 2))
        if first_bruneton is None and "bruneton:draft" in levels:
            t = time.monotonic()
            status, answer = server.get("/v1/radiance?model=bruneton&" + ONE_VIEW)
            first_bruneton = {
                "asked_at_s": round(now, 2), "status": status,
                "answer_ms": round((time.monotonic() - t) * 1e3, 2),
                "served_quality": json.loads(answer).get("served_quality")
                if status == 200 else None}
        if code == 200:
            return levels, first_bruneton, round(now, 2)
        time.sleep(0.1)
    raise RuntimeError(f"/readyz not 200 after {timeout_s} s")


def radiance_per_model(server):
    """One /v1/radiance per served model (its level may still be building: an answer from its
    draft or a 503 both count), then the resident memory."""
    _, body = server.get("/v1/models")
    for model in [m["id"] for m in json.loads(body)["models"]]:
        server.get(f"/v1/radiance?model={model}&" + ONE_VIEW, timeout=300)
    return server.resident_mib()


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def evaluation_pass(server, dataset):
    start = time.monotonic()
    code, ticket = server.post("/v1/evaluations", {"dataset": dataset, "models": "all"})
    if code not in (200, 201, 202):
        raise RuntimeError(f"POST /v1/evaluations: {code} {ticket}")
    while True:
        _, body = server.get(f"/v1/evaluations/tickets/{ticket['ticket']}")
        state = json.loads(body)
        if state.get("status") not in ("queued", "running"):
            break
        time.sleep(0.1)
    runs = {}
    for m in state.get("models", []):
        if m.get("run") is not None:
            _, body = server.get(f"/v1/evaluations/{m['run']}")
            runs[m["model"]] = json.loads(body).get("rmse")
    return {"seconds": round(time.monotonic() - start, 2), "status": state.get("status"),
            "rmse": runs}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/clearsky")
    parser.add_argument("--port", type=int, default=0, help="0: a free port")
    parser.add_argument("--models", help="serve only these models (comma-separated)")
    parser.add_argument("--dataset-db", help="a database holding the dataset to evaluate")
    parser.add_argument("--dataset", default="kider2014")
    parser.add_argument("--passes", type=int, default=3)
    parser.add_argument("--ready-timeout", type=float, default=900.0)
    parser.add_argument("--warm-restart", action="store_true")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()

    workdir = tempfile.mkdtemp(prefix="clearsky-serve-targets-")
    if args.dataset_db:
        shutil.copy(args.dataset_db, os.path.join(workdir, "db.sqlite"))
    extra = ["--models", args.models] if args.models else []
    port = args.port or free_port()
    server = Server(args.binary, workdir, port, extra)
    out = {"loadavg": open("/proc/loadavg", encoding="utf-8").read().split()[:3]}
    try:
        levels, first_bruneton, ready_s = wait_ready(server, args.ready_timeout)
        out.update(ready_s=ready_s, levels=levels, first_bruneton=first_bruneton)
        out["resident_when_ready_mib"] = server.resident_mib()
        out["resident_after_one_radiance_per_model_mib"] = radiance_per_model(server)
        if args.dataset_db:
            out["evaluation_passes"] = [evaluation_pass(server, args.dataset)
                                        for _ in range(args.passes)]
            out["resident_after_passes_mib"] = server.resident_mib()
        if args.warm_restart:
            server.stop()
            server = Server(args.binary, workdir, port, extra)
            _, _, ready_s = wait_ready(server, args.ready_timeout)
            out["warm_restart"] = {
                "ready_s": ready_s, "resident_when_ready_mib": server.resident_mib(),
                "resident_after_one_radiance_per_model_mib": radiance_per_model(server)}
    finally:
        server.stop()
        shutil.rmtree(workdir, ignore_errors=True)

    if args.json:
        print(json.dumps(out, indent=2))
        return 0
    print(f"load average {' '.join(out['loadavg'])}; /readyz 200 after {out['ready_s']} s")
    for key, seconds in sorted(out["levels"].items(), key=lambda kv: kv[1]):
        print(f"  {key:30s} ready at {seconds:7.2f} s")
    print("first Bruneton radiance:", out["first_bruneton"])
    print("resident when ready (MiB):", out["resident_when_ready_mib"])
    print("resident after one radiance per model (MiB):",
          out["resident_after_one_radiance_per_model_mib"])
    for i, p in enumerate(out.get("evaluation_passes", [])):
        print(f"all-model evaluation pass {i + 1}: {p['seconds']} s, {p['status']}")
    if "resident_after_passes_mib" in out:
        print("resident after the passes (MiB):", out["resident_after_passes_mib"])
    if "warm_restart" in out:
        print("warm restart:", out["warm_restart"])
    return 0


if __name__ == "__main__":
    sys.exit(main())
