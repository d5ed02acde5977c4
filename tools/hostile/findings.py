#!/usr/bin/env python3
"""The hardening findings of docs/threat-model.md "Findings, before and after", reproduced against
a fresh `clearsky serve` of a given executable (an old one too: flags it lacks are detected from
`serve --help` and said so). Per finding: what was done, what was observed (statuses, crash,
probes answered, resident MB, seconds) and whether /healthz answered within 1 s afterwards.

  tools/hostile/findings.py --binary build/clearsky [--only 1,2,8] [--json]

Sizes are the findings' own unless the finding says it used a smaller one (a full-size run
would take minutes). Exits 0 (a reproduction that finds a problem is a result, not a failure);
with --expect-fixed, exits 1 when one of the findings run shows the old behaviour (a crash, a
request without an answer, /healthz not answering after), which is what the CTest smoke checks.
"""

import argparse
import http.client
import io
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
import zipfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_process import free_port, start_server, status_kib  # noqa: E402

TOKEN = "findings-token"
HERE = os.path.dirname(os.path.abspath(__file__))
ARCHIVES = os.path.join(HERE, "..", "..", "..", "shared", "data", "kider2014", "2013-05-27",
                        "RADIANCE")  # replaced by --archives


def raw(port, data, timeout_s=5.0):
    """Sends bytes on a new connection; returns (status or None when nothing came, body)."""
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=timeout_s)
    except OSError:
        return None, b""
    answer = b""
    try:
        s.sendall(data)
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            s.settimeout(max(0.05, end - time.monotonic()))
            chunk = s.recv(65536)
            if not chunk:
                break
            answer += chunk
            head, sep, body = answer.partition(b"\r\n\r\n")
            m = re.search(rb"content-length: *(\d+)", head, re.I)
            if sep and m and len(body) >= int(m.group(1)):
                break
    except OSError:
        pass
    finally:
        s.close()
    m = re.match(rb"HTTP/1\.[01] (\d{3})", answer)
    return (int(m.group(1)) if m else None), answer.partition(b"\r\n\r\n")[2]


def get(port, target, timeout_s=5.0, method="GET", body=b"", headers=None):
    head = "%s %s HTTP/1.1\r\nHost: clearsky\r\nConnection: close\r\n" % (method, target)
    for name, value in (headers or {}).items():
        head += "%s: %s\r\n" % (name, value)
    if body or method == "POST":
        head += "Content-Length: %d\r\n" % len(body)
    return raw(port, head.encode("latin-1") + b"\r\n" + body, timeout_s)


def post_json(port, target, body, timeout_s=30.0, token=False):
    headers = {"Content-Type": "application/json"}
    if token:
        headers["Authorization"] = "Bearer " + TOKEN
    data = body if isinstance(body, bytes) else json.dumps(body).encode()
    return get(port, target, timeout_s, "POST", data, headers)


def healthz_1s(port):
    start = time.monotonic()
    status, _ = get(port, "/healthz", timeout_s=1.0)
    return status == 200 and time.monotonic() - start <= 1.0


def error_parameter(body):
    try:
        return json.loads(body)["error"].get("parameter")
    except (ValueError, KeyError, TypeError, AttributeError):
        return "(not an error document)"


def error_code(body):
    try:
        return json.loads(body)["error"].get("code")
    except (ValueError, KeyError, TypeError, AttributeError):
        return None


class Server:
    """A fresh `serve` in its own folder; flags the executable lacks are left out (and listed)."""

    def __init__(self, binary, models, extra=(), open_files=None, file_bytes=None, token=False,
                 ready_s=300):
        self.binary, self.models = binary, models
        self.dir = tempfile.mkdtemp(prefix="clearsky-findings-")
        self.flags = help_flags(binary)
        self.missing = []
        kept = []
        args = list(extra) + (["--token", TOKEN] if token else [])
        i = 0
        while i < len(args):
            flag = args[i]
            takes_value = i + 1 < len(args) and not args[i + 1].startswith("--")
            if flag.startswith("--") and flag not in self.flags:
                self.missing.append(flag)
            else:
                kept.append(flag)
                if takes_value:
                    kept.append(args[i + 1])
            i += 2 if takes_value else 1
        self.process, self.port = start_server(binary, self.dir, models,
                                               ["--prebuild-three", "false"] + kept,
                                               open_files=open_files, file_bytes=file_bytes,
                                               ready_s=ready_s)

    def alive(self):
        return self.process.poll() is None

    def rss_mb(self, field="VmRSS"):
        return round(status_kib(self.process.pid, field) / 1024.0, 1)

    def log(self):
        with open(os.path.join(self.dir, "server.log"), errors="replace") as f:
            return f.read()

    def stop(self):
        if self.alive():
            self.process.send_signal(signal.SIGKILL)
        self.process.wait()
        subprocess.run(["rm", "-rf", self.dir])


