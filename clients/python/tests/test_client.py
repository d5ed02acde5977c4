"""The Python client against a real `clearsky serve` (docs/clients.md): every method of Client,
the errors (a 400 naming its parameter, a 401 without the token, 404 no_database on a query
replica), and the bounded retry of a 503 with Retry-After (the answer memory held by another
answer: server/README.md "Memory budget of answers in flight").

Run by CTest (PythonClient, tests/clients/python/CMakeLists.txt), or by hand:
CLEARSKY_BINARY=build/clearsky PYTHONPATH=clients/python python3 -m unittest discover -s
clients/python/tests -v"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import os
import re
import socket
import tempfile
import threading
import unittest

import numpy as np

import kider_archive
from kider_archive import REPOSITORY
from clearsky_client import ClearskyError, Client, RetryNotice, RetryPolicy
from serve_process import TOKEN, ServeProcess

SUN = {"sun_zenith": 30, "sun_azimuth": 135}
EXR_MAGIC = b"\x76\x2f\x31\x01"  # OpenEXR file layout, "Magic Number"
# The answer memory bands (SkydomeRender::band_bytes, reported by the server's 413 message):
# a 1024-pixel spectral fisheye of the 40 default wavelengths holds 2351104 bytes, a 256-pixel
# one 755712. The budget fits the first with 500000 bytes to spare: the second waits for it.
HOLDER_QUERY = ("/v1/skydome?model=preetham&sun_zenith=30&sun_azimuth=135&size=1024"
                "&channels=spectral")
ANSWER_MEMORY_BYTES = 2351104 + 500000

# The README examples that must run as written (the address of the test server substituted).
READMES = [os.path.join(REPOSITORY, "clients", "python", "README.md"),
           os.path.join(REPOSITORY, "README.md")]

# Every operation of the route table (docs/http-api.md) and the client method that calls it.
CLIENT_METHODS = {
    "healthz": "health", "readyz": "readiness", "metrics": "metrics", "openapi": "openapi",
    "listModels": "models", "getSun": "sun", "getRadiance": "radiance",
    "postRadiance": "radiance_batch", "getIrradiance": "irradiance",
    "getIrradianceSeries": "irradiance_series", "getRgb": "rgb",
    "postRgb": "rgb_batch", "getSkydome": "skydome", "getSkyPatches": "sky_patches", "listDatasets": "list_datasets",
    "importDataset": "upload_dataset", "getDataset": "get_dataset",
    "deleteDataset": "delete_dataset", "listImports": "list_imports", "getImport": "get_import",
    "listEvaluations": "list_evaluations", "createEvaluation": "create_evaluation",
    "getEvaluation": "get_evaluation", "getEvaluationTicket": "get_evaluation_ticket",
    "listFits": "list_fits", "createFit": "create_fit", "getFit": "get_fit",
    "listAerosols": "list_aerosols", "uploadAerosols": "upload_aerosols",
    "getAerosols": "get_aerosols",
    "listJobs": "list_jobs", "createJob": "create_job", "getJob": "get_job",
    "deleteJob": "delete_job", "pauseJob": "pause_job", "resumeJob": "resume_job",
}


def python_blocks(markdown_path: str):
    """The ```python blocks of a Markdown file (not those marked ```python notest)."""
    with open(markdown_path, encoding="utf-8") as f:
        return re.findall(r"^```python\n(.*?)^```", f.read(), re.M | re.S)


def has_openimageio() -> bool:
    return importlib.util.find_spec("OpenImageIO") is not None


class SkydomeHolder:
    """A client that starts a large skydome and reads only its status line, so that the server
    holds the image's band in its answer memory until close() (a small receive buffer keeps
    the server's writes blocked)."""

    def __init__(self, port: int) -> None:
        self._socket = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._socket.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        self._socket.settimeout(120)
        self._socket.connect(("127.0.0.1", port))
        self._socket.sendall(f"GET {HOLDER_QUERY} HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n".encode())
        line = b""
        while not line.endswith(b"\r\n"):
            byte = self._socket.recv(1)
            if not byte:
                break
            line += byte
        self.status_line = line.decode("ascii", errors="replace").strip()
        self._lock = threading.Lock()

    def close(self) -> None:
        with self._lock:
            self._socket.close()


