"""A tar archive of one synthetic capture in the Kider et al. 2014 format, written by the
generator the OpenAPI check uses (tests/server/openapi/synthetic_kider.py): 81 radiance files,
enough for an upload, an import and an evaluation to run end to end."""

from __future__ import annotations

import os
import sys
import tarfile

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
sys.path.insert(0, os.path.join(REPOSITORY, "tests", "server", "openapi"))

import synthetic_kider  # noqa: E402

CAPTURE_LABEL = "2013-05-27___11.45.00"
CAPTURE_SAMPLES = 81


def write_archive(folder: str) -> str:
    """Writes folder/capture/ and folder/capture.tar.gz; returns the archive's path."""
    capture = synthetic_kider.write_capture(os.path.join(folder, "capture"), CAPTURE_LABEL)
    archive = os.path.join(folder, "capture.tar.gz")
    with tarfile.open(archive, "w:gz") as tar:
        tar.add(capture, arcname="capture")
    return archive
