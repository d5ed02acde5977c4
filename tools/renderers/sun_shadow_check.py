"""End-to-end check of the Blender recipe of docs/renderers.md: `clearsky serve` answers a
latlong skydome with the solar disc, Blender renders a pole on a plane lit by it
(blender_sun_shadow.py), and the shadow must point away from the sun: its azimuth equals the
sun's + 180 degrees within --tolerance-deg. Exit 77 (CTest's skip) when Blender is missing.

    sun_shadow_check.py --binary build/clearsky [--blender blender] [--size 96] [--samples 8]"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import urllib.request

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hostile"))
from serve_process import start_server  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--size", type=int, default=96, help="rendered image, pixels")
    parser.add_argument("--samples", type=int, default=8, help="Cycles samples per pixel")
    parser.add_argument("--sky-size", type=int, default=512, help="skydome width, pixels")
    parser.add_argument("--sun-zenith", type=float, default=50.0)
    parser.add_argument("--sun-azimuth", type=float, default=120.0)
    parser.add_argument("--tolerance-deg", type=float, default=8.0)
    args = parser.parse_args()

    blender = shutil.which(args.blender)
    if blender is None:
        print("skipped: %s not found (apt-get install blender)" % args.blender)
        return 77
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blender_sun_shadow.py")
    with tempfile.TemporaryDirectory(prefix="clearsky-blender-") as work:
        server, port = start_server(args.binary, work, "preetham")
        try:
            url = ("http://127.0.0.1:%d/v1/skydome?model=preetham&sun_zenith=%g&sun_azimuth=%g"
                   "&projection=latlong&size=%d&sun=disc&ground=albedo&compression=zip"
                   % (port, args.sun_zenith, args.sun_azimuth, args.sky_size))
            sky = os.path.join(work, "sky.exr")
            with urllib.request.urlopen(url, timeout=120) as answer, open(sky, "wb") as f:
                f.write(answer.read())
        finally:
            server.terminate()
            server.wait(timeout=60)
        run = subprocess.run(
            [blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python", script,
             "--", sky, os.path.join(work, "render.exr"), str(args.size), str(args.samples)],
            capture_output=True, text=True, timeout=240)
        lines = [l for l in run.stdout.splitlines() if l.startswith("CLEARSKY_SHADOW ")]
        if run.returncode != 0 or not lines:
            print(run.stdout[-4000:], run.stderr[-4000:])
            print("FAIL: Blender did not report the shadow (exit %d)" % run.returncode)
            return 1
    result = json.loads(lines[-1][len("CLEARSKY_SHADOW "):])
    expected = (args.sun_azimuth + 180.0) % 360.0
    error = (result["shadow_azimuth_deg"] - expected + 180.0) % 360.0 - 180.0
    print("shadow azimuth %.1f deg (expected %.1f, error %.1f), %d shadow pixels, lit plane %.1f "
          "(radiometric), render %.1f s"
          % (result["shadow_azimuth_deg"], expected, error, result["shadow_pixels"],
             result["lit_luminance"], result["render_s"]))
    if not (abs(error) <= args.tolerance_deg and result["shadow_pixels"] >= 10):
        print("FAIL: the shadow does not point away from the sun")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
