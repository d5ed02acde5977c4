"""An archive file read for an upload, reporting its progress: http.client reads the body from
this object block by block, and each block read is reported as (bytes_sent, bytes_total)."""

from __future__ import annotations

import os
from typing import BinaryIO, Callable, Optional

# progress(bytes_sent, bytes_total)
Progress = Callable[[int, int], None]


class ProgressFile:
    """Wraps a binary file opened for reading. Not thread-safe: one upload reads it."""

    def __init__(self, path: str, progress: Optional[Progress]) -> None:
        self._file: BinaryIO = open(path, "rb")
        self.total_bytes = os.fstat(self._file.fileno()).st_size
        self._sent = 0
        self._progress = progress

    def read(self, size: int = -1) -> bytes:
        block = self._file.read(size)
        self._sent += len(block)
        if block and self._progress is not None:
            self._progress(self._sent, self.total_bytes)
        return block

    def close(self) -> None:
        self._file.close()