_HELP = {}


def help_flags(binary):
    if binary not in _HELP:
        out = subprocess.run([binary, "serve", "--help"], capture_output=True, text=True).stdout
        _HELP[binary] = set(re.findall(r"(--[a-z][a-z0-9-]*)", out))
    return _HELP[binary]


def finish(server, result):
    """The common tail of a finding: crash, /healthz within 1 s, resident MB, flags missing."""
    result["crashed"] = not server.alive()
    if result["crashed"]:
        result["exit"] = server.process.returncode
    result["healthz_within_1s_after"] = server.alive() and healthz_1s(server.port)
    result["resident_mb"] = server.rss_mb()
    result["resident_peak_mb"] = server.rss_mb("VmHWM")
    if server.missing:
        result["flags_the_binary_lacks"] = server.missing
    return result


SKY = "model=preetham&sun_zenith=30&sun_azimuth=0"


def finding_1(binary, a):
    depth = 100000
    nested = b'{"a":' * depth + b"1" + b"}" * depth
    body = b'{"model":"preetham","sun_zenith":30,"sun_azimuth":0,"views":' + nested + b"}"
    result = {"did": "POST /v1/radiance and /v1/rgb with views = an object nested %d deep" % depth,
              "statuses": {}}
    for route in ("/v1/radiance", "/v1/rgb"):
        server = Server(binary, "preetham")
        try:
            status, answer = post_json(server.port, route, body, timeout_s=20)
            time.sleep(0.5)
            result["statuses"][route] = status if server.alive() else "crash"
            if status:
                result.setdefault("codes", {})[route] = error_code(answer)
            if route == "/v1/rgb":
                return finish(server, result)
            if not server.alive():
                result["crashed_on"] = route
        finally:
            server.stop()


UTF8_REQUESTS = [
    ("GET", "/v1/radiance?%s&view_zenith=45&view_azimuth=90" % SKY.replace("sun_zenith=30",
                                                                         "sun_zenith=%FF")),
    ("GET", "/v1/sun?lat=%C3%A9&lon=0&time=2026-06-21T12:00:00Z"),
    ("GET", "/v1/sun?lat=%EF%BC%95&lon=0&time=2026-06-21T12:00:00Z"),
    ("GET", "/v1/radiance?%s&view_zenith=45&view_azimuth=90&f%%FFoo=1" % SKY),
    ("POST", "/v1/radiance"),
]


def finding_2(binary, a):
    result = {"did": "5 requests with non-UTF-8 bytes (sun_zenith=%FF, lat=%C3%A9, lat=%EF%BC%95, "
                     "f%FFoo=1, a JSON body starting with 0xFF), then 300 of them on 300 "
                     "connections under ulimit -n 256", "statuses": [], "parameters": []}
    server = Server(binary, "preetham", open_files=256)
    try:
        for method, target in UTF8_REQUESTS:
            body = b"\xff{\"model\":\"preetham\"}" if method == "POST" else b""
            status, answer = get(server.port, target, 3.0, method, body,
                                 {"Content-Type": "application/json"} if body else None)
            result["statuses"].append(status if status else "no answer")
            if status:
                result["parameters"].append(error_parameter(answer))
        socks = []
        for i in range(300):
            method, target = UTF8_REQUESTS[i % 4]
            try:
                s = socket.create_connection(("127.0.0.1", server.port), timeout=2)
                s.sendall(("GET %s HTTP/1.1\r\nHost: clearsky\r\n\r\n" % target).encode())
                socks.append(s)
            except OSError:
                pass
        time.sleep(3)
        answered = 0
        for s in socks:
            try:
                s.settimeout(0.05)
                if s.recv(12).startswith(b"HTTP/1.1"):
                    answered += 1
            except OSError:
                pass
            s.close()
        result["of_300_answered"] = answered
        time.sleep(2)
        return finish(server, result)
    finally:
        server.stop()


