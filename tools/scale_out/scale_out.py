#!/usr/bin/env python3
"""Scale-out benchmark (docs/deploy.md "Scale-out on one host"): a writer and N query replicas of
`clearsky serve` on loopback behind HAProxy (deploy/haproxy/scale-out.cfg.in: health checks on
/readyz, `retries` with `option redispatch` and `retry-on all-retryable-errors`), then

  throughput  wrk on /v1/radiance for each N in --replicas, with each replica's resident memory;
  kill        one replica killed (SIGKILL) while wrk runs: failed requests (target 0);
  rolling     every replica in turn stopped with SIGTERM (the graceful drain) and started again
              while wrk runs: failed requests (target 0).

A failed request is a wrk socket error (connect, read, write, timeout) or an answer that is not
2xx/3xx. Prints one line per measurement and, with --json, a JSON summary as the last line.
--smoke runs a short version (N = 2, a few seconds each) and exits 1 when a failure phase lost a
request (CTest ScaleOutSmoke). Needs haproxy and wrk (exit 77 without them).

Usage: scale_out.py --binary build/clearsky [--replicas 1,2,3] [--duration 15] [--connections 64]
                    [--models preetham] [--smoke] [--json]
"""
import argparse
import json
import os
import pathlib
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parents[2]
TEMPLATE = REPO / "deploy" / "haproxy" / "scale-out.cfg.in"
QUERY = "/v1/radiance?model=preetham&sun_zenith=40&sun_azimuth=90&view_zenith=50&view_azimuth=180"
SKIP = 77


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def status_of(port, path):
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.sendall(f"GET {path} HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n".encode())
            head = s.recv(64)
            return int(head.split()[1]) if head.startswith(b"HTTP/1.1 ") else 0
    except (OSError, ValueError, IndexError):
        return 0


def wait_for(predicate, seconds, what):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return
        time.sleep(0.1)
    raise RuntimeError(f"timed out waiting for {what}")


def rss_mib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


class Server:
    """One `clearsky serve` process."""

    def __init__(self, binary, workdir, name, role, port, models, cache):
        self.binary, self.name, self.role, self.port = binary, name, role, port
        self.args = [binary, "serve", "--role", role, "--host", "127.0.0.1", "--port", str(port),
                     "--cache-dir", str(cache), "--models", models, "--prebuild-three", "false",
                     "--drain-delay", "2", "--drain-timeout", "30"]
        if role == "writer":
            self.args += ["--db", str(workdir / "writer.db")]
        self.log = open(workdir / f"{name}.log", "ab")
        self.process = None

    def start(self):
        self.process = subprocess.Popen(self.args, stdout=self.log, stderr=subprocess.STDOUT)
        wait_for(lambda: status_of(self.port, "/readyz") == 200, 300, f"{self.name} ready")

    def stop(self, sig=signal.SIGTERM):
        """Signals the process and waits for it; returns its exit status."""
        if self.process is None:
            return None
        self.process.send_signal(sig)
        code = self.process.wait(timeout=120)
        self.process = None
        return code


class Proxy:
    def __init__(self, workdir, front, writer, replicas):
        self.config = workdir / "haproxy.cfg"
        servers = "\n".join(f"    server {r.name} 127.0.0.1:{r.port}" for r in replicas)
        text = TEMPLATE.read_text()
        text = text.replace("@FRONT@", f"127.0.0.1:{front}").replace("@WRITER@", f"127.0.0.1:{writer.port}")
        self.config.write_text(text.replace("@QUERY_SERVERS@", servers))
        self.front = front
        self.log = open(workdir / "haproxy.log", "ab")
        self.process = subprocess.Popen(["haproxy", "-db", "-f", str(self.config)],
                                        stdout=self.log, stderr=subprocess.STDOUT)
        wait_for(lambda: self.process.poll() is not None or status_of(front, QUERY) == 200, 60,
                 "haproxy")
        if self.process.poll() is not None:
            raise RuntimeError(f"haproxy ended: see {workdir / 'haproxy.log'}")

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=30)


