"""`clearsky serve` as a child process for the client's tests: a temporary database, cache and
token file, the port the server chose (--port 0, read from its log), ready once /readyz answers
200 (docs/http-api.md). The executable comes from the environment variable CLEARSKY_BINARY,
which CTest sets (tests/clients/python/CMakeLists.txt)."""

from __future__ import annotations

import http.client
import os
import re
import subprocess
import tempfile
import time
from typing import List, Optional, Sequence

TOKEN = "python-client-test-token"
START_DEADLINE_S = 120.0


def binary_path() -> str:
    path = os.environ.get("CLEARSKY_BINARY")
    if not path or not os.access(path, os.X_OK):
        raise RuntimeError("set CLEARSKY_BINARY to the built clearsky executable "
                           "(ctest -R PythonClient does)")
    return path


class ServeProcess:
    """One server; stop() ends it (SIGTERM, then SIGKILL after 30 s) and removes its folder."""

    def __init__(self, extra: Sequence[str] = (), role: str = "writer",
                 models: str = "preetham,hosek") -> None:
        self._folder = tempfile.TemporaryDirectory(prefix="clearsky-pyclient-")
        self.folder = self._folder.name
        self.import_root = os.path.join(self.folder, "imports")
        os.makedirs(self.import_root)
        token_file = os.path.join(self.folder, "token")
        with open(token_file, "w", encoding="ascii") as f:
            f.write(TOKEN)
        command: List[str] = [binary_path(), "serve", "--role", role, "--host", "127.0.0.1",
                              "--port", "0", "--models", models,
                              "--cache-dir", os.path.join(self.folder, "cache")]
        if role == "writer":
            command += ["--db", os.path.join(self.folder, "sky.db"), "--token-file", token_file,
                        "--import-root", self.import_root]
        command += list(extra)
        self._log_path = os.path.join(self.folder, "serve.log")
        self._log = open(self._log_path, "wb")
        self.process = subprocess.Popen(command, stdout=self._log, stderr=subprocess.STDOUT)
        self.port = self._wait_ready()
        self.url = f"http://127.0.0.1:{self.port}"

    def log(self) -> str:
        with open(self._log_path, encoding="utf-8", errors="replace") as f:
            return f.read()

    def _wait_ready(self) -> int:
        deadline = time.monotonic() + START_DEADLINE_S
        port: Optional[int] = None
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError("clearsky serve exited at start:\n" + self.log())
            if port is None:
                found = re.search(r"serving on http://127\.0\.0\.1:(\d+)", self.log())
                port = int(found.group(1)) if found else None
            elif self._ready(port):
                return port
            time.sleep(0.1)
        self.stop()
        raise RuntimeError(f"clearsky serve not ready within {START_DEADLINE_S:g} s")

    @staticmethod
    def _ready(port: int) -> bool:
        connection = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        try:
            connection.request("GET", "/readyz")
            return connection.getresponse().status == 200
        except OSError:
            return False
        finally:
            connection.close()

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self._log.close()
        self._folder.cleanup()