def hostile(port, attack, connections, duration_s, probe="/healthz", extra=()):
    out = subprocess.run(
        [sys.executable, os.path.join(HERE, "hostile_clients.py"), "--port", str(port),
         "--attack", attack, "--connections", str(connections), "--duration", str(duration_s),
         "--probe-path", probe, "--json", *extra], capture_output=True, text=True,
        timeout=duration_s + 120)
    lines = out.stdout.strip().splitlines()
    report = json.loads(lines[-1]) if lines else {}
    d = report.get("during", {})
    return "%s/%s" % (d.get("answered"), d.get("total"))


def finding_3(binary, a):
    s = a.starvation_s
    result = {"did": "one server, in turn: 70 slowloris connections (a header line every 2 s) "
                     "probing /healthz and then /v1/radiance, 70 slow readers of a 4096-pixel "
                     "spectral skydome, 200 idle keep-alive connections, wrk -c1000; %d s each "
                     "(the issue: 50 s), a probe every 1 s answered within 1 s" % s,
              "probes_answered": {}}
    server = Server(binary, "preetham")
    try:
        radiance = "/v1/radiance?%s&view_zenith=45&view_azimuth=90" % SKY
        result["probes_answered"]["slowloris x70 /healthz"] = hostile(server.port, "slowloris",
                                                                      70, s)
        result["probes_answered"]["slowloris x70 /v1/radiance"] = hostile(
            server.port, "slowloris", 70, s, probe=radiance)
        result["probes_answered"]["slow readers x70"] = hostile(server.port, "slow-readers", 70, s)
        result["resident_mb_after_slow_readers"] = server.rss_mb()
        result["probes_answered"]["idle keep-alive x200"] = hostile(server.port, "idle", 200, s)
        result["probes_answered"]["wrk -c1000"] = hostile(server.port, "wrk", 1000, s)
        time.sleep(2)
        return finish(server, result)
    finally:
        server.stop()


def finding_4(binary, a):
    result = {"did": "token holder: POST /v1/datasets?name=p&path=P for /etc/shadow, "
                     "../../etc/passwd, a link in the import root to /etc/passwd, /dev/zero, "
                     "/proc/self/environ and a missing path (with --import-root when the binary "
                     "has it)", "answers": {}}
    root = tempfile.mkdtemp(prefix="clearsky-import-root-")
    os.symlink("/etc/passwd", os.path.join(root, "link"))
    server = Server(binary, "preetham", ["--import-root", root], token=True)
    try:
        paths = ["/etc/shadow", "../../etc/passwd", os.path.join(root, "link"), "/dev/zero",
                 "/proc/self/environ", "/no/such/path"]
        distinct = set()
        for i, path in enumerate(paths):
            status, answer = get(server.port, "/v1/datasets?name=p%d&path=%s" % (
                i, path.replace("/", "%2F")), 10, "POST", b"",
                {"Authorization": "Bearer " + TOKEN})
            code = error_code(answer) if status and status >= 400 else None
            result["answers"][path if path != os.path.join(root, "link") else "root/link"] = (
                "%s %s" % (status, code or "")).strip()
            distinct.add((status, code))
        time.sleep(3)
        result["distinct_answers"] = len(distinct)
        return finish(server, result)
    finally:
        server.stop()
        subprocess.run(["rm", "-rf", root])


def upload(port, name, data, timeout_s=60):
    return get(port, "/v1/datasets?name=%s" % name, timeout_s, "POST", data,
               {"Authorization": "Bearer " + TOKEN, "Content-Type": "application/octet-stream"})