class ClientAgainstWriter(unittest.TestCase):
    server: ServeProcess
    client: Client
    anonymous: Client

    @classmethod
    def setUpClass(cls) -> None:
        cls.server = ServeProcess(extra=["--answer-memory", str(ANSWER_MEMORY_BYTES),
                                         "--retry-after", "1", "--min-send-rate", "0",
                                         "--write-timeout", "300"])
        cls.client = Client(cls.server.url, token=TOKEN, timeout=120)
        cls.anonymous = Client(cls.server.url, timeout=120)
        cls.work = tempfile.TemporaryDirectory(prefix="clearsky-pyclient-work-")

    @classmethod
    def tearDownClass(cls) -> None:
        cls.server.stop()
        cls.work.cleanup()

    def assertRefused(self, call, status: int, code: str, parameter) -> ClearskyError:
        with self.assertRaises(ClearskyError) as caught:
            call()
        error = caught.exception
        self.assertEqual((error.status, error.code, error.parameter), (status, code, parameter),
                         error.message)
        return error

    def test_every_operation_has_a_client_method(self) -> None:
        document = self.client.openapi()
        operations = {op["operationId"] for item in document["paths"].values()
                      for op in item.values()}
        self.assertEqual(operations, set(CLIENT_METHODS))
        for method in CLIENT_METHODS.values():
            self.assertTrue(callable(getattr(self.client, method)), method)

    def test_service(self) -> None:
        self.assertEqual(self.client.health()["status"], "ok")
        readiness = self.client.readiness()
        self.assertEqual(readiness["status"], "ready")
        self.assertEqual(set(readiness["models"]), {"preetham", "hosek"})
        self.assertIn("clearsky_", self.client.metrics())

    def test_models(self) -> None:
        models = {m.id: m for m in self.client.models()}
        self.assertEqual(set(models), {"preetham", "hosek"})
        turbidity = next(p for p in models["preetham"].parameters if p.name == "turbidity")
        self.assertEqual((turbidity.min, turbidity.max), (2, 10))
        self.assertEqual(models["hosek"].status, "ready")

    def test_sun(self) -> None:
        sun = self.client.sun(42.444, -76.5, "2013-05-27T11:45:00-04:00")
        self.assertAlmostEqual(sun.zenith_deg, 26.6525, places=3)
        self.assertAlmostEqual(sun.azimuth_deg, 136.0464, places=3)
        self.assertEqual(sun.day, "normal")
        self.assertTrue(sun.sunrise.startswith("2013-05-27T05:34"))

    def test_radiance_single_and_batch(self) -> None:
        one = self.client.radiance("preetham", 45, 0, wavelengths=[450, 550, 650], **SUN)
        np.testing.assert_array_equal(one.wavelengths_nm, [450.0, 550.0, 650.0])
        self.assertEqual(one.radiance.shape, (1, 3))
        self.assertTrue(np.all(one.radiance > 0))
        batch = self.client.radiance_batch("preetham", [(60, 90), (45, 0)],
                                           wavelengths="450,550,650", **SUN)
        self.assertEqual(batch.radiance.shape, (2, 3))
        np.testing.assert_array_equal(batch.view_zenith_deg, [60.0, 45.0])
        np.testing.assert_array_equal(batch.radiance[1], one.radiance[0])
        self.assertEqual((batch.sun.zenith_deg, batch.sun.source), (30.0, "given"))
        # The default grid: the paper's 40 bins of 11.75 nm from 360 nm.
        full = self.client.radiance("hosek", 45, 0, lat=42.444, lon=-76.5,
                                    time="2013-05-27T11:45:00-04:00", turbidity=3)
        self.assertEqual(full.sun.source, "spa")
        self.assertEqual(full.radiance.shape[1], full.wavelengths_nm.shape[0])
        self.assertGreater(full.wavelengths_nm.shape[0], 20)

    def test_quality(self) -> None:
        # docs/quality-levels.md: Preetham has no cost option, so its three levels are one
        # setting; each answer states the level asked and served.
        draft = self.client.radiance("preetham", 45, 0, wavelengths=[450, 550, 650],
                                     quality="draft", **SUN)
        self.assertEqual((draft.quality, draft.served_quality), ("draft", "draft"))
        self.assertEqual(draft.raw["quality_setting"], {})
        self.assertEqual(draft.raw["quality_error"]["max_relative"], 0.0)
        plain = self.client.radiance("preetham", 45, 0, wavelengths=[450, 550, 650], **SUN)
        self.assertEqual(plain.quality, "standard")
        np.testing.assert_array_equal(draft.radiance, plain.radiance)
        batch = self.client.rgb_batch("hosek", [(45, 0)], quality="reference", **SUN)
        self.assertEqual(batch.quality, "reference")
        self.assertEqual(self.client.irradiance("preetham", quality="draft", **SUN).quality,
                         "draft")
        self.assertEqual(self.client.sky_patches("preetham", output="luminance",
                                                 quality="draft", **SUN)["quality"], "draft")
        self.assertRefused(lambda: self.client.radiance("preetham", 45, 0, quality="best", **SUN),
                           400, "invalid_parameter", "quality")

    def test_irradiance(self) -> None:
        plane = self.client.irradiance("preetham", tilt=30, surface_azimuth=180, spectral=True,
                                       **SUN)
        self.assertEqual((plane.tilt_deg, plane.surface_azimuth_deg), (30.0, 180.0))
        # Global = direct + sky diffuse + ground diffuse (docs/building-energy.md).
        self.assertAlmostEqual(plane.global_.irradiance_w_m2,
                               plane.direct.irradiance_w_m2 + plane.diffuse.irradiance_w_m2
                               + plane.ground_diffuse.irradiance_w_m2,
                               delta=1e-9 * plane.global_.irradiance_w_m2)
        self.assertGreater(plane.ground_diffuse.irradiance_w_m2, 0)
        wall = self.client.irradiance("preetham", tilt=90, ground_albedo=0.25, **SUN)
        flat = self.client.irradiance("preetham", **SUN)
        self.assertAlmostEqual(wall.ground_diffuse.irradiance_w_m2,
                               0.25 * flat.global_.irradiance_w_m2 / 2,
                               delta=1e-9 * flat.global_.irradiance_w_m2)
        without = self.client.irradiance("preetham", tilt=90, ground_reflection="exclude", **SUN)
        self.assertIsNone(without.ground_diffuse)
        self.assertEqual(plane.global_.spectral_w_m2_nm.shape, plane.wavelengths_nm.shape)
        diffuse = self.client.irradiance("preetham", component="diffuse", **SUN)
        self.assertIsNone(diffuse.direct)
        self.assertGreater(diffuse.diffuse.illuminance_lx, 0)
        # Preetham cannot go broadband: no broadband number, a reason instead; the figure over
        # its own range keeps its deprecated alias.
        dry = self.client.irradiance("preetham", precipitable_water_cm=0.5, ozone_atm_cm=0.3,
                                     **SUN)
        self.assertIsNone(dry.global_.broadband_irradiance_w_m2)
        self.assertIn("turbidity", dry.broadband_unavailable)
        self.assertEqual(dry.global_.model_range_irradiance_w_m2, dry.global_.irradiance_w_m2)

    def test_irradiance_series(self) -> None:
        # Paris on the day clocks go forward: local midnight to 06:00 is five hours.
        day = self.client.irradiance_series("preetham", 48.85, 2.35, "2024-03-31T00:00:00",
                                            "2024-03-31T23:00:00", tz="Europe/Paris",
                                            planes=[(30, 180), (90, 90)], ground_albedo=0.2)
        self.assertEqual(len(day), 23)
        self.assertEqual(day["time_local"][3], "2024-03-31T04:00:00+02:00")
        self.assertTrue(day["night"][0])
        # Preetham cannot go broadband: ghi, dni, dhi and poa_* are NaN (null) in every row,
        # with the reason; its own figures are the model_range_* columns.
        self.assertTrue(np.isnan(day["ghi"]).all())
        self.assertTrue(np.isnan(day["poa_global_30_180"]).all())
        self.assertIn("turbidity", day.broadband_unavailable)
        self.assertEqual(day["model_range_ghi"][0], 0.0)
        up = ~day["night"]
        ghi = day["model_range_ghi"]
        self.assertGreater(ghi[up].min(), 0.0)
        np.testing.assert_allclose(day["model_range_poa_ground_diffuse_90_90"][up],
                                   0.2 * ghi[up] / 2, rtol=1e-12)
        np.testing.assert_allclose(day["model_range_poa_global_30_180"],
                                   day["model_range_poa_direct_30_180"]
                                   + day["model_range_poa_diffuse_30_180"],
                                   rtol=1e-12, atol=1e-9)
        self.assertEqual(day.unanswered_steps, 0)
        self.assertRefused(lambda: self.client.irradiance_series(
            "preetham", 48.85, 2.35, "2024-01-01T00:00:00Z", "2025-12-31T00:00:00Z",
            step="PT10M"), 413, "too_large", "step")
        self.assertRefused(lambda: self.client.irradiance_series(
            "preetham", 48.85, 2.35, "2024-01-01T00:00:00Z", "2024-01-02T00:00:00Z",
            planes=[(200, 180)]), 400, "invalid_parameter", "planes")

    def test_sky_patches(self) -> None:
        vector = self.client.sky_patches("preetham", output="luminance", **SUN)
        self.assertEqual(len(vector["patches"]), 146)  # Tregenza: the ground and 145 patches
        reinhart = self.client.sky_patches("hosek", scheme="reinhart", mf=2, output="rgb", **SUN)
        self.assertEqual(len(reinhart["patches"]), 578)
        self.assertRefused(lambda: self.client.sky_patches("preetham", scheme="klems", **SUN),
                           400, "invalid_parameter", "scheme")

    def test_sky_matrix(self) -> None:
        # A day hourly in Paris: one Tregenza column per hour, the night ones flagged and zero,
        # a daytime one the sky vector of its instant.
        day = self.client.sky_matrix("preetham", 48.85, 2.35, "2024-06-21T00:00:00Z",
                                     "2024-06-21T23:00:00Z", output="rgb", sun="patch")
        self.assertEqual(day.matrix.shape, (146, 24, 3))
        self.assertEqual(day.time_utc[12], "2024-06-21T12:00:00Z")
        self.assertTrue(day.night[0])
        self.assertEqual(np.abs(day.matrix[:, day.night]).max(), 0.0)
        self.assertGreater(day.matrix[:, ~day.night].min(initial=1.0), -1e-30)
        noon = self.client.sky_patches("preetham", lat=48.85, lon=2.35,
                                       time="2024-06-21T12:00:00Z", output="rgb", sun="patch")
        np.testing.assert_allclose(day.matrix[:, 12],
                                   [p["value"] for p in noon["patches"]], rtol=1e-6)
        self.assertAlmostEqual(day.solid_angle_sr[1:].sum(), 2 * np.pi, places=9)
        self.assertRefused(lambda: self.client.sky_matrix(
            "preetham", 48.85, 2.35, "2024-01-01T00:00:00Z", "2024-12-31T23:00:00Z",
            scheme="reinhart", mf=2, output="rgb"), 413, "too_large", "step")

    def test_rgb_single_and_batch(self) -> None:
        one = self.client.rgb("preetham", 45, 0, **SUN)
        self.assertEqual(one.rgb.shape, (1, 3))
        self.assertEqual(one.method, "spectral")
        batch = self.client.rgb_batch("preetham", [(45, 0), (60, 90)], **SUN)
        np.testing.assert_array_equal(batch.rgb[0], one.rgb[0])
        np.testing.assert_array_equal(batch.gamut_clipped, [False, False])
        three = self.client.rgb("preetham", 45, 0, method="three", **SUN)
        self.assertEqual(three.method, "three")
        # A clear sky is blue: more blue than red (Preetham, sun at 30 degrees).
        self.assertGreater(one.rgb[0, 2], one.rgb[0, 0])

    def test_skydome_streamed_to_a_file(self) -> None:
        path = os.path.join(self.work.name, "sky.exr")
        received = []
        image = self.client.skydome(path, "preetham", size=64, chunk_bytes=4096,
                                    progress=lambda n, _total: received.append(n), **SUN)
        self.assertEqual(image.bytes_written, os.path.getsize(path))
        self.assertGreater(len(received), 1)
        self.assertEqual(received[-1], image.bytes_written)
        with open(path, "rb") as f:
            self.assertEqual(f.read(4), EXR_MAGIC)
        refused = os.path.join(self.work.name, "refused.exr")
        self.assertRefused(lambda: self.client.skydome(refused, "preetham", size=4, **SUN),
                           400, "invalid_parameter", "size")
        self.assertFalse(os.path.exists(refused) or os.path.exists(refused + ".part"))
        if not has_openimageio():
            self.skipTest("python3-openimageio is not installed: the EXR was not decoded")
        decoded = self.client.read_skydome(path)
        self.assertEqual(decoded.pixels.shape, (64, 64, 4))
        self.assertEqual(sorted(decoded.channels), ["A", "B", "G", "R"])
        # The zenith (the image centre) is answered and blue.
        centre = decoded.pixels[32, 32]
        self.assertEqual(decoded.channel("A")[32, 32], 1.0)
        self.assertGreater(centre[decoded.channels.index("B")],
                           centre[decoded.channels.index("R")])

    def test_errors_name_the_parameter(self) -> None:
        self.assertRefused(lambda: self.client.radiance("preetham", 45, 0, turbidity=99, **SUN),
                           400, "invalid_parameter", "turbidity")
        self.assertRefused(lambda: self.client.radiance("preetham", 45, 0, turbidty=3, **SUN),
                           400, "unknown_parameter", "turbidty")
        self.assertRefused(lambda: self.client.rgb("nope", 45, 0, **SUN), 404, "unknown_model",
                           "model")
        self.assertRefused(lambda: self.client.get_job(999999), 404, "unknown_job", "id")

    def test_writes_without_the_token_are_401(self) -> None:
        self.assertRefused(lambda: self.anonymous.create_job("x", "0 3 * * *", "none"), 401,
                           "unauthorized", "Authorization")
        archive = kider_archive.write_archive(os.path.join(self.work.name, "anonymous"))
        self.assertRefused(lambda: self.anonymous.upload_dataset("anonymous", archive), 401,
                           "unauthorized", "Authorization")
        self.assertNotIn("anonymous",
                         [d.name for d in self.client.list_datasets(limit=1000).items])
        # A body far above the socket buffers: the server answers 401 from the head and closes
        # while the client still sends; the client reads that answer instead of failing on the
        # broken connection (docs/http-api.md "Authorisation").
        large = os.path.join(self.work.name, "large.bin")
        with open(large, "wb") as f:
            f.truncate(32 << 20)
        sent = []
        self.assertRefused(
            lambda: self.anonymous.upload_dataset("anonymous", large,
                                                  progress=lambda n, _total: sent.append(n)),
            401, "unauthorized", "Authorization")
        self.assertLess(sent[-1], 32 << 20)

    def test_readme_examples_run_as_written(self) -> None:
        for readme in READMES:
            blocks = python_blocks(readme)
            self.assertTrue(blocks, readme)
            for code in blocks:
                code = code.replace("http://127.0.0.1:8080", self.server.url)
                code = code.replace('"clients/python"',
                                    repr(os.path.join(REPOSITORY, "clients", "python")))
                folder = tempfile.mkdtemp(dir=self.work.name)
                printed = io.StringIO()
                cwd = os.getcwd()
                os.chdir(folder)
                try:
                    with contextlib.redirect_stdout(printed):
                        exec(compile(code, readme, "exec"), {"__name__": "readme"})
                finally:
                    os.chdir(cwd)
                self.assertTrue(printed.getvalue(), readme)

    def test_data_workflow(self) -> None:
        archive = kider_archive.write_archive(os.path.join(self.work.name, "upload"))
        sent = []
        queued = self.client.upload_dataset("synthetic", archive,
                                            progress=lambda n, total: sent.append((n, total)))
        size = os.path.getsize(archive)
        self.assertEqual(sent[-1], (size, size))
        self.assertEqual((queued.dataset, queued.source), ("synthetic", "upload"))
        done = self.client.wait_for_import(queued.id, timeout_s=300)
        self.assertEqual(done.report["samples_added"], kider_archive.CAPTURE_SAMPLES)
        self.assertIn(queued.id, [i.id for i in self.client.list_imports(dataset="synthetic")
                                  .items])
        self.assertEqual(self.client.get_import(queued.id).status, "succeeded")

        names = [d.name for d in self.client.list_datasets().items]
        self.assertIn("synthetic", names)
        dataset = self.client.get_dataset("synthetic")
        self.assertEqual(dataset.capture_labels, [kider_archive.CAPTURE_LABEL])
        one = self.client.get_dataset("synthetic", capture=kider_archive.CAPTURE_LABEL)
        self.assertEqual(len(one.captures[0]["samples"]), kider_archive.CAPTURE_SAMPLES)

        # The same capture from a folder under the import root (path=).
        kider_archive.synthetic_kider.write_capture(
            os.path.join(self.server.import_root, "folder"), kider_archive.CAPTURE_LABEL)
        by_path = self.client.wait_for_import(
            self.client.import_dataset_path("from-path", "folder").id, timeout_s=300)
        self.assertEqual(by_path.source, "path")
        self.assertRefused(lambda: self.client.import_dataset_path("x", "../../etc"), 404,
                           "path_not_importable", "path")

        ticket = self.client.create_evaluation("synthetic", ["preetham"], {"turbidity": 3})
        self.assertEqual(ticket.models[0]["model"], "preetham")
        finished = self.client.wait_for_evaluation(ticket.ticket, timeout_s=300)
        self.assertEqual(len(finished.runs), 1)
        run = self.client.get_evaluation(finished.runs[0], samples=True)
        self.assertEqual((run.model, run.status, run.parameters), ("preetham", "succeeded",
                                                                   {"turbidity": 3}))
        self.assertGreater(run.rmse, 0)
        self.assertIn("samples", run.captures[0])
        listed = self.client.list_evaluations(model="preetham", dataset="synthetic")
        self.assertEqual([r.id for r in listed.items], finished.runs)
        self.assertRefused(lambda: self.client.create_evaluation("synthetic", ["bruneton"]),
                           404, "unknown_model", "models")

        queued_fit = self.client.create_fit("synthetic", "preetham", ["turbidity"],
                                            {"turbidity": [2, 6]}, grid=[9])
        self.assertEqual((queued_fit.model, queued_fit.dataset), ("preetham", "synthetic"))
        fit = self.client.wait_for_fit(queued_fit.id, timeout_s=300)
        self.assertTrue(2 <= fit.values["turbidity"] <= 6)
        self.assertLessEqual(fit.rmse_after, fit.rmse_before)
        self.assertIn("history", self.client.get_fit(fit.id, history=True).raw)
        self.assertEqual([f.id for f in self.client.list_fits().items], [fit.id])
        self.assertRefused(lambda: self.client.create_fit("synthetic", "preetham", ["alpha"]),
                           400, "invalid_parameter", "free")

        # The stored fit used by a sky request: the same answer as its values given explicitly,
        # and the answer says which fit (docs/fits.md "Using a fit").
        turbidity = fit.values["turbidity"]
        by_fit = self.client.radiance("preetham", 45, 0, sun_zenith=30, sun_azimuth=135,
                                      fit=fit.id)
        explicit = self.client.radiance("preetham", 45, 0, sun_zenith=30, sun_azimuth=135,
                                        turbidity=turbidity)
        self.assertEqual(by_fit.radiance.tolist(), explicit.radiance.tolist())
        self.assertEqual((by_fit.fit["id"], by_fit.fit["parameters"]),
                         (fit.id, {"turbidity": turbidity}))
        self.assertIsNone(explicit.fit)
        self.assertEqual(self.client.rgb("preetham", 45, 0, sun_zenith=30, sun_azimuth=135,
                                         fit="latest").fit["id"], fit.id)
        self.assertRefused(lambda: self.client.radiance("hosek", 45, 0, sun_zenith=30,
                                                        sun_azimuth=135, fit=fit.id),
                           409, "fit_model_mismatch", "fit")

        job = self.client.create_job("nightly", "0 3 * * *", "synthetic", ["preetham", "hosek"],
                                     {"turbidity": 3})
        self.assertFalse(job.paused)
        # A new job has skipped nothing (the scheduler counts occurrences skipped while the
        # previous run was still going; tests/server/scheduler).
        self.assertEqual(self.client.get_job(job.id).skipped_count, 0)
        self.assertIsNone(self.client.get_job(job.id).last_skipped)
        self.assertRefused(lambda: self.client.create_job("nightly", "0 3 * * *", "synthetic"),
                           409, "conflict", "name")
        second = self.client.create_job("weekly", "0 4 * * 1", "synthetic")
        first_page = self.client.list_jobs(limit=1)
        self.assertEqual([j.name for j in first_page.items], ["nightly"])
        self.assertIsNotNone(first_page.next_cursor)
        last_page = self.client.list_jobs(limit=1, cursor=first_page.next_cursor)
        self.assertEqual([j.name for j in last_page.items], ["weekly"])
        self.assertIsNone(last_page.next_cursor)
        self.assertTrue(self.client.pause_job(job.id).paused)
        self.assertTrue(self.client.get_job(job.id).paused)
        self.assertFalse(self.client.resume_job(job.id).paused)
        self.assertEqual(self.client.delete_job(second.id), second.id)
        self.assertRefused(lambda: self.client.get_job(second.id), 404, "unknown_job", "id")
        # A job that re-fits the dataset before each evaluation (docs/fits.md "In evaluations
        # and jobs"): the fit request as given, no fit before its first occurrence.
        refitting = self.client.create_job("refit", "0 5 * * *", "synthetic", ["preetham"],
                                           refit={"model": "preetham", "free": ["turbidity"]})
        self.assertEqual(refitting.refit, {"model": "preetham", "free": ["turbidity"]})
        self.assertIsNone(refitting.last_fit)
        self.assertRefused(lambda: self.client.create_job("bad-refit", "0 5 * * *", "synthetic",
                                                          ["preetham"],
                                                          refit={"model": "nonsense"}),
                           400, "invalid_parameter", "refit.model")
        self.assertEqual(self.client.delete_job(refitting.id), refitting.id)

        self.assertEqual(self.client.delete_dataset("from-path"), "from-path")
        self.assertRefused(lambda: self.client.get_dataset("from-path"), 404, "unknown_dataset",
                           "dataset")

    def test_503_with_retry_after_is_retried_within_bounds(self) -> None:
        holder = SkydomeHolder(self.server.port)
        try:
            self.assertIn(" 200 ", holder.status_line + " ")
            path = os.path.join(self.work.name, "retried.exr")
            # Bounded to one attempt: the refusal is raised with its Retry-After.
            once = Client(self.server.url, retry=RetryPolicy(max_attempts=1))
            error = self.assertRefused(
                lambda: once.skydome(path, "preetham", size=256, channels="spectral", **SUN),
                503, "busy", "answer_memory")
            self.assertEqual((error.retry_after_s, error.attempts), (1.0, 1))
            # Bounded by the total wait: a Retry-After of 1 s does not fit in 0.5 s.
            short = Client(self.server.url, retry=RetryPolicy(max_total_wait_s=0.5))
            self.assertRefused(
                lambda: short.skydome(path, "preetham", size=256, channels="spectral", **SUN),
                503, "busy", "answer_memory")
            # Retried: the first refusal releases the held image; a later attempt succeeds.
            notices = []

            def on_retry(notice: RetryNotice) -> None:
                notices.append(notice)
                holder.close()

            patient = Client(self.server.url, timeout=120,
                             retry=RetryPolicy(max_attempts=30, max_total_wait_s=60,
                                               on_retry=on_retry))
            image = patient.skydome(path, "preetham", size=256, channels="spectral", **SUN)
            self.assertGreater(image.bytes_written, 256 * 256 * 40 * 4)
            self.assertGreaterEqual(len(notices), 1)
            self.assertEqual((notices[0].attempt, notices[0].status, notices[0].code,
                              notices[0].wait_s), (1, 503, "busy", 1.0))
        finally:
            holder.close()


