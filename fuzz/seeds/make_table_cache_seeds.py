#!/usr/bin/env python3
"""Writes the seeds of the table_cache fuzz program (fuzz/corpus/table_cache/): tiny but valid
Bruneton table blobs (models/bruneton/bruneton_table_blob.cpp) of 1 wavelength and 2 or 4
texels per axis, each as a table cache file (server/cache/file_table_cache.h, first byte even)
and as a bare blob (first byte odd, the program stores it). The cache file's XXH3 checksum
comes from Debian's libxxhash through ctypes."""
import ctypes
import os
import struct
import sys

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpus", "table_cache")
os.makedirs(out, exist_ok=True)
xxhash = ctypes.CDLL("libxxhash.so.0")
xxhash.XXH3_64bits.restype = ctypes.c_uint64
xxhash.XXH3_64bits.argtypes = [ctypes.c_char_p, ctypes.c_size_t]
KEY = b"bruneton-fuzz"  # the program's key (fuzz/table_cache_fuzz.cpp)
STRIDE = 8  # padded_stride(1), models/bruneton/spectral_rows.h


def fnv_words(data):
    h = 14695981039346656037
    words = len(data) // 8
    for i in range(words):
        h ^= struct.unpack_from("<Q", data, i * 8)[0]
        h = (h * 1099511628211) % 2**64
    for b in data[words * 8:]:
        h ^= b
        h = (h * 1099511628211) % 2**64
    return h


def blob(n, orders):
    description = (b"bruneton-tables;version=fuzz;format=1;grid=1;orders=%d;r=%d;mu=%d;mu_s=%d;nu=%d"
                   % (orders, n, n, n, n))
    b = b"CSKYBRUN" + struct.pack("<II", 1, len(description)) + description
    b += struct.pack("<ii", 1, STRIDE)
    # transmittance mu, r; irradiance mu_s, r; r, mu, mu_s, nu; steps and samples; orders.
    b += struct.pack("<13i", n, n, n, n, n, n, n, n, 8, 8, 4, 4, orders)
    b += struct.pack("<3d", 6360e3, 6420e3, 6421e3)
    for value in (0.9, 0.1):
        count = n * n * STRIDE
        b += struct.pack("<Q", count) + struct.pack("<%df" % count, *([value] * count))
    for table in range(3):
        empty = table == 2 and orders == 1
        texels = 0 if empty else n ** 4 * STRIDE
        rows = 0 if empty else n * n
        b += struct.pack("<Q", texels) + struct.pack("<%dH" % texels, *([0x3C00] * texels))
        b += struct.pack("<Q", rows) + struct.pack("<%df" % rows, *([1.0] * rows))
    return b + struct.pack("<Q", fnv_words(b))


def cache_file(payload):
    header = b"CSKYTBL\n" + struct.pack("<II", 2, len(KEY)) + KEY
    header += struct.pack("<QQ", len(payload), xxhash.XXH3_64bits(payload, len(payload)))
    return header + payload


for n, orders in ((2, 2), (2, 1), (4, 4)):
    b = blob(n, orders)
    with open(os.path.join(out, f"file_{n}x{orders}"), "wb") as f:
        f.write(b"\x00" + cache_file(b))
    with open(os.path.join(out, f"blob_{n}x{orders}"), "wb") as f:
        f.write(b"\x01" + b)
with open(os.path.join(out, "file_empty_payload"), "wb") as f:
    f.write(b"\x00" + cache_file(b""))