def wait_import(server, answer, timeout_s):
    """The import's final state (polling its Location), or its last state at timeout."""
    try:
        doc = json.loads(answer)
    except ValueError:
        return None
    import_id = doc.get("id") or doc.get("import_id") or doc.get("import", {}).get("id")
    end = time.monotonic() + timeout_s
    state = doc.get("state") or doc.get("status")
    while import_id is not None and time.monotonic() < end and server.alive():
        status, body = get(server.port, "/v1/imports/%s" % import_id, 5)
        try:
            doc = json.loads(body)
            state = doc.get("state") or doc.get("status")
        except ValueError:
            pass
        if state not in ("queued", "running", None):
            break
        time.sleep(0.5)
    return {"state": state, "error": (doc.get("error") or {}) if isinstance(doc, dict) else None}


def finding_5(binary, a):
    mib = a.bomb_mib
    result = {"did": "token holder uploads a zip whose one entry inflates to %d MiB of zeros "
                     "(the issue: without bound); peak resident memory while it is imported"
                     % mib}
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as z:
        name = "2013-05-27___12.00.00/2013-05-27___12.00.00_-_0____0.0___12.1151.asd.rad.txt"
        with z.open(name, "w", force_zip64=True) as entry:
            block = b"\0" * (1 << 20)
            for _ in range(mib):
                entry.write(block)
    data = buffer.getvalue()
    server = Server(binary, "preetham", token=True)
    try:
        start = time.monotonic()
        status, answer = upload(server.port, "bomb", data)
        result["upload_status"] = status
        final = wait_import(server, answer, 120)
        result["import"] = final and "%s %s" % (final["state"], (final["error"] or {}).get(
            "parameter") or (final["error"] or {}).get("code") or "")
        result["seconds"] = round(time.monotonic() - start, 1)
        result["compressed_kib"] = len(data) // 1024
        return finish(server, result)
    finally:
        server.stop()


def finding_6(binary, a):
    configs = ["beta=0.4", "beta=1", "g=0.95", "beta=0.2", "alpha=1.8"][:a.bruneton_configs]
    result = {"did": "anonymous GET /v1/radiance?model=bruneton with %d new atmospheres (%s), "
                     "each answered or refused before the next%s" % (
                         len(configs), ", ".join(configs), (", --table-memory %d" % a.table_memory)
                         if a.table_memory else ""),
              "statuses": []}
    server = Server(binary, "bruneton", ["--table-memory", str(a.table_memory)] if
                    a.table_memory else [], ready_s=900)
    try:
        result["resident_mb_ready"] = server.rss_mb()
        start = time.monotonic()
        for c in configs:
            target = "/v1/radiance?model=bruneton&sun_zenith=30&sun_azimuth=0&view_zenith=45" \
                     "&view_azimuth=90&" + c
            end = time.monotonic() + 600
            while True:
                status, body = get(server.port, target, 600)
                if status != 503 or error_parameter(body) not in (None, "", "model") or \
                        time.monotonic() > end:
                    break
                time.sleep(2)
            result["statuses"].append("%s %s" % (status, error_parameter(body) if status and
                                                 status >= 400 else ""))
        result["seconds"] = round(time.monotonic() - start, 1)
        return finish(server, result)
    finally:
        server.stop()


def finding_7(binary, a):
    result = {"did": "GET /v1/radiance?model=haber for a sun not computed before: seconds to "
                     "the first answer (waiting 90 s at most)"}
    server = Server(binary, "haber", ready_s=900)
    try:
        start = time.monotonic()
        status, body = get(server.port, "/v1/radiance?model=haber&sun_zenith=37.3&sun_azimuth=0"
                           "&view_zenith=45&view_azimuth=90", 90)
        result["first_answer"] = "%s %s" % (status or "none", error_parameter(body) or "" if
                                            status and status >= 400 else "")
        result["seconds"] = round(time.monotonic() - start, 1)
        return finish(server, result)
    finally:
        server.stop()


