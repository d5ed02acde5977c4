"""Typed answers of the sky endpoints: the sun, the models, radiance, irradiance and colour
(docs/http-api.md; the schemas Sun, Model, Radiance, Irradiance and Rgb of /openapi.json).

Spectra and per-view values are numpy arrays; every answer also keeps the whole JSON it came
from in ``raw``, so a member this client does not name is still at hand. Angles are degrees,
azimuths clockwise from North; radiance W/(m2.sr.nm), irradiance W/m2, luminance cd/m2."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple

import numpy as np


@dataclass(frozen=True)
class Sun:
    """GET /v1/sun: the sun's position and the day's events (times in the request's offset)."""

    zenith_deg: float
    azimuth_deg: float
    sunrise: Optional[str]
    transit: Optional[str]
    sunset: Optional[str]
    day: str
    raw: Dict[str, Any] = field(repr=False)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Sun":
        return cls(j["zenith"], j["azimuth"], j.get("sunrise"), j.get("transit"),
                   j.get("sunset"), j["day"], j)


@dataclass(frozen=True)
class SunUsed:
    """The sun an answer was computed for; source is ``given`` or ``spa`` (from place and
    time)."""

    zenith_deg: float
    azimuth_deg: float
    source: str

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "SunUsed":
        return cls(j["zenith_deg"], j["azimuth_deg"], j["source"])


@dataclass(frozen=True)
class ModelParameter:
    """One parameter a model takes: unit, default and valid range (GET /v1/models)."""

    name: str
    unit: str
    description: str
    default: float
    min: float
    max: float
    integer: bool
    kind: str


@dataclass(frozen=True)
class ModelInfo:
    """A served model (GET /v1/models): its parameters and the state of its tables."""

    id: str
    name: str
    version: str
    citation: str
    wavelength_range_nm: Tuple[float, float]
    parameters: List[ModelParameter]
    status: str
    raw: Dict[str, Any] = field(repr=False)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "ModelInfo":
        parameters = [ModelParameter(p["name"], p["unit"], p["description"], p["default"],
                                     p["min"], p["max"], p["integer"], p["kind"])
                      for p in j["parameters"]]
        low, high = j["wavelength_range_nm"]
        return cls(j["id"], j["name"], j["version"], j["citation"], (low, high), parameters,
                   j["state"]["status"], j)


@dataclass(frozen=True)
class Radiance:
    """GET or POST /v1/radiance: one row of ``radiance`` per view, one column per wavelength.

    radiance: shape (views, wavelengths), W/(m2.sr.nm); wavelengths_nm: shape (wavelengths,);
    view_zenith_deg, view_azimuth_deg: shape (views,)."""

    model: str
    model_version: str
    sun: SunUsed
    altitude_m: float
    unit: str
    grid: str
    wavelengths_nm: np.ndarray
    view_zenith_deg: np.ndarray
    view_azimuth_deg: np.ndarray
    radiance: np.ndarray
    raw: Dict[str, Any] = field(repr=False)

    @property
    def quality(self) -> str:
        """The quality level asked (docs/quality-levels.md)."""
        return self.raw["quality"]

    @property
    def served_quality(self) -> str:
        """The level whose tables answered: quality, or draft while standard is being built."""
        return self.raw["served_quality"]

    @property
    def fit(self) -> Optional[Dict[str, Any]]:
        """The stored fit the request named (fit=): id, model, model_version, dataset and the
        fitted parameters used; None without one (docs/fits.md "Using a fit")."""
        return self.raw.get("fit")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Radiance":
        samples = j["samples"]
        wavelengths = np.asarray(j["wavelengths_nm"], dtype=np.float64)
        values = np.asarray([s["radiance"] for s in samples], dtype=np.float64)
        return cls(j["model"], j["model_version"], SunUsed.from_json(j["sun"]), j["altitude_m"],
                   j["unit"], j["grid"], wavelengths,
                   np.asarray([s["view_zenith_deg"] for s in samples], dtype=np.float64),
                   np.asarray([s["view_azimuth_deg"] for s in samples], dtype=np.float64),
                   values.reshape(len(samples), len(wavelengths)), j)


@dataclass(frozen=True)
class Rgb:
    """GET or POST /v1/rgb: linear sRGB (D65, radiometric) and luminance per view.

    rgb: shape (views, 3); luminance_cd_m2 and gamut_clipped: shape (views,) (a colour outside
    the sRGB gamut had its negative components clipped to 0: docs/http-api.md "RGB")."""

    model: str
    model_version: str
    method: str
    sun: SunUsed
    colour_space: str
    view_zenith_deg: np.ndarray
    view_azimuth_deg: np.ndarray
    rgb: np.ndarray
    luminance_cd_m2: np.ndarray
    gamut_clipped: np.ndarray
    warning: Optional[str]
    raw: Dict[str, Any] = field(repr=False)

    @property
    def quality(self) -> str:
        """The quality level asked (docs/quality-levels.md)."""
        return self.raw["quality"]

    @property
    def served_quality(self) -> str:
        """The level whose tables answered: quality, or draft while standard is being built."""
        return self.raw["served_quality"]

    @property
    def fit(self) -> Optional[Dict[str, Any]]:
        """The stored fit the request named (fit=): id, model, model_version, dataset and the
        fitted parameters used; None without one (docs/fits.md "Using a fit")."""
        return self.raw.get("fit")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Rgb":
        samples = j["samples"]
        return cls(j["model"], j["model_version"], j["method"], SunUsed.from_json(j["sun"]),
                   j["colour_space"],
                   np.asarray([s["view_zenith_deg"] for s in samples], dtype=np.float64),
                   np.asarray([s["view_azimuth_deg"] for s in samples], dtype=np.float64),
                   np.asarray([s["rgb"] for s in samples], dtype=np.float64).reshape(-1, 3),
                   np.asarray([s["luminance_cd_m2"] for s in samples], dtype=np.float64),
                   np.asarray([s["gamut_clipped"] for s in samples], dtype=bool),
                   j.get("warning"), j)


@dataclass(frozen=True)
class IrradianceComponent:
    """One component of the irradiance on the plane; spectral_w_m2_nm with spectral=True.
    model_range_irradiance_w_m2 is over integrated_range_nm (irradiance_w_m2: its deprecated
    alias); broadband_irradiance_w_m2 over 300..4000 nm with molecular absorption, None when
    the model cannot go broadband (Irradiance.broadband_unavailable says why)."""

    irradiance_w_m2: float
    illuminance_lx: float
    spectral_w_m2_nm: Optional[np.ndarray]
    model_range_irradiance_w_m2: float
    broadband_irradiance_w_m2: Optional[float]

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "IrradianceComponent":
        spectrum = j.get("spectral_w_m2_nm")
        return cls(j["irradiance_w_m2"], j["illuminance_lx"],
                   None if spectrum is None else np.asarray(spectrum, dtype=np.float64),
                   j.get("model_range_irradiance_w_m2", j["irradiance_w_m2"]),
                   j.get("broadband_irradiance_w_m2"))


@dataclass(frozen=True)
class Irradiance:
    """GET /v1/irradiance: the components asked for (None for the others) on the plane."""

    model: str
    model_version: str
    sun: SunUsed
    tilt_deg: float
    surface_azimuth_deg: float
    integrated_range_nm: Tuple[float, float]
    wavelengths_nm: Optional[np.ndarray]
    direct_normal: Optional[IrradianceComponent]
    direct: Optional[IrradianceComponent]
    diffuse: Optional[IrradianceComponent]
    global_: Optional[IrradianceComponent]
    raw: Dict[str, Any] = field(repr=False)
    # The isotropic ground's reflection on the plane (None with ground_reflection="exclude").
    ground_diffuse: Optional[IrradianceComponent] = None

    @property
    def quality(self) -> str:
        """The quality level asked (docs/quality-levels.md)."""
        return self.raw["quality"]

    @property
    def served_quality(self) -> str:
        """The level whose tables answered: quality, or draft while standard is being built."""
        return self.raw["served_quality"]

    @property
    def fit(self) -> Optional[Dict[str, Any]]:
        """The stored fit the request named (fit=): id, model, model_version, dataset and the
        fitted parameters used; None without one (docs/fits.md "Using a fit")."""
        return self.raw.get("fit")

    @property
    def broadband_unavailable(self) -> Optional[str]:
        """Why the model's answer has no broadband figures (None when it has them)."""
        return self.raw.get("broadband_unavailable")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "Irradiance":
        def component(name: str) -> Optional[IrradianceComponent]:
            return IrradianceComponent.from_json(j[name]) if name in j else None

        low, high = j["integrated_range_nm"]
        wavelengths = j.get("wavelengths_nm")
        return cls(j["model"], j["model_version"], SunUsed.from_json(j["sun"]),
                   j["plane"]["tilt_deg"], j["plane"]["surface_azimuth_deg"], (low, high),
                   None if wavelengths is None else np.asarray(wavelengths, dtype=np.float64),
                   component("direct_normal"), component("direct"), component("diffuse"),
                   component("global"), j, component("ground_diffuse"))


@dataclass(frozen=True)
class IrradianceSeries:
    """GET /v1/irradiance/series: one numpy array per column (``columns``, pvlib's names:
    ``ghi``, ``dni``, ``dhi``, ``poa_global_30_180``, ... broadband, 300..4000 nm, and the
    model's own range as ``model_range_ghi``, ...; times as ISO 8601 strings, ``night`` as
    booleans, a value the model could not answer as NaN), and the answer's other members in
    ``raw`` (without its rows). A model that cannot go broadband has NaN broadband columns and
    says why in ``broadband_unavailable``."""

    columns: Dict[str, np.ndarray]
    planes: List[Dict[str, Any]]
    unanswered_steps: int
    raw: Dict[str, Any] = field(repr=False)

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name]

    def __len__(self) -> int:
        return int(self.raw["steps"])

    @property
    def broadband_unavailable(self) -> Optional[str]:
        """Why ghi, dni, dhi and poa_* are NaN, or None when they are broadband figures."""
        return self.raw.get("broadband_unavailable")

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "IrradianceSeries":
        names = j["columns"]
        rows = j["rows"]
        columns: Dict[str, np.ndarray] = {}
        for k, name in enumerate(names):
            values = [row[k] for row in rows]
            if name.startswith("time_"):
                columns[name] = np.asarray(values, dtype=object)
            elif name == "night":
                columns[name] = np.asarray(values, dtype=bool)
            else:
                columns[name] = np.asarray([np.nan if v is None else v for v in values],
                                           dtype=np.float64)
        raw = {key: value for key, value in j.items() if key != "rows"}
        return cls(columns, j["planes"], j["unanswered_steps"], raw)


