#!/usr/bin/env bash
# Writes the seed archives of the kider_archive fuzz program (fuzz/corpus/kider_archive/) from
# one published Kider et al. 2014 capture, cut down so that the seeds stay a few kilobytes:
# every radiance file keeps its header and the rows every 430 nm from 350 to 2500 nm (the
# reader needs 350..2500 nm, not every nanometre). Usage: make_kider_seeds.sh CAPTURE.7z
# (e.g. ../shared/data/kider2014/2013-05-27/RADIANCE/2013-05-27___09.30.00.7z). Needs 7z
# (p7zip-full) and python3.
set -euo pipefail
archive=$(realpath "$1")
out="$(realpath "$(dirname "$0")/..")/corpus/kider_archive"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
cd "$work"
7z x -bd -ofull "$archive" >/dev/null
label=$(basename "$archive" .7z)
mkdir -p "cut/$label"
for f in full/"$label"/*.asd.rad.txt; do
  awk 'NR == 1 || ($1 - 350) % 430 == 0' "$f" >"cut/$label/$(basename "$f")"
done
(cd cut && 7z a -bd -mx=9 "$out/capture.7z" "$label" >/dev/null)
python3 - "$out" "$label" <<'PY'
import io, os, sys, tarfile, zipfile
out, label = sys.argv[1], sys.argv[2]
folder = os.path.join("cut", label)
names = sorted(os.listdir(folder))
with zipfile.ZipFile(os.path.join(out, "capture.zip"), "w", zipfile.ZIP_DEFLATED) as z:
    for n in names:
        z.write(os.path.join(folder, n), f"{label}/{n}")
# A folder-like tar (the capture's folder, gzip-compressed) and a tar of the 7z archive
# (archives one level down).
with tarfile.open(os.path.join(out, "capture_folder.tar.gz"), "w:gz") as t:
    t.add(folder, arcname=label)
with tarfile.open(os.path.join(out, "nested_7z.tar"), "w") as t:
    t.add(os.path.join(out, "capture.7z"), arcname=f"{label}.7z")
# One file alone (an incomplete capture: the reader must refuse it by name).
with tarfile.open(os.path.join(out, "one_file.tar"), "w") as t:
    t.add(os.path.join(folder, names[0]), arcname=names[0])
PY
ls -l "$out"