def finding_8(binary, a):
    result = {"did": "altitude 1e999, views [[1e999,0]], a 400-digit sun_zenith, wavelengths=10 "
                     "for oneal and nishita93, a 2 MiB upload to a 1 MiB file-size limit "
                     "(RLIMIT_FSIZE, a full disk's EFBIG), a 20 kB URI (414), a bad request "
                     "line (400): status and the error's parameter", "answers": {}}
    digits = "1" * 400
    cases = [
        ("altitude=1e999", "POST", "/v1/radiance", {"model": "preetham", "sun_zenith": 30,
                                                    "sun_azimuth": 0, "altitude": "1e999",
                                                    "views": [[45, 90]]}),
        ("views=[[1e999,0]]", "POST", "/v1/radiance", None),
        ("sun_zenith=400 digits", "POST", "/v1/radiance", None),
        ("oneal wavelengths=10", "GET", "/v1/radiance?model=oneal&sun_zenith=30&sun_azimuth=0"
                                        "&view_zenith=45&view_azimuth=90&wavelengths=10", None),
        ("nishita93 wavelengths=10", "GET", "/v1/radiance?model=nishita93&sun_zenith=30"
                                            "&sun_azimuth=0&view_zenith=45&view_azimuth=90"
                                            "&wavelengths=10", None),
    ]
    server = Server(binary, "preetham,oneal,nishita93", token=True, file_bytes=1 << 20,
                    ready_s=900)
    try:
        for label, method, target, body in cases:
            if label.startswith("altitude"):
                data = (b'{"model":"preetham","sun_zenith":30,"sun_azimuth":0,"altitude":1e999,'
                        b'"views":[[45,90]]}')
                status, answer = post_json(server.port, target, data)
            elif label.startswith("sun_zenith"):
                data = ('{"model":"preetham","sun_zenith":%s,"sun_azimuth":0,"views":[[45,90]]}'
                        % digits).encode()
                status, answer = post_json(server.port, target, data)
            elif label.startswith("views"):
                data = b'{"model":"preetham","sun_zenith":30,"sun_azimuth":0,"views":[[1e999,0]]}'
                status, answer = post_json(server.port, target, data)
            else:
                status, answer = get(server.port, target, 120)
            result["answers"][label] = "%s %s" % (status, error_parameter(answer))
        status, answer = upload(server.port, "full", os.urandom(2 << 20))
        result["answers"]["upload to a full disk"] = "%s %s" % (status, error_parameter(answer))
        status, answer = get(server.port, "/v1/models?x=" + "a" * 20000, 10)
        result["answers"]["20 kB URI"] = "%s %s" % (status, error_parameter(answer))
        status, answer = raw(server.port, b"GARBAGE\r\n\r\n", 5)
        result["answers"]["bad request line"] = "%s %s" % (status, error_parameter(answer))
        return finish(server, result)
    finally:
        server.stop()


def first_archive():
    names = sorted(n for n in os.listdir(ARCHIVES) if n.endswith(".7z")) if os.path.isdir(
        ARCHIVES) else []
    if not names:
        return None
    with open(os.path.join(ARCHIVES, names[0]), "rb") as f:
        return f.read()


def finding_9(binary, a):
    archive = first_archive()
    result = {"did": "token holder uploads a Kider capture as a/b, ../x and a 5,000-character "
                     "name, then GETs and DELETEs each", "answers": {}}
    if archive is None:
        result["skipped"] = "no Kider archive under " + ARCHIVES
        return result
    server = Server(binary, "preetham", token=True)
    try:
        for label, name in (("a/b", "a%2Fb"), ("../x", "..%2Fx"), ("5000 chars", "n" * 5000)):
            status, answer = upload(server.port, name, archive)
            final = wait_import(server, answer, 60) if status == 202 else None
            got, _ = get(server.port, "/v1/datasets/" + name, 10)
            deleted, _ = get(server.port, "/v1/datasets/" + name, 10, "DELETE", b"",
                             {"Authorization": "Bearer " + TOKEN})
            result["answers"][label] = "upload %s%s, GET %s, DELETE %s" % (
                status, (" (import %s)" % final["state"]) if final else "", got, deleted)
        return finish(server, result)
    finally:
        server.stop()


