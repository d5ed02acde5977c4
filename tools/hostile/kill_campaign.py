#!/usr/bin/env python3
"""Kill -9 at random points of imports, evaluations and table builds (docs/threat-model.md).

Each round starts `clearsky serve` on the same database and cache folder, starts one action,
waits a random time, kills the process with SIGKILL, and checks what the next start finds:

  - the SQLite database passes `PRAGMA integrity_check` right after the kill;
  - the server is ready again (its cached tables load or rebuild);
  - no import, evaluation run or evaluation ticket is left `queued` or `running` by the killed
    process once the new one has started (each is finished, resumed or marked failed or
    interrupted with a reason);
  - every stored capture has its 81 samples (an import is one transaction);
  - every evaluation ticket answers after the restarts and lists every model it asked for,
    each with a run or `interrupted`/`skipped` with a reason (reported otherwise);
  - the killed build's configuration is answered afterwards with finite, non-negative radiance.

Standard library only. Usage:
  tools/hostile/kill_campaign.py --binary build/clearsky --rounds 20 --seed 1 [--json]
        [--archives ../shared/data/kider2014/2013-05-27/RADIANCE]
"""

import argparse
import collections
import glob
import http.client
import json
import math
import os
import random
import signal
import socket
import sqlite3
import subprocess
import sys
import tempfile
import time

TOKEN = "kill-campaign-token"
MODELS = "preetham,hosek,haber,nishita96"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    def __init__(self, binary, workdir):
        self.binary = binary
        self.workdir = workdir
        self.process = None
        self.port = None

    def start(self, timeout_s=300):
        self.port = free_port()
        log = open(os.path.join(self.workdir, "server.log"), "ab")
        self.process = subprocess.Popen(
            [self.binary, "serve", "--port", str(self.port),
             "--db", os.path.join(self.workdir, "db.sqlite"),
             "--cache-dir", os.path.join(self.workdir, "cache"), "--models", MODELS,
             "--prebuild-three", "0", "--token", TOKEN],
            stdout=log, stderr=subprocess.STDOUT)
        started = time.time()
        while time.time() - started < timeout_s:
            if self.process.poll() is not None:
                return None
            try:
                if self.request("GET", "/readyz", timeout=2)[0] == 200:
                    return time.time() - started
            except OSError:
                pass
            time.sleep(0.1)
        return None

    def kill(self):
        self.process.send_signal(signal.SIGKILL)
        self.process.wait()

    def stop(self):
        if self.process and self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()

    def request(self, method, target, body=None, timeout=30, content_type="application/json"):
        c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        headers = {"Authorization": "Bearer " + TOKEN}
        if body is not None:
            headers["Content-Type"] = content_type
        c.request(method, target, body=body, headers=headers)
        r = c.getresponse()
        data = r.read()
        c.close()
        return r.status, data


def integrity(db_path):
    with sqlite3.connect(db_path, timeout=30) as db:
        return db.execute("PRAGMA integrity_check").fetchone()[0]


def incomplete_captures(db_path):
    with sqlite3.connect(db_path, timeout=30) as db:
        return db.execute(
            "SELECT COUNT(*) FROM (SELECT c.id FROM captures c LEFT JOIN samples s "
            "ON s.capture_id = c.id GROUP BY c.id HAVING COUNT(s.id) != 81)").fetchone()[0]


def unfinished(db_path, before_utc):
    """Imports, runs and tickets still queued or running that were created before before_utc."""
    with sqlite3.connect(db_path, timeout=30) as db:
        imports = db.execute(
            "SELECT COUNT(*) FROM imports WHERE status IN ('queued','running') AND created_utc < ?",
            (before_utc,)).fetchone()[0]
        runs = db.execute(
            "SELECT COUNT(*) FROM evaluation_runs WHERE status = 'running' AND started_utc < ?",
            (before_utc,)).fetchone()[0]
        tickets = db.execute(
            "SELECT COUNT(*) FROM evaluation_tickets WHERE status IN ('queued','running')"
            " AND created_utc < ?", (before_utc,)).fetchone()[0]
    return imports, runs, tickets


def utc_now():
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())