class ClientAgainstQueryReplica(unittest.TestCase):
    """A query replica (serve --role query) has no database: its data endpoints answer 404
    no_database, which the client raises at once. It lets one client start
    one table build per 4 s (--build-rate, docs/tables-and-memory.md): a second one is 429
    too_many_builds with Retry-After, which the client waits for."""

    @classmethod
    def setUpClass(cls) -> None:
        cls.server = ServeProcess(role="query", models="preetham",
                                  extra=["--build-rate", "1", "--build-rate-window-s", "4"])

    def test_429_with_retry_after_is_retried(self) -> None:
        # Each turbidity other than the default is a new configuration: a table build.
        self.assertEqual(Client(self.server.url).radiance("preetham", 45, 0, turbidity=3,
                                                          **SUN).radiance.shape[0], 1)
        once = Client(self.server.url, retry=RetryPolicy(max_attempts=1))
        with self.assertRaises(ClearskyError) as caught:
            once.radiance("preetham", 45, 0, turbidity=4, **SUN)
        error = caught.exception
        self.assertEqual((error.status, error.code, error.parameter),
                         (429, "too_many_builds", "build_rate"))
        self.assertIsNotNone(error.retry_after_s)
        notices = []
        patient = Client(self.server.url, retry=RetryPolicy(max_attempts=10,
                                                            max_total_wait_s=60,
                                                            on_retry=notices.append))
        answer = patient.radiance("preetham", 45, 0, turbidity=4, **SUN)
        self.assertEqual(answer.radiance.shape[0], 1)
        self.assertGreaterEqual(len(notices), 1)
        self.assertEqual((notices[0].status, notices[0].code), (429, "too_many_builds"))

    @classmethod
    def tearDownClass(cls) -> None:
        cls.server.stop()

    def test_no_database_is_not_retried(self) -> None:
        notices = []
        client = Client(self.server.url, token=TOKEN,
                        retry=RetryPolicy(on_retry=notices.append))
        for call in (client.list_datasets, lambda: client.create_job("j", "0 3 * * *", "d")):
            with self.assertRaises(ClearskyError) as caught:
                call()
            error = caught.exception
            self.assertEqual((error.status, error.code, error.parameter), (404, "no_database",
                                                                           "role"))
            self.assertEqual((error.retry_after_s, error.attempts), (None, 1))
        self.assertEqual(notices, [])
        self.assertEqual(client.rgb("preetham", 45, 0, **SUN).rgb.shape, (1, 3))


if __name__ == "__main__":
    unittest.main()
