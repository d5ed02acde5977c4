"""A synthetic capture in the Kider et al. 2014 file format (storage/importers/kider_format.h):
81 files DATE___HH.MM.SS_-_INDEX____AZIMUTH___ELEVATION.asd.rad.txt with 350..2500 nm rows, the
scan pattern of rings 32, 24, 16, 8 and the zenith. The values are a smooth sky-like spectrum
(lambda^-4), enough for an import and an evaluation to run end to end."""

import os

# (elevation degrees, samples on the ring), from the horizon up; azimuths counter-clockwise.
RINGS = [(12.1151, 32), (33.749, 24), (53.3665, 16), (71.9187, 8), (90.0, 1)]


def write_capture(folder, label="2013-05-27___11.45.00"):
    os.makedirs(folder, exist_ok=True)
    rows = "".join(
        f"{nm}\t {0.06 * (450.0 / nm) ** 4:.14E} \n" for nm in range(350, 2501)
    )
    index = 0
    for elevation, count in RINGS:
        for k in range(count):
            azimuth = 360.0 * k / count
            name = f"{label}_-_{index}____{azimuth:g}___{elevation:g}.asd.rad"
            with open(os.path.join(folder, name + ".txt"), "w", encoding="ascii") as out:
                out.write(f"Wavelength\t{name}\n")
                out.write(rows)
            index += 1
    return folder
