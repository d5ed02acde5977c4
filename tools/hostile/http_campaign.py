#!/usr/bin/env python3
"""A hostile client's campaign against a real `clearsky serve` (docs/threat-model.md).

Reads the server's own /openapi.json, then sends requests to every operation: valid values
taken from the document (examples, defaults, enums, range ends) mixed with hostile ones
(invalid UTF-8, overflowing and non-finite numbers, huge and empty values, unknown and repeated
parameters, deeply nested and truncated JSON bodies, wrong tokens). It counts the statuses and
checks the server's promises:

  - every answer arrives (a request that takes more than --hang-s seconds is a hang);
  - no 500 (an internal error is a bug: the request is printed);
  - every error body is JSON naming a parameter or limit (`error.parameter` not null);
  - every number in a successful JSON body is finite, and radiances are not negative;
  - the process never dies, and /healthz answers within 1 s at the end;
  - the resident memory peak (VmHWM) and the final resident memory (VmRSS) are reported.

Standard library only. Usage:
  tools/hostile/http_campaign.py --binary build/clearsky --requests 30000 --seed 1 [--json]
The server is started on a free port with a temporary database and stopped at the end.
"""

import argparse
import collections
import http.client
import json
import math
import os
import random
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.parse

from serve_process import start_server, status_kib

TOKEN = "campaign-token"


def resolve(document, node):
    while isinstance(node, dict) and "$ref" in node:
        target = document
        for part in node["$ref"].lstrip("#/").split("/"):
            target = target[part]
        node = target
    return node


HOSTILE_TEXT = [
    "", " ", "-", "+", ".", "e", "1e999", "-1e999", "1e-999", "nan", "NaN", "inf", "-inf",
    "Infinity", "0x10", "1_0", "1,5", "١٢", "\uff15", "9" * 400, "-0", "00000000001",
    "1e308", "-1e308", "4.9e-324", "2147483648", "-2147483649", "18446744073709551616",
    "%FF", "%C3%A9", "%EF%BC%95", "%00", "%0d%0aX-Injected: 1", "../../etc/passwd",
    "/etc/shadow", "/dev/zero", "a" * 5000, "{}", "[]", "null", "true", "\"", "'", ";",
    "2013-05-27T25:61:61Z", "2013-02-30T12:00:00Z", "9999-12-31T23:59:59+14:01",
    "0000-01-01T00:00:00Z", "2013-05-27T12:00:00", "* * * * *", "@yearly",
]


def schema_values(schema):
    values = []
    for key in ("example", "default"):
        if key in schema:
            values.append(schema[key])
    values += schema.get("enum", [])
    for key in ("minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"):
        if key in schema:
            bound = schema[key]
            values += [bound, bound - 1e-9, bound + 1e-9, bound * 10 + 1]
    if schema.get("type") == "boolean":
        values += [True, False, "yes", "2"]
    if schema.get("type") in ("number", "integer") and not values:
        values += [0, 1, -1, 45.5]
    return values or ["x"]


