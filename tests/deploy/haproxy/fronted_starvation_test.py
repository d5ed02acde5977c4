#!/usr/bin/env python3
"""The fronted deployment under load (docs/deployment.md "Fronted by HAProxy"): `clearsky serve`
behind HAProxy with deploy/haproxy/clearsky.cfg, then 1,000 wrk connections on /v1/radiance for
12 s and 70 slowloris connections for 6 s through HAProxy, while /healthz is probed on a new
connection every second: every probe must be answered 200 within 1 s.

Usage: fronted_starvation_test.py CLEARSKY_EXECUTABLE
Exits 77 (CTest: skipped) with a message when haproxy or wrk is missing (deploy/install-deps.sh
installs both).
"""
import json
import os
import pathlib
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[3]
CONFIG = REPO / "deploy" / "haproxy" / "clearsky.cfg"
HOSTILE = REPO / "tools" / "hostile" / "hostile_clients.py"
SKIP = 77


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(predicate, seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.1)
    return False


def answers(port, path="/healthz"):
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=2) as s:
            s.sendall(f"GET {path} HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n".encode())
            return s.recv(64).startswith(b"HTTP/1.1 200")
    except OSError:
        return False


def attack(front, kind, connections, duration):
    out = subprocess.run([sys.executable, str(HOSTILE), "--port", str(front), "--attack", kind,
                          "--connections", str(connections), "--duration", str(duration),
                          "--warm-up", "2", "--json"], capture_output=True, text=True, check=True)
    print(out.stdout.splitlines()[0], flush=True)
    return json.loads(out.stdout.splitlines()[-1])


def main():
    haproxy = shutil.which("haproxy") or shutil.which("haproxy", path="/usr/sbin:/sbin")
    if haproxy is None:
        print("SKIPPED: haproxy is not installed (deploy/install-deps.sh installs it)")
        return SKIP
    if shutil.which("wrk") is None:
        print("SKIPPED: wrk is not installed (deploy/install-deps.sh installs it)")
        return SKIP
    clearsky = sys.argv[1]
    front = free_port()
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        log = open(work / "serve.log", "w")
        server = subprocess.Popen([clearsky, "serve", "--host", "127.0.0.1", "--port", "0",
                                   "--db", str(work / "sky.db"), "--cache-dir", str(work / "cache"),
                                   "--models", "preetham", "--prebuild-three", "false"],
                                  stdout=log, stderr=subprocess.STDOUT)
        proxy = None
        try:
            found = []
            wait_for(lambda: found.extend(re.findall(r"serving on http://127\.0\.0\.1:(\d+)",
                                                     (work / "serve.log").read_text())) or found, 60)
            if not found:
                print("clearsky did not start:\n" + (work / "serve.log").read_text())
                return 1
            env = dict(os.environ, CLEARSKY_FRONT=f"127.0.0.1:{front}",
                       CLEARSKY_BACKEND=f"127.0.0.1:{found[0]}", CLEARSKY_MAXCONN="4000")
            proxy = subprocess.Popen([haproxy, "-db", "-f", str(CONFIG)], env=env,
                                     stdout=subprocess.DEVNULL, stderr=open(work / "haproxy.log", "w"))
            if not wait_for(lambda: answers(front), 30):
                print("haproxy did not answer:\n" + (work / "haproxy.log").read_text())
                return 1
            failures = []
            for kind, connections, duration in (("wrk", 1000, 12), ("slowloris", 70, 6)):
                report = attack(front, kind, connections, duration)
                during = report["during"]
                if during["total"] < duration - 4 or during["answered"] != during["total"]:
                    failures.append(f"{kind}: {during['answered']}/{during['total']} probes answered")
                elif during["max_ms"] >= 1000:
                    failures.append(f"{kind}: a probe took {during['max_ms']} ms")
            for f in failures:
                print("FAILED:", f)
            return 1 if failures else 0
        finally:
            for p in (proxy, server):
                if p is not None:
                    p.terminate()
                    p.wait(timeout=30)


if __name__ == "__main__":
    sys.exit(main())
