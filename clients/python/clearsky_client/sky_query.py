"""The query parameters shared by the sky endpoints (docs/http-api.md; /openapi.json
``components.parameters``): the model, the sun given (sun_zenith, sun_azimuth) or computed from
a place and time (lat, lon, time), the wavelengths, and the model's and atmosphere's own
parameters (turbidity, albedo, alpha, ...), passed through by name.

The server refuses an unknown or unused parameter with a 400 naming it, so a misspelt keyword
fails loudly here too; this module only writes values as the server reads them."""

from __future__ import annotations

from datetime import datetime
from typing import Dict, List, Mapping, Optional, Sequence, Tuple, Union

Number = Union[int, float]
ParameterValue = Union[int, float, str, bool]
Wavelengths = Union[str, Sequence[Number]]
Time = Union[str, datetime]
# A stored fit: its id, "latest" or "latest:DATASET".
FitReference = Union[int, str]
# A view: (view_zenith_deg, view_azimuth_deg).
View = Tuple[Number, Number]


def format_value(value: ParameterValue) -> str:
    """A value as the server parses it: booleans as true/false, numbers with full precision."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def format_wavelengths(wavelengths: Wavelengths) -> str:
    """A list of nm as "450,550,650"; a text ("450,550,650" or "400:700:10") as it is."""
    if isinstance(wavelengths, str):
        return wavelengths
    return ",".join(format_value(float(w)) for w in wavelengths)


def format_time(time: Time) -> str:
    """ISO 8601 with its UTC offset; a datetime must carry its time zone."""
    if isinstance(time, datetime):
        if time.tzinfo is None:
            raise ValueError("time: a datetime needs a time zone (tzinfo), e.g. timezone.utc")
        return time.isoformat()
    return time


def sky_parameters(model: str, sun_zenith: Optional[Number], sun_azimuth: Optional[Number],
                   lat: Optional[Union[Number, str]], lon: Optional[Union[Number, str]],
                   time: Optional[Time], wavelengths: Optional[Wavelengths],
                   parameters: Mapping[str, ParameterValue],
                   quality: Optional[str] = None,
                   fit: Optional[FitReference] = None) -> Dict[str, ParameterValue]:
    """The parameters of a sky request as a dict, only those given. quality: draft, standard or
    reference (docs/quality-levels.md); absent, the server's level. fit: a stored fit's id,
    "latest" or "latest:DATASET", whose fitted values the model then uses (docs/fits.md "Using
    a fit")."""
    out: Dict[str, ParameterValue] = {"model": model}
    if quality is not None:
        out["quality"] = quality
    if fit is not None:
        out["fit"] = fit
    for name, value in (("sun_zenith", sun_zenith), ("sun_azimuth", sun_azimuth),
                        ("lat", lat), ("lon", lon)):
        if value is not None:
            out[name] = value
    if time is not None:
        out["time"] = format_time(time)
    if wavelengths is not None:
        out["wavelengths"] = format_wavelengths(wavelengths)
    out.update(parameters)
    return out


def as_query(parameters: Mapping[str, ParameterValue]) -> List[Tuple[str, str]]:
    """Query pairs of a parameter dict (None values left out)."""
    return [(k, format_value(v)) for k, v in parameters.items() if v is not None]


def views_body(views: Sequence[View]) -> List[List[float]]:
    """The ``views`` member of a batch body: [[zenith, azimuth], ...] in degrees."""
    out = []
    for view in views:
        zenith, azimuth = view
        out.append([float(zenith), float(azimuth)])
    return out
