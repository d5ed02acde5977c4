#!/usr/bin/env python3
"""Concurrent large answers against a real `clearsky serve`, and its resident memory
(docs/threat-model.md "exhaust memory with answers or requests", docs/deployment.md "Memory").

--clients connections at once (each on its own HTTP worker thread of the server) ask, until
--requests answers have been read, for spectral skydomes (64..--max-size pixels), radiance
batches of up to 4,000 views at every wavelength and RGB batches. Meanwhile the server's
resident memory (VmRSS) and thread count are sampled; after the load, the server idles for
--idle-s seconds (its surplus workers end) and its resident memory is read again. Reports the
start, peak and after-idle resident memory and the most threads seen; with --max-peak-mib or
--max-idle-mib, exits 1 when a figure is above its bound (also on a crash or an error status).

Standard library only. Usage:
  tools/hostile/memory_load.py --binary build/clearsky --clients 48 --requests 600 --seed 1 [--json]
The server is started on a free port with a temporary database and stopped at the end; extra
environment for it (e.g. MALLOC_ARENA_MAX=8 to compare) comes from the caller's environment.
"""

import argparse
import http.client
import json
import random
import signal
import subprocess
import sys
import tempfile
import threading
import time

from serve_process import start_server, status_kib


def one_request(rng, port, max_size, timeout_s):
    """One large answer, read to the end; returns its status."""
    kind = rng.random()
    zenith, azimuth = round(rng.uniform(0, 80), 2), round(rng.uniform(0, 360), 2)
    model = rng.choice(["preetham", "hosek"])
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout_s)
    if kind < 0.4:
        size = rng.randint(64, max_size)
        c.request("GET", "/v1/skydome?model=%s&sun_zenith=%s&sun_azimuth=%s&size=%d"
                  "&channels=spectral" % (model, zenith, azimuth, size))
    else:
        count = rng.randint(500, 4000)
        views = [[round(rng.uniform(0, 89), 3), round(rng.uniform(0, 360), 3)]
                 for _ in range(count)]
        path = "/v1/radiance" if kind < 0.8 else "/v1/rgb"
        body = {"model": model, "sun_zenith": zenith, "sun_azimuth": azimuth, "views": views}
        c.request("POST", path, json.dumps(body), {"Content-Type": "application/json"})
    r = c.getresponse()
    while r.read(1 << 20):
        pass
    c.close()
    return r.status


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/clearsky")
    parser.add_argument("--clients", type=int, default=48)
    parser.add_argument("--requests", type=int, default=600)
    parser.add_argument("--max-size", type=int, default=1024)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--models", default="preetham,hosek")
    parser.add_argument("--threads", type=int, default=512)
    parser.add_argument("--idle-s", type=float, default=15.0)
    parser.add_argument("--timeout-s", type=float, default=300.0)
    parser.add_argument("--max-peak-mib", type=float)
    parser.add_argument("--max-idle-mib", type=float)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="clearsky-memory-") as workdir:
        process, port = start_server(args.binary, workdir, args.models,
                                         ["--prebuild-three", "false", "--threads", str(args.threads)])
        try:
            start_kib = status_kib(process.pid, "VmRSS")
            statuses = {}
            errors = []
            lock = threading.Lock()
            remaining = [args.requests]
            done = threading.Event()
            peak = {"rss_kib": start_kib, "threads": 0}

            def sample():
                while not done.is_set():
                    peak["rss_kib"] = max(peak["rss_kib"], status_kib(process.pid, "VmRSS"))
                    peak["threads"] = max(peak["threads"], status_kib(process.pid, "Threads"))
                    time.sleep(0.1)

            def client(index):
                rng = random.Random(args.seed * 1000 + index)
                while True:
                    with lock:
                        if remaining[0] <= 0:
                            return
                        remaining[0] -= 1
                    try:
                        status = one_request(rng, port, args.max_size, args.timeout_s)
                    except (OSError, http.client.HTTPException) as e:
                        status = "error"
                        with lock:
                            errors.append(repr(e)[:120])
                    with lock:
                        statuses[str(status)] = statuses.get(str(status), 0) + 1

            sampler = threading.Thread(target=sample)
            sampler.start()
            started = time.time()
            clients = [threading.Thread(target=client, args=(i,)) for i in range(args.clients)]
            for t in clients:
                t.start()
            for t in clients:
                t.join()
            elapsed = time.time() - started
            after_load_kib = status_kib(process.pid, "VmRSS")
            time.sleep(args.idle_s)
            done.set()
            sampler.join()
            report = {
                "requests": args.requests,
                "clients": args.clients,
                "seconds": round(elapsed, 1),
                "statuses": statuses,
                "errors": errors[:3],
                "crashed": process.poll() is not None,
                "resident_start_mib": round(start_kib / 1024, 1),
                "resident_peak_mib": round(max(peak["rss_kib"], status_kib(process.pid, "VmHWM"))
                                           / 1024, 1),
                "resident_after_load_mib": round(after_load_kib / 1024, 1),
                "resident_after_idle_mib": round(status_kib(process.pid, "VmRSS") / 1024, 1),
                "threads_peak": peak["threads"],
                "threads_after_idle": status_kib(process.pid, "Threads"),
            }
        finally:
            if process.poll() is None:
                process.send_signal(signal.SIGTERM)
                try:
                    process.wait(timeout=30)
                except subprocess.TimeoutExpired:
                    process.kill()
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        for key, value in report.items():
            print("%-24s %s" % (key, value))
    ok = (not report["crashed"] and set(statuses) <= {"200", "422"} and
          (args.max_peak_mib is None or report["resident_peak_mib"] <= args.max_peak_mib) and
          (args.max_idle_mib is None or report["resident_after_idle_mib"] <= args.max_idle_mib))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