def finding_10(binary, a):
    result = {"did": "tools/hostile/http_campaign.py --requests %d --seed 1 (the issue: 30,000): "
                     "resident memory peak" % a.campaign_requests}
    start = time.monotonic()
    out = subprocess.run([sys.executable, os.path.join(HERE, "http_campaign.py"), "--binary",
                          binary, "--requests", str(a.campaign_requests), "--seed", "1",
                          "--json"], capture_output=True, text=True, timeout=3600)
    result["seconds"] = round(time.monotonic() - start, 1)
    try:
        report = json.loads(out.stdout[out.stdout.index("{"):])
    except ValueError:
        result["output"] = (out.stdout + out.stderr)[-600:]
        return result
    for key in ("requests", "statuses", "crashes", "hangs", "status_500", "resident_peak_mb",
                "resident_mb", "max_rss_mb", "rss_peak_mb"):
        if key in report:
            result[key] = report[key]
    result.setdefault("report", {k: v for k, v in report.items() if not isinstance(v, list)})
    return result


def finding_11(binary, a):
    archive = first_archive()
    result = {"did": "token holder: a dataset, POST /v1/evaluations for 3 models, SIGKILL 0.2 s "
                     "later, restart: what the ticket (or the run list) says of each model"}
    if archive is None:
        result["skipped"] = "no Kider archive under " + ARCHIVES
        return result
    server = Server(binary, "preetham,hosek,oneal", token=True, ready_s=900)
    try:
        status, answer = upload(server.port, "base", archive)
        wait_import(server, answer, 60)
        status, answer = post_json(server.port, "/v1/evaluations",
                                   {"dataset": "base", "models": ["preetham", "hosek", "oneal"]},
                                   token=True)
        result["evaluation_status"] = status
        try:
            ticket = json.loads(answer).get("ticket")
        except ValueError:
            ticket = None
        time.sleep(0.2)
        server.process.send_signal(signal.SIGKILL)
        server.process.wait()
        process, port = start_server(binary, server.dir, server.models,
                                     ["--prebuild-three", "false", "--token", TOKEN],
                                     ready_s=900)
        server.process, server.port = process, port
        if ticket is not None:
            status, body = get(port, "/v1/evaluations/tickets/%s" % ticket, 10)
            try:
                models = json.loads(body).get("models", [])
                result["ticket_after_restart"] = "%s: %s" % (status, {
                    m.get("model"): m.get("status") for m in models})
            except (ValueError, AttributeError):
                result["ticket_after_restart"] = status
        else:
            result["ticket_after_restart"] = "no ticket in the 202"
        status, body = get(port, "/v1/evaluations", 10)
        try:
            doc = json.loads(body)
            runs = doc if isinstance(doc, list) else doc.get("runs", doc.get("items", []))
            result["runs_after_restart"] = "%d runs of 3 models asked: %s" % (
                len(runs), [(r.get("model"), r.get("status")) for r in runs])
        except (ValueError, AttributeError):
            result["runs_after_restart"] = status
        return finish(server, result)
    finally:
        server.stop()


