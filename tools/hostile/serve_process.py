"""`clearsky serve` as a child process for the hostile tools (docs/threat-model.md): a free
loopback port, the server started on it with a database and cache in a work folder, ready once
/readyz answers 200; and the process's memory figures from /proc."""

import http.client
import os
import resource
import signal
import socket
import subprocess
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(binary, workdir, models, extra=(), open_files=None, file_bytes=None,
                 ready_s=120, cache_dir=None):
    """Starts `binary serve` on a free port; returns (process, port) once it is ready (ready_s
    at most). Its output goes to workdir/server.log. open_files: its RLIMIT_NOFILE;
    file_bytes: its RLIMIT_FSIZE (SIGXFSZ ignored, so that a write beyond fails with EFBIG);
    cache_dir: its table cache (default workdir/cache)."""
    port = free_port()
    log = open(os.path.join(workdir, "server.log"), "ab")

    def limits():
        if open_files is not None:
            resource.setrlimit(resource.RLIMIT_NOFILE, (open_files, open_files))
        if file_bytes is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (file_bytes, file_bytes))

    process = subprocess.Popen(
        [binary, "serve", "--port", str(port), "--db", os.path.join(workdir, "db.sqlite"),
         "--cache-dir", cache_dir or os.path.join(workdir, "cache"), "--models", models,
         *extra],
        stdout=log, stderr=subprocess.STDOUT, preexec_fn=limits)
    deadline = time.time() + ready_s
    while time.time() < deadline:
        if process.poll() is not None:
            raise RuntimeError("the server exited at start (see %s/server.log)" % workdir)
        try:
            c = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
            c.request("GET", "/readyz")
            if c.getresponse().status == 200:
                return process, port
        except OSError:
            pass
        time.sleep(0.2)
    process.kill()
    raise RuntimeError("the server was not ready within %d s" % ready_s)


def status_kib(pid, field):
    """A figure of /proc/PID/status in KiB (VmRSS, VmHWM) or a count (Threads); 0 when gone."""
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0
