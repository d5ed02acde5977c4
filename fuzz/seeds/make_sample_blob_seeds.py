#!/usr/bin/env python3
"""Writes the seeds of the sample_blob fuzz program (fuzz/corpus/sample_blob/): sample errors
blobs (storage/repositories/sample_errors_blob.h, first byte even) and the wavelength and value
blobs of a measured spectrum (storage/sqlite/blob.h, first byte odd, split at the middle)."""
import os
import struct

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpus", "sample_blob")
os.makedirs(out, exist_ok=True)


def errors_blob(samples, wavelengths):
    b = struct.pack("<II", len(samples), wavelengths)
    for index, zenith, azimuth, rmse, bias in samples:
        b += struct.pack("<iffdd", index, zenith, azimuth, rmse, bias)
        b += struct.pack("<%df" % wavelengths, *[bias + 0.5 * k for k in range(wavelengths)])
    return b


def spectrum_blobs(wavelengths, values):
    return struct.pack("<%dd" % len(wavelengths), *wavelengths) + struct.pack(
        "<%dd" % len(values), *values)


seeds = {
    "errors_empty": b"\x00" + errors_blob([], 31),
    "errors_two": b"\x00" + errors_blob([(0, 77.9, 0.0, 12.5, -3.25), (80, 0.0, 0.0, 8.0, 1.5)], 3),
    "spectrum_kider": b"\x01" + spectrum_blobs([350.0, 780.0, 1210.0, 1640.0, 2070.0, 2500.0],
                                               [0.0563, 0.0223, 0.00313, 0.000969, 0.00021, -0.00158]),
    "spectrum_one": b"\x01" + spectrum_blobs([550.0], [0.1]),
}
for name, data in seeds.items():
    with open(os.path.join(out, name), "wb") as f:
        f.write(data)
