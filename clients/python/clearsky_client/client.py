"""The client of the clearsky HTTP API v1: one method per operation of the route table
(docs/http-api.md "The route table"), typed answers, one error type, bounded retries
(docs/clients.md)."""

from __future__ import annotations

import io
import os
import time as time_module
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, TypeVar, Union
from urllib.parse import quote

from .data_results import (AerosolInversion, Dataset, DatasetSummary, Evaluation, EvaluationSummary,
                           EvaluationTicket, Fit, Import, Job, Page, next_cursor_of)
from .errors import ClearskyError
from .exr_image import SkydomeImage, read_skydome
from .retry import RetryPolicy
from .sky_query import (FitReference, Number, ParameterValue, Time, View, Wavelengths,
                        as_query, format_time, format_value, sky_parameters, views_body)
from .sky_results import (Irradiance, IrradianceSeries, ModelInfo, Radiance, Rgb, SkydomeFile,
                          SkyMatrix, Sun)
from .transport import Answer, Transport
from .upload_progress import Progress, ProgressFile

Models = Union[str, Sequence[str]]
T = TypeVar("T")
Polled = TypeVar("Polled", Import, EvaluationTicket)


class Client:
    """A clearsky server at ``base_url``.

    token: the bearer token of the writes (uploads, evaluations, jobs, deletions); reads need
    none. timeout_s: the socket timeout of each request, s (a skydome is read in chunks, each
    within it). retry: the bounds of the retries of 503 and 429 answers that carry Retry-After.

    The client keeps no connection and no other state between requests: one Client may be used
    from several threads.

    Example:
        >>> from clearsky_client import Client
        >>> client = Client("http://127.0.0.1:8080")
        >>> sky = client.radiance("preetham", 45, 0, sun_zenith=30, sun_azimuth=135,
        ...                       wavelengths=[450, 550, 650])
        >>> sky.wavelengths_nm, sky.radiance[0]
        (array([450., 550., 650.]), array([0.16657478, 0.07732173, 0.03455196]))
    """

    def __init__(self, base_url: str, token: Optional[str] = None, timeout: float = 60.0,
                 retry: Optional[RetryPolicy] = None) -> None:
        self._transport = Transport(base_url, token, timeout, retry or RetryPolicy())

    # --- service -----------------------------------------------------------------------------

    def health(self) -> Dict[str, Any]:
        """GET /healthz: {"status": "ok"} while the process serves."""
        return self._get("/healthz").json()

    def readiness(self) -> Dict[str, Any]:
        """GET /readyz: each model's table state. A server still building its tables answers
        503 with Retry-After, which the retry policy waits for."""
        return self._get("/readyz").json()

    def metrics(self) -> str:
        """GET /metrics: the Prometheus text."""
        return self._get("/metrics").body.decode("utf-8")

    def openapi(self) -> Dict[str, Any]:
        """GET /openapi.json: the OpenAPI 3.0 document of the API."""
        return self._get("/openapi.json").json()

    def models(self) -> List[ModelInfo]:
        """GET /v1/models: the served models, their parameters and table states.

        Example:
            >>> [m.id for m in client.models()]
            ['preetham', 'hosek']
        """
        return [ModelInfo.from_json(m) for m in self._get("/v1/models").json()["models"]]

    # --- the sky -----------------------------------------------------------------------------

    def sun(self, lat: Union[Number, str], lon: Union[Number, str], time: Optional[Time] = None,
            **options: ParameterValue) -> Sun:
        """GET /v1/sun: the sun at a place and time (NREL SPA); time absent: now. options:
        altitude, pressure, temperature, delta_t, delta_ut1, refraction.

        Example:
            >>> client.sun(42.444, -76.5, "2013-05-27T11:45:00-04:00").zenith_deg
            26.652540765126872
        """
        query = {"lat": lat, "lon": lon, **options}
        if time is not None:
            query["time"] = format_time(time)
        return Sun.from_json(self._get("/v1/sun", query).json())

    def radiance(self, model: str, view_zenith: Number, view_azimuth: Number, *,
                 sun_zenith: Optional[Number] = None, sun_azimuth: Optional[Number] = None,
                 lat: Optional[Union[Number, str]] = None,
                 lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                 wavelengths: Optional[Wavelengths] = None,
                 quality: Optional[str] = None,
                 fit: Optional[FitReference] = None,
                 **parameters: ParameterValue) -> Radiance:
        """GET /v1/radiance: the spectral radiance of one view, W/(m2.sr.nm).

        The sun is given (sun_zenith, sun_azimuth, degrees) or computed (lat, lon, time).
        wavelengths: nm, a list or a text ("400:700:10"); absent, the model's default grid.
        parameters: the model's and the atmosphere's (turbidity=3, albedo=0.1, altitude=...).
        fit: a stored fit of the model (its id, "latest" or "latest:DATASET") whose fitted values
        are used instead (docs/fits.md "Using a fit"; the answer's ``fit`` says which).

        Example:
            >>> sky = client.radiance("hosek", 45, 0, lat=42.444, lon=-76.5,
            ...                       time="2013-05-27T11:45:00-04:00", turbidity=3)
            >>> sky.radiance.shape
            (1, 40)
        """
        query = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time, wavelengths,
                               parameters, quality, fit)
        query.update(view_zenith=view_zenith, view_azimuth=view_azimuth)
        return Radiance.from_json(self._get("/v1/radiance", query).json())

    def radiance_batch(self, model: str, views: Sequence[View], *,
                       sun_zenith: Optional[Number] = None, sun_azimuth: Optional[Number] = None,
                       lat: Optional[Union[Number, str]] = None,
                       lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                       wavelengths: Optional[Wavelengths] = None,
                       quality: Optional[str] = None,
                       fit: Optional[FitReference] = None,
                       **parameters: ParameterValue) -> Radiance:
        """POST /v1/radiance: many views at once, (zenith, azimuth) in degrees; one row of the
        answer per view, in the order given. Otherwise as ``radiance``.

        Example:
            >>> sky = client.radiance_batch("preetham", [(45, 0), (60, 90)], sun_zenith=30,
            ...                             sun_azimuth=135, wavelengths="450,550,650")
            >>> sky.radiance.shape
            (2, 3)
        """
        body: Dict[str, Any] = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time,
                                              wavelengths, parameters, quality, fit)
        body["views"] = views_body(views)
        return Radiance.from_json(self._transport.request("POST", "/v1/radiance",
                                                          json_body=body).json())

    def irradiance(self, model: str, *, tilt: Optional[Number] = None,
                   surface_azimuth: Optional[Number] = None, component: Optional[str] = None,
                   spectral: bool = False, sun_zenith: Optional[Number] = None,
                   sun_azimuth: Optional[Number] = None,
                   lat: Optional[Union[Number, str]] = None,
                   lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                   ground_reflection: Optional[str] = None,
                   ground_albedo: Optional[Number] = None,
                   quality: Optional[str] = None,
                   fit: Optional[FitReference] = None,
                   precipitable_water_cm: Optional[Number] = None,
                   ozone_atm_cm: Optional[Number] = None,
                   **parameters: ParameterValue) -> Irradiance:
        """GET /v1/irradiance: direct, diffuse (sky), ground-reflected and global irradiance
        (W/m2) and illuminance (lx) on a plane (tilt from horizontal and the azimuth of its
        normal, degrees; horizontal by default). component: all, direct, diffuse,
        ground_diffuse or global; spectral=True adds the spectra. ground_reflection: include
        (default) or exclude; ground_albedo: the isotropic ground's albedo (default: the
        model's ground albedo spectrum).
        Each component's broadband_irradiance_w_m2 (300..4000 nm) uses the absorbers
        precipitable_water_cm and ozone_atm_cm (defaults 1.42 cm and 0.34 atm-cm).

        Example:
            >>> client.irradiance("preetham", sun_zenith=30, sun_azimuth=135,
            ...                   tilt=30, surface_azimuth=180).global_.irradiance_w_m2
            659.987393848494
        """
        query = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time, None, parameters,
                               quality, fit)
        for name, value in (("tilt", tilt), ("surface_azimuth", surface_azimuth),
                            ("component", component), ("ground_reflection", ground_reflection),
                            ("ground_albedo", ground_albedo),
                            ("precipitable_water_cm", precipitable_water_cm),
                            ("ozone_atm_cm", ozone_atm_cm)):
            if value is not None:
                query[name] = value
        if spectral:
            query["spectral"] = True
        return Irradiance.from_json(self._get("/v1/irradiance", query).json())

    def irradiance_series(self, model: str, lat: Union[Number, str], lon: Union[Number, str],
                          start: Time, end: Time, *, step: Optional[str] = None,
                          tz: Optional[str] = None,
                          planes: Optional[Sequence[Sequence[Number]]] = None,
                          ground_reflection: Optional[str] = None,
                          ground_albedo: Optional[Number] = None,
                          fit: Optional[FitReference] = None,
                          **parameters: ParameterValue) -> IrradianceSeries:
        """GET /v1/irradiance/series: the irradiance of a place from start to end (both ISO
        8601 with an offset, aware datetimes, or local times in ``tz``, an IANA zone) every
        ``step`` (ISO 8601: "PT1H", "PT10M"), on the horizontal and on ``planes`` ((tilt,
        azimuth) pairs, degrees), one numpy array per pvlib column (docs/building-energy.md
        "Irradiance time series"): ``ghi``, ``dni``, ``dhi``, ``poa_global_30_180``, ...

        Example:
            >>> year = client.irradiance_series("preetham", 48.85, 2.35, "2024-01-01T00:00:00",
            ...                                 "2024-12-31T23:00:00", tz="Europe/Paris",
            ...                                 planes=[(30, 180)])
            >>> year["poa_global_30_180"].shape
            (8784,)
        """
        query: Dict[str, ParameterValue] = {"model": model, "lat": lat, "lon": lon,
                                            "start": format_time(start), "end": format_time(end)}
        if planes is not None:
            query["planes"] = ",".join(f"{format_value(tilt)}:{format_value(azimuth)}"
                                       for tilt, azimuth in planes)
        for name, value in (("step", step), ("tz", tz), ("ground_reflection", ground_reflection),
                            ("ground_albedo", ground_albedo), ("fit", fit)):
            if value is not None:
                query[name] = value
        query.update(parameters)
        return IrradianceSeries.from_json(self._get("/v1/irradiance/series", query).json())

    def rgb(self, model: str, view_zenith: Number, view_azimuth: Number, *,
            method: Optional[str] = None, sun_zenith: Optional[Number] = None,
            sun_azimuth: Optional[Number] = None, lat: Optional[Union[Number, str]] = None,
            lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
            quality: Optional[str] = None,
            fit: Optional[FitReference] = None,
            **parameters: ParameterValue) -> Rgb:
        """GET /v1/rgb: linear sRGB (D65, radiometric) and luminance of one view; method
        ``spectral`` (default, CIE 1931 over the 40 bins) or ``three`` (the paper's
        3-wavelength method).

        Example:
            >>> client.rgb("preetham", 45, 0, sun_zenith=30, sun_azimuth=135).luminance_cd_m2
            array([5404.27240365])
        """
        query = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time, None, parameters,
                               quality, fit)
        query.update(view_zenith=view_zenith, view_azimuth=view_azimuth)
        if method is not None:
            query["method"] = method
        return Rgb.from_json(self._get("/v1/rgb", query).json())

    def rgb_batch(self, model: str, views: Sequence[View], *, method: Optional[str] = None,
                  sun_zenith: Optional[Number] = None, sun_azimuth: Optional[Number] = None,
                  lat: Optional[Union[Number, str]] = None,
                  lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                  quality: Optional[str] = None,
                  fit: Optional[FitReference] = None,
                  **parameters: ParameterValue) -> Rgb:
        """POST /v1/rgb: ``rgb`` for many views, one row per view in the order given."""
        body: Dict[str, Any] = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time,
                                              None, parameters, quality, fit)
        if method is not None:
            body["method"] = method
        body["views"] = views_body(views)
        return Rgb.from_json(self._transport.request("POST", "/v1/rgb", json_body=body).json())

    def skydome(self, path: str, model: str, *, projection: Optional[str] = None,
                size: Optional[int] = None, channels: Optional[str] = None,
                pixel_type: Optional[str] = None, method: Optional[str] = None,
                wavelengths: Optional[Wavelengths] = None, sun_zenith: Optional[Number] = None,
                sun_azimuth: Optional[Number] = None, lat: Optional[Union[Number, str]] = None,
                lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                chunk_bytes: int = 1 << 20, progress: Optional[Progress] = None,
                quality: Optional[str] = None,
                fit: Optional[FitReference] = None,
                **parameters: ParameterValue) -> SkydomeFile:
        """GET /v1/skydome streamed into the file ``path`` (an OpenEXR image) chunk by chunk,
        never whole in memory. progress(bytes_received, 0) after each chunk (the length of a
        streamed image is not known in advance). A refused request leaves no file.

        projection: fisheye, latlong or cubemap; size: width in pixels; channels: rgb,
        luminance or spectral (with wavelengths); pixel_type: half or float.

        Example:
            >>> client.skydome("sky.exr", "preetham", sun_zenith=30, sun_azimuth=135, size=64)
            SkydomeFile(path='sky.exr', bytes_written=...)
        """
        query = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time, wavelengths,
                               parameters, quality, fit)
        for name, value in (("projection", projection), ("size", size),
                            ("channels", channels), ("pixel_type", pixel_type),
                            ("method", method)):
            if value is not None:
                query[name] = value
        partial = path + ".part"
        written = 0

        with open(partial, "wb") as out:
            def sink(chunk: bytes) -> None:
                nonlocal written
                out.write(chunk)
                written += len(chunk)
                if progress is not None:
                    progress(written, 0)

            try:
                self._transport.request("GET", "/v1/skydome", as_query(query), sink=sink,
                                        chunk_bytes=chunk_bytes)
            except BaseException:
                out.close()
                os.unlink(partial)
                raise
        os.replace(partial, path)
        return SkydomeFile(path, written)

    def read_skydome(self, path: str) -> SkydomeImage:
        """Decodes a skydome file into numpy arrays (needs Debian's python3-openimageio;
        exr_image.read_skydome)."""
        return read_skydome(path)

    def sky_patches(self, model: str, *, scheme: Optional[str] = None, mf: Optional[int] = None,
                    sun: Optional[str] = None, output: Optional[str] = None,
                    ground_reflectance: Optional[Number] = None,
                    wavelengths: Optional[Wavelengths] = None,
                    sun_zenith: Optional[Number] = None, sun_azimuth: Optional[Number] = None,
                    lat: Optional[Union[Number, str]] = None,
                    lon: Optional[Union[Number, str]] = None, time: Optional[Time] = None,
                    quality: Optional[str] = None,
                    fit: Optional[FitReference] = None,
                    **parameters: ParameterValue) -> Dict[str, Any]:
        """GET /v1/skypatches: the sky vector of Radiance's daylight-coefficient tools
        (docs/building-energy.md), the JSON answer as a dict: ``patches`` in Radiance's order
        (patch 0 the ground), each with its centre, solid angle (sr) and values, and the sun
        when ``sun="separate"`` (the default). scheme: tregenza or reinhart (with mf 1..6);
        output: spectral, rgb (Radiance's) or luminance.

        Example:
            >>> len(client.sky_patches("preetham", sun_zenith=30, sun_azimuth=135,
            ...                        output="luminance")["patches"])
            146
        """
        query = sky_parameters(model, sun_zenith, sun_azimuth, lat, lon, time, wavelengths,
                               parameters, quality, fit)
        for name, value in (("scheme", scheme), ("mf", mf), ("sun", sun), ("output", output),
                            ("ground_reflectance", ground_reflectance)):
            if value is not None:
                query[name] = value
        return self._get("/v1/skypatches", query).json()

    def sky_matrix(self, model: str, lat: Union[Number, str], lon: Union[Number, str],
                   start: Time, end: Time, *, step: Optional[str] = None,
                   tz: Optional[str] = None, scheme: Optional[str] = None,
                   mf: Optional[int] = None, sun: Optional[str] = None,
                   output: Optional[str] = None, ground_reflectance: Optional[Number] = None,
                   **parameters: ParameterValue) -> SkyMatrix:
        """GET /v1/skypatches with start: a sky matrix for daylight coefficients
        (docs/building-energy.md "Sky matrices"), one sky vector per step from start to end
        (as irradiance_series), in Radiance's patch order: ``matrix`` is a numpy array of
        patches x steps (x components for rgb and spectral), ``night`` flags the night
        columns (zeros). output: rgb (Radiance's), luminance or spectral; sun: patch (the sun
        in its patch, the three-phase convention) or separate (the sky alone, the suns in
        ``raw["times"]``).

        Example:
            >>> day = client.sky_matrix("preetham", 48.85, 2.35, "2024-06-21T00:00:00Z",
            ...                         "2024-06-21T23:00:00Z", output="rgb", sun="patch")
            >>> day.matrix.shape
            (146, 24, 3)
        """
        query: Dict[str, ParameterValue] = {"model": model, "lat": lat, "lon": lon,
                                            "start": format_time(start), "end": format_time(end)}
        for name, value in (("step", step), ("tz", tz), ("scheme", scheme), ("mf", mf),
                            ("sun", sun), ("output", output),
                            ("ground_reflectance", ground_reflectance)):
            if value is not None:
                query[name] = value
        query.update(parameters)
        return SkyMatrix.from_json(self._get("/v1/skypatches", query).json())

    # --- datasets and imports ------------------------------------------------------------------

    def list_datasets(self, limit: Optional[int] = None,
                      cursor: Optional[str] = None) -> Page[DatasetSummary]:
        """GET /v1/datasets: one page, by name."""
        answer = self._get("/v1/datasets", {"limit": limit, "cursor": cursor})
        return _page(answer, DatasetSummary.from_json)

    def get_dataset(self, name: str, samples: bool = False,
                    capture: Optional[str] = None) -> Dataset:
        """GET /v1/datasets/{name}: its captures; samples=True adds each capture's samples,
        capture=LABEL answers one capture with its spectra."""
        query: Dict[str, Any] = {"capture": capture}
        if samples:
            query["samples"] = True
        return Dataset.from_json(self._get("/v1/datasets/" + _segment(name), query).json())

    def delete_dataset(self, name: str) -> str:
        """DELETE /v1/datasets/{name} (token): the dataset, its captures and its runs."""
        answer = self._transport.request("DELETE", "/v1/datasets/" + _segment(name),
                                         authorize=True)
        return answer.json()["deleted"]

    def upload_dataset(self, name: str, archive_path: str, format: Optional[str] = None,
                       progress: Optional[Progress] = None) -> Import:
        """POST /v1/datasets (token): uploads an archive (.7z, zip, tar) of measured captures
        into the dataset ``name`` (created when absent), streamed from the file;
        progress(bytes_sent, bytes_total) after each block. Answers the queued import: follow it
        with ``wait_for_import``.

        Example:
            >>> queued = client.upload_dataset("kider", "captures.tar",
            ...                                progress=lambda sent, total: print(sent, total))
            >>> client.wait_for_import(queued.id).report["samples_added"]
            81
        """
        def body() -> Any:
            stream = ProgressFile(archive_path, progress)
            return stream, stream.total_bytes

        answer = self._transport.request("POST", "/v1/datasets",
                                         as_query({"name": name, "format": format}), body=body,
                                         content_type="application/octet-stream",
                                         authorize=True)
        return Import.from_json(answer.json())

    def import_dataset_path(self, name: str, path: str, format: Optional[str] = None) -> Import:
        """POST /v1/datasets?path= (token): imports a file or folder the server reads under its
        import roots (docs/data-api.md "Server-side paths")."""
        answer = self._transport.request("POST", "/v1/datasets",
                                         as_query({"name": name, "format": format, "path": path}),
                                         authorize=True)
        return Import.from_json(answer.json())

    def list_imports(self, status: Optional[str] = None, dataset: Optional[str] = None,
                     limit: Optional[int] = None, cursor: Optional[str] = None) -> Page[Import]:
        """GET /v1/imports: newest first, filtered by status and dataset."""
        answer = self._get("/v1/imports", {"status": status, "dataset": dataset, "limit": limit,
                                           "cursor": cursor})
        return _page(answer, Import.from_json)

    def get_import(self, import_id: int) -> Import:
        """GET /v1/imports/{id}."""
        return Import.from_json(self._get(f"/v1/imports/{int(import_id)}").json())

    def wait_for_import(self, import_id: int, poll_s: float = 0.25,
                        timeout_s: float = 600.0) -> Import:
        """Polls an import until it has succeeded and answers it; raises ClearskyError with the
        import's error code when it failed, and with code ``timeout`` after timeout_s."""
        final = _poll(lambda: self.get_import(import_id), poll_s, timeout_s,
                      f"import {import_id}")
        if final.status != "succeeded":
            error = final.error or {}
            raise ClearskyError(None, str(error.get("code", final.status)),
                                f"import {import_id} {final.status}: {error.get('message', '')}",
                                body=final.raw)
        return final

    # --- evaluations ---------------------------------------------------------------------------

    def create_evaluation(self, dataset: str, models: Models = "all",
                          parameters: Optional[Mapping[str, ParameterValue]] = None
                          ) -> EvaluationTicket:
        """POST /v1/evaluations (token): evaluates the models against every capture of the
        dataset; answers the queued ticket (follow it with ``wait_for_evaluation``).

        Example:
            >>> ticket = client.create_evaluation("kider", ["preetham"], {"turbidity": 3})
            >>> run = client.get_evaluation(client.wait_for_evaluation(ticket.ticket).runs[0])
            >>> run.model, run.status
            ('preetham', 'succeeded')
        """
        body = {"dataset": dataset, "models": models if isinstance(models, str) else list(models),
                "parameters": dict(parameters or {})}
        answer = self._transport.request("POST", "/v1/evaluations", json_body=body,
                                         authorize=True)
        return EvaluationTicket.from_json(answer.json())

    def get_evaluation_ticket(self, ticket: int) -> EvaluationTicket:
        """GET /v1/evaluations/tickets/{ticket}."""
        return EvaluationTicket.from_json(
            self._get(f"/v1/evaluations/tickets/{int(ticket)}").json())

    def wait_for_evaluation(self, ticket: int, poll_s: float = 0.25,
                            timeout_s: float = 600.0) -> EvaluationTicket:
        """Polls a ticket until every model's run succeeded and answers it; raises
        ClearskyError (code ``evaluation_failed`` or ``evaluation_interrupted``) when it failed
        or was interrupted, and with code ``timeout`` after timeout_s."""
        final = _poll(lambda: self.get_evaluation_ticket(ticket), poll_s, timeout_s,
                      f"evaluation ticket {ticket}")
        if final.status != "succeeded":
            raise ClearskyError(None, "evaluation_" + final.status,
                                f"evaluation ticket {ticket} {final.status}: {final.error}",
                                body=final.raw)
        return final

    def list_evaluations(self, model: Optional[str] = None, dataset: Optional[str] = None,
                         status: Optional[str] = None, since: Optional[Time] = None,
                         until: Optional[Time] = None, job: Optional[int] = None,
                         limit: Optional[int] = None,
                         cursor: Optional[str] = None) -> Page[EvaluationSummary]:
        """GET /v1/evaluations: runs newest first, filtered (since and until on the start
        time)."""
        query = {"model": model, "dataset": dataset, "status": status,
                 "since": None if since is None else format_time(since),
                 "until": None if until is None else format_time(until), "job": job,
                 "limit": limit, "cursor": cursor}
        return _page(self._get("/v1/evaluations", query), EvaluationSummary.from_json)

    def get_evaluation(self, run_id: int, samples: Union[bool, str] = False,
                       capture: Optional[str] = None) -> Evaluation:
        """GET /v1/evaluations/{id}: the run with its per-capture RMSE; samples=True (or
        "spectra") adds each capture's samples, capture=LABEL one capture."""
        query: Dict[str, Any] = {"capture": capture}
        if samples:
            query["samples"] = samples
        return Evaluation.from_json(self._get(f"/v1/evaluations/{int(run_id)}", query).json())

    # --- jobs ----------------------------------------------------------------------------------

    def create_job(self, name: str, schedule: str, dataset: str, models: Models = "all",
                   parameters: Optional[Mapping[str, ParameterValue]] = None,
                   refit: Optional[Mapping[str, Any]] = None) -> Job:
        """POST /v1/jobs (token): evaluates the models against the dataset on a 5-field UTC cron
        schedule ("0 3 * * *"); 409 when the name is taken. ``refit``: the body of POST /v1/fits
        without dataset (docs/fits.md "In evaluations and jobs"): each occurrence first fits
        the dataset, then evaluates with the new fit (``Job.last_fit``)."""
        body: Dict[str, Any] = {"name": name, "schedule": schedule, "dataset": dataset,
                                "models": models if isinstance(models, str) else list(models),
                                "parameters": dict(parameters or {})}
        if refit is not None:
            body["refit"] = dict(refit)
        return Job.from_json(self._transport.request("POST", "/v1/jobs", json_body=body,
                                                     authorize=True).json())

    def create_fit(self, dataset: str, model: str, free: Optional[Sequence[str]] = None,
                   bounds: Optional[Mapping[str, Sequence[float]]] = None,
                   **options: Any) -> Fit:
        """POST /v1/fits (token): fits the model's free parameters to the dataset (docs/fits.md);
        options are the other members of the body (grid, captures, parameters, search_options,
        per_capture, cross_validate, max_evaluations, fold_evaluations). Answers the queued fit
        (follow it with ``wait_for_fit``).

        Example:
            >>> fit = client.create_fit("kider", "preetham", ["turbidity"], {"turbidity": [2, 6]})
            >>> client.wait_for_fit(fit.id).values
            {'turbidity': 2.348...}
        """
        body: Dict[str, Any] = {"dataset": dataset, "model": model, **options}
        if free is not None:
            body["free"] = list(free)
        if bounds is not None:
            body["bounds"] = {name: list(range_) for name, range_ in bounds.items()}
        answer = self._transport.request("POST", "/v1/fits", json_body=body, authorize=True)
        return Fit.from_json(answer.json())

    def get_fit(self, fit_id: int, history: bool = False) -> Fit:
        """GET /v1/fits/{id}; history adds every point evaluated (in ``raw``)."""
        return Fit.from_json(self._get(f"/v1/fits/{int(fit_id)}",
                                       {"history": "true" if history else None}).json())

    def list_fits(self, limit: Optional[int] = None, cursor: Optional[str] = None) -> Page[Fit]:
        """GET /v1/fits: newest first."""
        return _page(self._get("/v1/fits", {"limit": limit, "cursor": cursor}), Fit.from_json)

    def wait_for_fit(self, fit_id: int, poll_s: float = 0.25, timeout_s: float = 600.0) -> Fit:
        """Polls a fit until it has succeeded and answers it; raises ClearskyError (code
        ``fit_failed`` or ``fit_interrupted``) when it did not, and with code ``timeout`` after
        timeout_s."""
        final = _poll(lambda: self.get_fit(fit_id), poll_s, timeout_s, f"fit {fit_id}")
        if final.status != "succeeded":
            raise ClearskyError(None, "fit_" + final.status,
                                f"fit {fit_id} {final.status}: {final.error}", body=final.raw)
        return final

    def upload_aerosols(self, name: str, path: str) -> AerosolInversion:
        """POST /v1/aerosols (token): stores an AERONET phase-function inversion (.pfn) read from
        ``path`` under the label ``name``; the server reads it whole first (400 naming ``body``
        with the line and column when it refuses it). Its ``id`` is what ``aerosols=`` selects.

        Example:
            >>> stored = client.upload_aerosols("egbert", "130527_130527_Egbert.pfn")
            >>> stored.retrieval_count
            5
        """
        with open(path, "rb") as source:
            content = source.read()

        def body() -> Any:
            return io.BytesIO(content), len(content)

        answer = self._transport.request("POST", "/v1/aerosols", as_query({"name": name}),
                                         body=body, content_type="text/plain", authorize=True)
        return AerosolInversion.from_json(answer.json())

    def list_aerosols(self, limit: Optional[int] = None,
                      cursor: Optional[str] = None) -> Page[AerosolInversion]:
        """GET /v1/aerosols: newest first, without their retrievals."""
        return _page(self._get("/v1/aerosols", {"limit": limit, "cursor": cursor}),
                     AerosolInversion.from_json)

    def get_aerosols(self, inversion_id: int) -> AerosolInversion:
        """GET /v1/aerosols/{id}: with every retrieval's time and optical depth."""
        return AerosolInversion.from_json(self._get(f"/v1/aerosols/{int(inversion_id)}").json())

    def list_jobs(self, limit: Optional[int] = None, cursor: Optional[str] = None) -> Page[Job]:
        """GET /v1/jobs: by name."""
        return _page(self._get("/v1/jobs", {"limit": limit, "cursor": cursor}), Job.from_json)

    def get_job(self, job_id: int) -> Job:
        """GET /v1/jobs/{id}: the job, its next run and the newest run of each model."""
        return Job.from_json(self._get(f"/v1/jobs/{int(job_id)}").json())

    def pause_job(self, job_id: int) -> Job:
        """POST /v1/jobs/{id}/pause (token)."""
        return Job.from_json(self._transport.request("POST", f"/v1/jobs/{int(job_id)}/pause",
                                                     authorize=True).json())

    def resume_job(self, job_id: int) -> Job:
        """POST /v1/jobs/{id}/resume (token): the next run is computed from now."""
        return Job.from_json(self._transport.request("POST", f"/v1/jobs/{int(job_id)}/resume",
                                                     authorize=True).json())

    def delete_job(self, job_id: int) -> int:
        """DELETE /v1/jobs/{id} (token); its runs stay."""
        return self._transport.request("DELETE", f"/v1/jobs/{int(job_id)}",
                                       authorize=True).json()["deleted"]

    # --- helpers -------------------------------------------------------------------------------

    def _get(self, path: str, query: Optional[Mapping[str, Any]] = None) -> Answer:
        return self._transport.request("GET", path, as_query(query or {}))


def _segment(name: str) -> str:
    return quote(name, safe="")


def _page(answer: Answer, parse: Callable[[Dict[str, Any]], T]) -> Page[T]:
    """One page of a list answer: its items parsed, and the next page's cursor."""
    return Page([parse(item) for item in answer.json()], next_cursor_of(answer.headers.get("link")))


def _poll(read: Callable[[], Polled], poll_s: float, timeout_s: float, what: str) -> Polled:
    """Reads an import or ticket until it is done, or raises ClearskyError ``timeout``."""
    deadline = time_module.monotonic() + timeout_s
    while True:
        current = read()
        if current.done:
            return current
        if time_module.monotonic() > deadline:
            raise ClearskyError(None, "timeout",
                                f"{what} still {current.status} after {timeout_s:g} s",
                                body=current.raw)
        time_module.sleep(poll_s)