@dataclass(frozen=True)
class SkyMatrix:
    """GET /v1/skypatches with start: ``matrix`` (patches x steps for luminance, patches x
    steps x components for rgb and spectral; Radiance's patch order, patch 0 the ground),
    ``time_utc`` and ``night`` per step (column), the patches' centre ``altitude_deg``,
    ``azimuth_deg`` and ``solid_angle_sr``, and the answer's other members in ``raw`` (without
    the matrix)."""

    matrix: np.ndarray
    time_utc: np.ndarray
    night: np.ndarray
    altitude_deg: np.ndarray
    azimuth_deg: np.ndarray
    solid_angle_sr: np.ndarray
    raw: Dict[str, Any] = field(repr=False)

    @classmethod
    def from_json(cls, j: Dict[str, Any]) -> "SkyMatrix":
        times = j["times"]
        patches = j["patches"]
        raw = {key: value for key, value in j.items() if key != "matrix"}
        return cls(np.asarray(j["matrix"], dtype=np.float64),
                   np.asarray([t["time_utc"] for t in times], dtype=object),
                   np.asarray([t["night"] for t in times], dtype=bool),
                   np.asarray([p["altitude_deg"] for p in patches], dtype=np.float64),
                   np.asarray([p["azimuth_deg"] for p in patches], dtype=np.float64),
                   np.asarray([p["solid_angle_sr"] for p in patches], dtype=np.float64), raw)


@dataclass(frozen=True)
class SkydomeFile:
    """GET /v1/skydome streamed to a file: its path and size (an OpenEXR image; read it with
    ``read_skydome`` when Debian's python3-openimageio is installed)."""

    path: str
    bytes_written: int