def finite_radiance(body):
    try:
        answer = json.loads(body)
    except ValueError:
        return False
    values = [v for s in answer.get("samples", []) for v in s.get("radiance", [])]
    return bool(values) and all(math.isfinite(v) and v >= 0 for v in values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/clearsky")
    parser.add_argument("--rounds", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--max-delay-s", type=float, default=3.0)
    parser.add_argument("--archives",
                        default=os.path.join(os.path.dirname(__file__),
                                             "../../../shared/data/kider2014/2013-05-27/RADIANCE"))
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    rng = random.Random(args.seed)
    archives = sorted(glob.glob(os.path.join(args.archives, "*.7z")))
    if not archives:
        sys.exit("no .7z archives under " + args.archives)

    findings = collections.defaultdict(list)
    actions = collections.Counter()
    ready_s = []
    with tempfile.TemporaryDirectory(prefix="clearsky-kill-") as workdir:
        server = Server(args.binary, workdir)
        db_path = os.path.join(workdir, "db.sqlite")
        if server.start() is None:
            sys.exit("the server did not start")
        # A first dataset, so that evaluations have something to evaluate.
        with open(archives[0], "rb") as f:
            server.request("POST", "/v1/datasets?name=base", f.read(),
                           content_type="application/octet-stream")
        time.sleep(3)
        for round_index in range(args.rounds):
            action = rng.choice(["import", "evaluation", "build", "haber_sun"])
            actions[action] += 1
            pending_build = None
            try:
                if action == "import":
                    with open(rng.choice(archives), "rb") as f:
                        server.request("POST", "/v1/datasets?name=d%d" % round_index, f.read(),
                                       content_type="application/octet-stream", timeout=60)
                elif action == "evaluation":
                    status, body = server.request(
                        "POST", "/v1/evaluations",
                        json.dumps({"dataset": "base", "models": MODELS.split(",")}).encode())
                    if status == 202:
                        findings_ticket = json.loads(body).get("ticket")
                        findings["tickets"].append(findings_ticket)
                elif action == "build":
                    # A new aerosol amount: a new configuration, hence new tables.
                    beta = round(rng.uniform(0.01, 0.5), 4)
                    pending_build = ("/v1/radiance?model=nishita96&sun_zenith=40&sun_azimuth=0"
                                     "&view_zenith=50&view_azimuth=90&beta=%s" % beta)
                    server.request("GET", pending_build, timeout=2)
                else:
                    zenith = round(rng.uniform(0, 85), 2)
                    pending_build = ("/v1/radiance?model=haber&sun_zenith=%s&sun_azimuth=0"
                                     "&view_zenith=50&view_azimuth=90" % zenith)
                    server.request("GET", pending_build, timeout=2)
            except (OSError, http.client.HTTPException):
                pass  # a build answering later than the short timeout is expected
            time.sleep(rng.uniform(0, args.max_delay_s))
            server.kill()
            check = integrity(db_path)
            if check != "ok":
                findings["integrity"].append((round_index, action, check))
            restart_utc = utc_now()
            time.sleep(1.1)  # the next start's times are strictly later than restart_utc
            ready = server.start()
            if ready is None:
                findings["not_ready"].append((round_index, action))
                break
            ready_s.append(ready)
            time.sleep(2)
            imports, runs, tickets = unfinished(db_path, restart_utc)
            if imports or runs or tickets:
                findings["left_unfinished"].append((round_index, action, imports, runs, tickets))
            missing = incomplete_captures(db_path)
            if missing:
                findings["incomplete_captures"].append((round_index, action, missing))
            if pending_build:
                deadline = time.time() + 120
                while True:
                    status, body = server.request("GET", pending_build, timeout=120)
                    if status != 503 or time.time() > deadline:
                        break
                    time.sleep(1)
                if status != 200 or not finite_radiance(body):
                    findings["build_after_kill"].append((round_index, pending_build, status))
        # Tickets: each answers after the restarts, and every requested model has a run or
        # the reason it has none (interrupted by a kill, skipped after a failure).
        for ticket in findings.pop("tickets", []):
            status, body = server.request("GET", "/v1/evaluations/tickets/%s" % ticket)
            if status != 200:
                findings["ticket_missing"].append((ticket, status))
                continue
            answer = json.loads(body)
            unaccounted = [m for m in answer.get("models", []) if not m.get("run") and not (
                m.get("status") in ("interrupted", "skipped") and m.get("error"))]
            if len(answer.get("models", [])) < len(MODELS.split(",")) or unaccounted:
                findings["ticket_models_unaccounted"].append((ticket, answer.get("status"),
                                                              len(unaccounted)))
        server.stop()
    report = {
        "rounds": args.rounds,
        "actions": dict(actions),
        "ready_after_restart_s": {"max": round(max(ready_s), 2) if ready_s else None,
                                  "median": round(sorted(ready_s)[len(ready_s) // 2], 2)
                                  if ready_s else None},
        "findings": {k: len(v) for k, v in findings.items()},
        "examples": {k: [repr(x)[:300] for x in v[:3]] for k, v in findings.items()},
    }
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        for key, value in report.items():
            print("%-24s %s" % (key, value))
    sys.exit(1 if findings else 0)


if __name__ == "__main__":
    main()