def finding_12(binary, a):
    result = {"did": "GET /v1/rgb for a low sun (out-of-gamut colours): negative components or "
                     "flagged; /v1/sun with time ...+14:01; with --table-cache-model M, that "
                     "model's largest table cache file truncated, then a restart: log lines "
                     "naming it (a Bruneton build takes minutes on a loaded machine)"}
    server = Server(binary, ",".join(["oneal"] + ([a.table_cache_model] if
                                                  a.table_cache_model else [])), ready_s=900)
    try:
        views = [[z, az] for z in range(0, 91, 10) for az in range(-180, 180, 30)]
        negative, flagged, statuses = 0, 0, set()
        for sun_zenith in (89.5, 92.0, 95.0):
            status, body = post_json(server.port, "/v1/rgb", {
                "model": "oneal", "sun_zenith": sun_zenith, "sun_azimuth": 0, "views": views}, 60)
            statuses.add(status)
            try:
                for sample in json.loads(body)["samples"]:
                    negative += any(x < 0 for x in sample["rgb"])
                    flagged += bool(sample.get("gamut_clipped"))
            except (ValueError, KeyError, TypeError):
                pass
        result["low_sun_rgb"] = "statuses %s, %d samples with a negative component, %d flagged " \
                                "gamut_clipped (of %d)" % (sorted(statuses, key=str), negative,
                                                           flagged, 3 * len(views))
        status, body = get(server.port, "/v1/sun?lat=0&lon=0&time=2026-06-21T12:00:00%2B14:01", 10)
        result["utc_offset_+14:01"] = "%s %s" % (status, error_parameter(body) if status and
                                                 status >= 400 else "")
        if not a.table_cache_model:
            return finish(server, result)
        server.process.send_signal(signal.SIGKILL)
        server.process.wait()
        cache = os.path.join(server.dir, "cache")
        files = [os.path.join(d, f) for d, _, fs in os.walk(cache) for f in fs]
        files = sorted((f for f in files if os.path.getsize(f) > 4096), key=os.path.getsize)[::-1]
        if files:
            with open(files[0], "r+b") as f:
                f.truncate(os.path.getsize(files[0]) // 2)
            before = len(server.log())
            process, port = start_server(server.binary, server.dir, server.models,
                                         ["--prebuild-three", "false"], ready_s=900)
            server.process, server.port = process, port
            time.sleep(1)
            name = os.path.basename(files[0])
            lines = [line for line in server.log()[before:].splitlines()
                     if name in line or "truncat" in line.lower() or "damaged" in line.lower()]
            result["truncated_cache_log_lines"] = len(lines)
        else:
            result["truncated_cache_log_lines"] = "no cache file written"
            process, port = start_server(server.binary, server.dir, server.models,
                                         ["--prebuild-three", "false"], ready_s=900)
            server.process, server.port = process, port
        return finish(server, result)
    finally:
        server.stop()


def still_open(n, r):
    """Whether a finding's result shows the old behaviour (what --expect-fixed checks)."""
    if "error" in r or r.get("crashed") or not r.get("healthz_within_1s_after", True):
        return True
    if n == 1:
        return any(s != 400 for s in r["statuses"].values())
    if n == 2:
        return any(s == "no answer" or s >= 500 for s in r["statuses"]) or \
            r["of_300_answered"] < 300
    if n == 4:
        return r["distinct_answers"] > 1 or any(v.startswith("2") for v in r["answers"].values())
    if n == 8:
        return any(v.startswith("5") and not v.startswith("507") or v.endswith("None")
                   for v in r["answers"].values())
    return False


FINDINGS = {i: globals()["finding_%d" % i] for i in range(1, 13)}


def main():
    global ARCHIVES
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--binary", default="build/clearsky")
    p.add_argument("--only", default="", help="comma-separated finding numbers (default: all)")
    p.add_argument("--starvation-s", type=int, default=20)
    p.add_argument("--bomb-mib", type=int, default=256)
    p.add_argument("--bruneton-configs", type=int, default=3)
    p.add_argument("--campaign-requests", type=int, default=3000)
    p.add_argument("--table-cache-model", default="", help="finding 12: a model with a table "
                   "cache on disk (bruneton); default: that part is not run")
    p.add_argument("--table-memory", type=int, default=0, help="finding 6: serve --table-memory "
                   "(default: the server's own)")
    p.add_argument("--expect-fixed", action="store_true")
    p.add_argument("--json", action="store_true")
    p.add_argument("--archives", default=ARCHIVES, help="a folder of Kider .7z captures "
                   "(findings 9 and 11; default: ../shared/data/kider2014/2013-05-27/RADIANCE "
                   "beside the repository)")
    a = p.parse_args()
    ARCHIVES = a.archives
    binary = os.path.abspath(a.binary)
    chosen = [int(x) for x in a.only.split(",") if x] or sorted(FINDINGS)
    results = {}
    for n in chosen:
        start = time.monotonic()
        try:
            r = FINDINGS[n](binary, a)
        except Exception as e:  # a reproduction that could not run is reported, not fatal
            r = {"error": "%s: %s" % (type(e).__name__, e)}
        r.setdefault("seconds", round(time.monotonic() - start, 1))
        results[n] = r
        if not a.json:
            print("%2d %s" % (n, json.dumps(r)), flush=True)
    if a.json:
        print(json.dumps({"binary": binary, "findings": results}, indent=1))
    if a.expect_fixed:
        old = [n for n, r in results.items() if still_open(n, r)]
        if old:
            print("findings showing the old behaviour: %s" % old, file=sys.stderr)
            sys.exit(1)


if __name__ == "__main__":
    main()
