"""Reading a skydome (an OpenEXR image, docs/http-api.md) into numpy arrays with Debian's
python3-openimageio (OpenImageIO's Python bindings), an OpenEXR reader Debian 12 packages for
Python (docs/clients.md "Install and dependencies").

It is optional: the client runs without it, a skydome is then a file to open with any OpenEXR
reader, and ``read_skydome`` says what to install."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, List

import numpy as np

from .errors import ClearskyError


@dataclass(frozen=True)
class SkydomeImage:
    """The pixels of a skydome: ``pixels`` of shape (height, width, channels), float32, in the
    order of ``channels`` (e.g. R, G, B, A, or one channel per wavelength and A; A is the
    coverage: 0 where the model gave no answer); ``attributes`` the header's attributes
    (``clearskyGamutMapping`` and the others the server writes)."""

    channels: List[str]
    pixels: np.ndarray
    attributes: Dict[str, Any] = field(repr=False)

    def channel(self, name: str) -> np.ndarray:
        """One channel as a (height, width) array."""
        return self.pixels[:, :, self.channels.index(name)]


def read_skydome(path: str) -> SkydomeImage:
    """Decodes the OpenEXR file ``path`` (every channel, as float32).

    Raises ClearskyError (code ``exr_reader_missing``) without python3-openimageio, and
    (code ``exr_unreadable``) when the file cannot be read.

    Example:
        >>> image = read_skydome(client.skydome("sky.exr", "preetham", sun_zenith=30,
        ...                                     sun_azimuth=135, size=64).path)
        >>> image.channel("R").shape
        (64, 64)
    """
    try:
        import OpenImageIO as oiio  # Debian: python3-openimageio
    except ImportError as missing:
        raise ClearskyError(None, "exr_reader_missing",
                            "reading an EXR image needs OpenImageIO's Python bindings "
                            "(Debian: apt-get install python3-openimageio); the file is at "
                            + path) from missing
    source = oiio.ImageInput.open(path)
    if source is None:
        raise ClearskyError(None, "exr_unreadable", f"{path}: {oiio.geterror()}")
    try:
        spec = source.spec()
        pixels = source.read_image(0, 0, 0, spec.nchannels, oiio.FLOAT)
        if pixels is None:
            raise ClearskyError(None, "exr_unreadable", f"{path}: {source.geterror()}")
        attributes = {a.name: a.value for a in spec.extra_attribs}
        return SkydomeImage(list(spec.channelnames),
                            np.asarray(pixels, dtype=np.float32).reshape(
                                spec.height, spec.width, spec.nchannels), attributes)
    finally:
        source.close()
