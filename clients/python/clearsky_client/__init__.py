"""A Python client of the clearsky HTTP API v1 (docs/clients.md).

Example:
    >>> from clearsky_client import Client
    >>> client = Client("http://127.0.0.1:8080")
    >>> client.rgb("preetham", 45, 0, sun_zenith=30, sun_azimuth=135).rgb
    array([[ 4.37494015,  8.14954111, 15.98833595]])
"""

from .client import Client
from .data_results import (AerosolInversion, Dataset, DatasetSummary, Evaluation, EvaluationSummary,
                           IrradianceComponentResult,
                           EvaluationTicket, Fit, Import, Job, Page)
from .errors import ClearskyError
from .exr_image import SkydomeImage, read_skydome
from .retry import RetryNotice, RetryPolicy
from .sky_results import (Irradiance, IrradianceComponent, IrradianceSeries, ModelInfo,
                          ModelParameter, Radiance, Rgb, SkydomeFile, SkyMatrix, Sun, SunUsed)

__version__ = "0.1.0"

__all__ = [
    "Client", "ClearskyError", "RetryPolicy", "RetryNotice", "Page", "Sun", "SunUsed",
    "ModelInfo", "ModelParameter", "Radiance", "Rgb", "Irradiance", "IrradianceComponent",
    "IrradianceSeries", "SkyMatrix",
    "SkydomeFile", "SkydomeImage", "read_skydome", "DatasetSummary", "Dataset", "Import",
    "EvaluationTicket", "EvaluationSummary", "Evaluation", "IrradianceComponentResult", "Fit", "AerosolInversion", "Job",
]