def text_of(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return str(value)


def quote(text):
    # Percent-escapes in HOSTILE_TEXT ("%FF") are kept: the server decodes them to raw bytes.
    if text.startswith("%") and len(text) > 1:
        return urllib.parse.quote(text, safe="%,:*")
    return urllib.parse.quote(text, safe=",:*")


class Campaign:
    def __init__(self, document, port, rng, hang_s):
        self.document = document
        self.port = port
        self.rng = rng
        self.hang_s = hang_s
        self.statuses = collections.Counter()
        self.findings = collections.defaultdict(list)
        self.requests = 0
        self.unnamed = collections.Counter()
        self.last = None
        self.current_path = ""
        self.operations = []
        for path, item in document["paths"].items():
            for method, op in item.items():
                if method in ("get", "post", "delete"):
                    self.operations.append((method.upper(), path, op))

    def parameters(self, op):
        out = []
        for p in op.get("parameters", []):
            p = resolve(self.document, p)
            if p.get("in") == "query":
                out.append((p["name"], resolve(self.document, p.get("schema", {}))))
        return out

    def path_of(self, path):
        choices = {"{name}": ["kider2014", "none", "a%2Fb", "..", "x" * 300, "%FF"],
                   "{id}": ["1", "0", "-1", "99999999999999999999", "abc", "1.5"],
                   "{ticket}": ["1", "abc", "0"]}
        for key, values in choices.items():
            if key in path:
                path = path.replace(key, self.rng.choice(values))
        return path

    def query(self, op):
        parts = []
        for name, schema in self.parameters(op):
            if self.rng.random() < 0.5:
                continue
            if self.rng.random() < 0.8:
                value = quote(text_of(self.rng.choice(schema_values(schema))))
            else:
                value = quote(self.rng.choice(HOSTILE_TEXT)) if self.rng.random() < 0.5 else \
                    self.rng.choice(HOSTILE_TEXT[29:32])
            parts.append("%s=%s" % (urllib.parse.quote(name), value))
            if self.rng.random() < 0.03:
                parts.append(parts[-1])  # repeated
        if self.rng.random() < 0.05:
            parts.append(self.rng.choice(["f%FFoo=1", "unknown=1", "=1", "&&", "a=%"]))
        self.rng.shuffle(parts)
        return "&".join(parts)

    def body(self, op):
        content = resolve(self.document, op.get("requestBody", {})).get("content", {})
        media = content.get("application/json")
        if media is None:
            return None, None
        example = media.get("example")
        if example is None:
            example = resolve(self.document, media.get("schema", {})).get("example", {})
        roll = self.rng.random()
        if roll < 0.5:
            data = json.dumps(example).encode()
        elif roll < 0.6:
            depth = self.rng.choice([10, 1000, 50000, 100000])
            data = (b'{"model":"preetham","sun_zenith":30,"sun_azimuth":0,"views":' +
                    b'{"a":' * depth + b"1" + b"}" * depth + b"}")
        elif roll < 0.7:
            data = b"\xff\xfe" + json.dumps(example).encode()
        elif roll < 0.8:
            data = json.dumps(example).encode()[: self.rng.randint(0, 40)]
        else:
            mutated = dict(example) if isinstance(example, dict) else {}
            if mutated:
                key = self.rng.choice(list(mutated))
                mutated[key] = self.rng.choice(
                    [None, [], {}, "1e999", -1, 1e308, "x" * 10000, [[1e308, 0]] * 3, True])
            data = json.dumps(mutated).encode().replace(b"1e+308", b"1e999")
        return data, "application/json"

    def check_body(self, status, content_type, body, request):
        if status == 500:
            self.findings["internal_error"].append(request)
        if status >= 400 and status != 304:
            try:
                parsed = json.loads(body)
                error = parsed.get("error") if isinstance(parsed, dict) else None
                if not isinstance(error, dict) or error.get("parameter") in (None, ""):
                    self.findings["error_without_parameter"].append((status, request))
                    self.unnamed[(status, request[0], self.current_path)] += 1
            except ValueError:
                self.findings["error_not_json"].append((status, request))
        elif 200 <= status < 300 and content_type.startswith("application/json") and body:
            try:
                parsed = json.loads(body, parse_constant=lambda c: float("nan"))
            except ValueError:
                self.findings["success_not_json"].append(request)
                return
            bad = []

            def walk(node, key=""):
                if isinstance(node, dict):
                    for k, v in node.items():
                        walk(v, k)
                elif isinstance(node, list):
                    for v in node:
                        walk(v, key)
                elif isinstance(node, float):
                    if not math.isfinite(node) or (key in ("radiance", "irradiance") and node < 0):
                        bad.append((key, node))
            walk(parsed)
            if bad:
                self.findings["bad_number"].append((request, bad[:3]))

    def send(self, method, target, body, content_type, headers):
        self.requests += 1
        self.last = (method, target, (body or b"")[:300])
        started = time.time()
        try:
            c = http.client.HTTPConnection("127.0.0.1", self.port, timeout=self.hang_s)
            c.putrequest(method, target, skip_accept_encoding=True)
            for k, v in headers.items():
                c.putheader(k, v)
            if body is not None:
                c.putheader("Content-Type", content_type)
                c.putheader("Content-Length", str(len(body)))
            try:
                c.endheaders(body)
            except (BrokenPipeError, ConnectionResetError):
                # Refused from its head (a wrong token, a body above the limit): the server
                # answered and closed before the body was sent; the answer is still there.
                pass
            r = c.getresponse()
            data = r.read(64 << 20)
            c.close()
            self.statuses[r.status] += 1
            self.check_body(r.status, r.getheader("Content-Type", ""), data,
                            (method, target[:300], (body or b"")[:200]))
        except socket.timeout:
            self.statuses["hang"] += 1
            self.findings["hang"].append((method, target[:300], time.time() - started))
        except (ConnectionError, http.client.HTTPException, OSError) as e:
            self.statuses["connection_error"] += 1
            self.findings["connection_error"].append((method, target[:200], repr(e)[:100]))

    def one(self):
        method, path, op = self.rng.choice(self.operations)
        self.current_path = path
        target = self.path_of(path)
        q = self.query(op)
        if q:
            target += "?" + q
        headers = {}
        if method != "GET" or self.rng.random() < 0.05:
            roll = self.rng.random()
            if roll < 0.7:
                headers["Authorization"] = "Bearer " + TOKEN
            elif roll < 0.85:
                headers["Authorization"] = "Bearer wrong"
        if self.rng.random() < 0.03:
            headers["If-None-Match"] = self.rng.choice(["*", '"abc"', "W/\"x\", \"y\""])
        if self.rng.random() < 0.02:
            headers["Origin"] = "http://evil.example"
        body, content_type = (None, None)
        if method == "POST":
            body, content_type = self.body(op)
            if path == "/v1/datasets":
                body, content_type = os.urandom(self.rng.randint(0, 4096)), "application/octet-stream"
        self.send(method, target, body, content_type, headers)


def healthz_seconds(port):
    started = time.time()
    try:
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=5)
        c.request("GET", "/healthz")
        ok = c.getresponse().status == 200
        return time.time() - started if ok else None
    except OSError:
        return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/clearsky")
    parser.add_argument("--requests", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--models", default="preetham,hosek")
    parser.add_argument("--hang-s", type=float, default=30.0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()

    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory(prefix="clearsky-campaign-") as workdir:
        process, port = start_server(args.binary, workdir, args.models, ["--token", TOKEN])
        try:
            c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            c.request("GET", "/openapi.json")
            document = json.loads(c.getresponse().read())
            campaign = Campaign(document, port, rng, args.hang_s)
            start_rss = status_kib(process.pid, "VmRSS")
            started = time.time()
            crashes = []
            peak_kib = 0
            for _ in range(args.requests):
                campaign.one()
                if campaign.requests % 50 == 0:
                    peak_kib = max(peak_kib, status_kib(process.pid, "VmHWM"))
                if process.poll() is not None:
                    # A crash is a finding; the campaign goes on against a restarted server.
                    crashes.append({"after_request": campaign.requests,
                                    "exit_code": process.returncode,
                                    "last": repr(campaign.last)[:300]})
                    process, port = start_server(args.binary, workdir, args.models, ["--token", TOKEN])
                    campaign.port = port
            elapsed = time.time() - started
            health = healthz_seconds(port)
            peak_kib = max(peak_kib, status_kib(process.pid, "VmHWM"))
            report = {
                "requests": campaign.requests,
                "seconds": round(elapsed, 1),
                "statuses": {str(k): v for k, v in sorted(campaign.statuses.items(), key=str)},
                "crashes": crashes,
                "healthz_after_s": health,
                "resident_start_mib": round(start_rss / 1024, 1),
                "resident_peak_mib": round(peak_kib / 1024, 1),
                "resident_end_mib": round(status_kib(process.pid, "VmRSS") / 1024, 1),
                "findings": {k: len(v) for k, v in campaign.findings.items()},
                "unnamed_errors": {"%s %s %s" % k: v for k, v in campaign.unnamed.most_common()},
                "examples": {k: [repr(x)[:400] for x in v[:3]]
                             for k, v in campaign.findings.items()},
            }
        finally:
            if process.poll() is None:
                process.send_signal(signal.SIGTERM)
                try:
                    process.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    process.kill()
    if args.json:
        print(json.dumps(report, indent=2))
    else:
        for key, value in report.items():
            print("%-20s %s" % (key, value))
    ok = (not report["crashes"] and report["healthz_after_s"] is not None and
          report["healthz_after_s"] < 1.0 and not campaign.findings)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
