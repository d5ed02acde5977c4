"""Typed answers of the data endpoints: datasets, imports, evaluations, tickets, fits, aerosol
inversions and jobs (docs/data-api.md; the schemas DatasetSummary, Dataset, Import,
EvaluationTicket, EvaluationSummary, Evaluation, Fit, AerosolInversion and Job of /openapi.json),
and a page of a list.

Times are the server's ISO 8601 texts. Every answer keeps its whole JSON in ``raw``: the
captures of a dataset and of an evaluation, with their samples, are read from there."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, Generic, List, Optional, TypeVar, Union
from urllib.parse import parse_qs, urlsplit

T = TypeVar("T")


@dataclass(frozen=True)
class Page(Generic[T]):
    """One page of a list (docs/data-api.md "Pagination"): its items, and the cursor of the next
    page (from the answer's Link header; None on the last page)."""

    items: List[T]
    next_cursor: Optional[str]


def next_cursor_of(link: Optional[str]) -> Optional[str]:
    """The cursor of a Link header's rel="next" target (RFC 8288), or None."""
    if not link:
        return None
    for part in link.split(","):
        if 'rel="next"' not in part and "rel=next" not in part:
            continue
        target = part.split(";")[0].strip().lstrip("<").rstrip(">")
        cursor = parse_qs(urlsplit(target).query).get("cursor")
        if cursor:
            return cursor[0]
    return None


@dataclass(frozen=True)
class DatasetSummary:
    """A dataset in GET /v1/datasets."""

    name: str
    format: str
    created: str
    captures: int
    samples: int

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "DatasetSummary":
        return cls(j["name"], j["format"], j["created"], j["captures"], j["samples"])


@dataclass(frozen=True)
class Dataset:
    """GET /v1/datasets/{name}: the dataset with its captures (as the server sent them)."""

    name: str
    format: str
    created: str
    captures: List[Dict[str, Any]]
    raw: Dict[str, Any] = field(repr=False)

    @property
    def capture_labels(self) -> List[str]:
        return [c["label"] for c in self.captures]

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Dataset":
        return cls(j["name"], j["format"], j["created"], list(j["captures"]), j)


@dataclass(frozen=True)
class Import:
    """An import (POST /v1/datasets, GET /v1/imports/{id}): status ``queued``, ``running``,
    ``succeeded`` (with ``report``) or ``failed`` (with ``error``: {"code", "message"})."""

    id: int
    dataset: str
    format: str
    source: str
    status: str
    progress: Optional[Dict[str, Any]]
    report: Optional[Dict[str, Any]]
    error: Optional[Dict[str, Any]]
    raw: Dict[str, Any] = field(repr=False)

    @property
    def done(self) -> bool:
        return self.status in ("succeeded", "failed")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Import":
        return cls(j["id"], j["dataset"], j["format"], j["source"], j["status"],
                   j.get("progress"), j.get("report"), j.get("error"), j)


@dataclass(frozen=True)
class EvaluationTicket:
    """POST /v1/evaluations and GET /v1/evaluations/tickets/{ticket}: status ``queued``,
    ``running``, ``succeeded``, ``failed`` or ``interrupted``; ``runs`` the ids of the runs
    started; ``models`` one entry per requested model (docs/data-api.md "Evaluation
    tickets")."""

    ticket: int
    dataset: str
    status: str
    runs: List[int]
    models: List[Dict[str, Any]]
    error: Optional[str]
    raw: Dict[str, Any] = field(repr=False)

    @property
    def done(self) -> bool:
        return self.status in ("succeeded", "failed", "interrupted")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "EvaluationTicket":
        return cls(j["ticket"], j["dataset"], j["status"], list(j["runs"]), list(j["models"]),
                   j.get("error"), j)


@dataclass(frozen=True)
class Fit:
    """An atmosphere fit (POST /v1/fits, GET /v1/fits/{id}; docs/fits.md): status ``queued``,
    ``running`` (with ``progress`` 0..1 and ``stage``), ``succeeded`` (with ``values`` and the
    RMSE before and after, mW/(m2.sr.nm)), ``failed`` or ``interrupted`` (with ``error``)."""

    id: int
    dataset: str
    model: str
    status: str
    progress: float
    stage: Optional[str]
    values: Optional[Dict[str, float]]
    rmse_before: Optional[float]
    rmse_after: Optional[float]
    cross_validated_rmse: Optional[float]
    error: Optional[str]
    raw: Dict[str, Any] = field(repr=False)

    @property
    def done(self) -> bool:
        return self.status in ("succeeded", "failed", "interrupted")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Fit":
        return cls(j["id"], j["dataset"], j["model"], j["status"], j["progress"], j.get("stage"),
                   j.get("values"), j.get("rmse_before"), j.get("rmse_after"),
                   j.get("cross_validated_rmse"), j.get("error"), j)


@dataclass(frozen=True)
class AerosolInversion:
    """A stored AERONET inversion for measured_aerosols (POST, GET /v1/aerosols; docs/data-api.md
    "Aerosol inversions"): its id (what ``aerosols=`` selects), label, site, days and content
    hash; ``retrievals`` (time and optical depth per wavelength) when read one by one."""

    id: int
    name: str
    site: str
    first_day: str
    last_day: str
    retrieval_count: int
    content_hash: str
    wavelengths_nm: Optional[List[float]]
    retrievals: Optional[List[Dict[str, Any]]]
    raw: Dict[str, Any] = field(repr=False)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "AerosolInversion":
        return cls(j["id"], j["name"], j["site"], j["first_day"], j["last_day"],
                   j["retrieval_count"], j["content_hash"], j.get("wavelengths_nm"),
                   j.get("retrievals"), j)


@dataclass(frozen=True)
class IrradianceComponentResult:
    """One measured component (ghi, dhi, dni) of a broadband irradiance dataset against the
    model's broadband figure: RMSE and mean bias (model minus measured) in W/m2, None when no
    sample was compared; ``errors_w_m2`` per sample (by instant, None where not compared) when
    the run was read with samples=True."""

    component: str
    rmse_w_m2: Optional[float]
    mean_bias_w_m2: Optional[float]
    samples_compared: int
    errors_w_m2: Optional[List[Optional[float]]] = None

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "IrradianceComponentResult":
        return cls(j["component"], j.get("rmse_w_m2"), j.get("mean_bias_w_m2"),
                   j["samples_compared"], j.get("errors_w_m2"))


def _irradiance_components(j: Dict[str, Any]) -> List[IrradianceComponentResult]:
    return [IrradianceComponentResult.from_json(c) for c in j.get("irradiance_components", [])]


@dataclass(frozen=True)
class EvaluationSummary:
    """A run in GET /v1/evaluations; rmse in ``rmse_unit`` (mW/(m2.sr.nm) over 360..720 nm on
    captures, W/m2 on a broadband irradiance dataset; None until finished), and on a broadband
    dataset its ``irradiance_components``."""

    id: int
    dataset: str
    model: str
    status: str
    rmse: Optional[float]
    samples_compared: Optional[int]
    job: Optional[int]
    rmse_unit: str = "mW/(m2.sr.nm)"
    irradiance_components: List[IrradianceComponentResult] = field(default_factory=list)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "EvaluationSummary":
        return cls(j["id"], j["dataset"], j["model"], j["status"], j.get("rmse"),
                   j.get("samples_compared"), j.get("job"),
                   j.get("rmse_unit", "mW/(m2.sr.nm)"), _irradiance_components(j))


@dataclass(frozen=True)
class Evaluation:
    """GET /v1/evaluations/{id}: one run with its per-capture RMSE (``captures``; with
    samples=True each capture's samples too), or on a broadband irradiance dataset its
    per-component results in W/m2 (``irradiance_components``; ``rmse_unit`` says which)."""

    id: int
    dataset: str
    model: str
    model_version: str
    parameters: Dict[str, Any]
    status: str
    rmse: Optional[float]
    samples_compared: Optional[int]
    captures: List[Dict[str, Any]]
    raw: Dict[str, Any] = field(repr=False)
    rmse_unit: str = "mW/(m2.sr.nm)"
    irradiance_components: List[IrradianceComponentResult] = field(default_factory=list)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Evaluation":
        return cls(j["id"], j["dataset"], j["model"], j["model_version"], j["parameters"],
                   j["status"], j.get("rmse"), j.get("samples_compared"), list(j["captures"]), j,
                   j.get("rmse_unit", "mW/(m2.sr.nm)"), _irradiance_components(j))


@dataclass(frozen=True)
class Job:
    """A scheduled evaluation (POST /v1/jobs, GET /v1/jobs/{id}): a 5-field UTC cron
    ``schedule``; ``models`` is "all" or a list of ids."""

    id: int
    name: str
    schedule: str
    dataset: str
    models: Union[str, List[str]]
    parameters: Dict[str, Any]
    paused: bool
    next_run: Optional[str]
    last_run: Optional[str]
    raw: Dict[str, Any] = field(repr=False)
    # Due occurrences skipped because the previous run was still going, and the last one.
    skipped_count: int = 0
    last_skipped: Optional[str] = None
    # The fit request each occurrence runs first, and the fit the newest one made
    # ({"id", "status", "rmse_after", "values", "error"}); None when the job does not re-fit.
    refit: Optional[Dict[str, Any]] = None
    last_fit: Optional[Dict[str, Any]] = None

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Job":
        return cls(j["id"], j["name"], j["schedule"], j["dataset"], j["models"],
                   j["parameters"], j["paused"], j.get("next_run"), j.get("last_run"), j,
                   j.get("skipped_count", 0), j.get("last_skipped"), j.get("refit"),
                   j.get("last_fit"))