def wrk(front, connections, duration_s):
    return subprocess.Popen(["wrk", "-t2", f"-c{connections}", f"-d{duration_s}s", "--timeout", "10s",
                             f"http://127.0.0.1:{front}{QUERY}"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def parse_wrk(output):
    requests = int(re.search(r"(\d+) requests in", output).group(1))
    rate = float(re.search(r"Requests/sec:\s+([\d.]+)", output).group(1))
    non2xx = re.search(r"Non-2xx or 3xx responses: (\d+)", output)
    socket_errors = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", output)
    errors = sum(int(x) for x in socket_errors.groups()) if socket_errors else 0
    failed = errors + (int(non2xx.group(1)) if non2xx else 0)
    return {"requests": requests, "requests_per_s": rate, "failed": failed,
            "non_2xx": int(non2xx.group(1)) if non2xx else 0, "socket_errors": errors,
            "socket_error_kinds": dict(zip(("connect", "read", "write", "timeout"),
                                           (int(x) for x in socket_errors.groups())))
            if socket_errors else {}}


def failure_kinds(measured):
    """What a failed request was, for the log: non-2xx answers and wrk's socket error kinds."""
    if measured["failed"] == 0:
        return ""
    return f"(non-2xx {measured['non_2xx']}, socket errors {measured['socket_error_kinds']})"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--replicas", default="1,2,3")
    parser.add_argument("--duration", type=int, default=15)
    parser.add_argument("--connections", type=int, default=64)
    parser.add_argument("--models", default="preetham")
    parser.add_argument("--smoke", action="store_true")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    for tool in ("haproxy", "wrk"):
        if shutil.which(tool) is None:
            print(f"{tool} is missing (deploy/install-deps.sh installs it): skipped")
            return SKIP
    if args.smoke:
        args.replicas, args.duration, args.connections = "2", 4, 16
    counts = [int(n) for n in args.replicas.split(",")]
    binary = str(pathlib.Path(args.binary).resolve())
    results = {"throughput": [], "models": args.models, "connections": args.connections,
               "duration_s": args.duration}

    with tempfile.TemporaryDirectory(prefix="clearsky-scale-out-") as tmp:
        if os.environ.get("CLEARSKY_SCALE_OUT_KEEP"):
            tmp = tempfile.mkdtemp(prefix="clearsky-scale-out-kept-")
            print(f"keeping {tmp}", flush=True)
        workdir = pathlib.Path(tmp)
        cache = workdir / "cache"
        writer = Server(binary, workdir, "writer", "writer", free_port(), args.models, cache)
        writer.start()
        replicas = [Server(binary, workdir, f"q{i + 1}", "query", free_port(), args.models, cache)
                    for i in range(max(counts))]
        try:
            if not args.smoke:
                for n in counts:
                    for r in replicas[:n]:
                        r.start()
                    proxy = Proxy(workdir, free_port(), writer, replicas[:n])
                    run = wrk(proxy.front, args.connections, args.duration)
                    time.sleep(args.duration / 2)
                    rss = [round(rss_mib(r.process.pid), 1) for r in replicas[:n]]
                    measured = parse_wrk(run.communicate()[0])
                    measured.update({"replicas": n, "rss_mib": rss})
                    results["throughput"].append(measured)
                    print(f"throughput N={n}: {measured['requests_per_s']:.0f} req/s, "
                          f"{measured['failed']} failed, replica RSS {rss} MiB", flush=True)
                    proxy.stop()
                    for r in replicas[:n]:
                        r.stop()

            n = max(counts)
            for r in replicas[:n]:
                if r.process is None:
                    r.start()
            proxy = Proxy(workdir, free_port(), writer, replicas[:n])

            # One replica killed under load.
            kill_run = wrk(proxy.front, args.connections, 3 * args.duration)
            time.sleep(args.duration)
            replicas[0].stop(signal.SIGKILL)
            measured = parse_wrk(kill_run.communicate()[0])
            results["kill"] = measured
            print(f"kill one of {n} replicas under load: {measured['requests']} requests, "
                  f"{measured['failed']} failed {failure_kinds(measured)}", flush=True)
            replicas[0].start()
            time.sleep(2)

            # Rolling restart under load: SIGTERM (drain), wait, start again, one by one.
            roll_run = wrk(proxy.front, args.connections, 3600)
            time.sleep(args.duration / 2)
            exit_codes = []
            for r in replicas[:n]:
                exit_codes.append(r.stop(signal.SIGTERM))
                r.start()
                # HAProxy marks it up after two good checks (inter 500ms, rise 2).
                time.sleep(2)
            time.sleep(args.duration / 2)
            roll_run.send_signal(signal.SIGINT)
            measured = parse_wrk(roll_run.communicate()[0])
            measured["exit_codes"] = exit_codes
            results["rolling"] = measured
            print(f"rolling restart of {n} replicas under load: {measured['requests']} requests, "
                  f"{measured['failed']} failed {failure_kinds(measured)}, exit codes {exit_codes}", flush=True)
            proxy.stop()
        finally:
            for r in replicas:
                if r.process is not None:
                    r.stop(signal.SIGKILL)
            writer.stop()
    if args.json:
        print(json.dumps(results))
    lost = results["kill"]["failed"] + results["rolling"]["failed"]
    clean_exits = all(code == 0 for code in results["rolling"]["exit_codes"])
    return 0 if lost == 0 and clean_exits else 1


if __name__ == "__main__":
    sys.exit(main())
