#!/usr/bin/env bash
# Builds the clearsky image with podman and checks it without starting a container
# (docs/deploy.md "Container image"): on machines whose sandbox refuses to start containers,
# podman still builds with `--isolation chroot`, and the image's filesystem can be exported and
# run with chroot. No image registry is needed: the Debian 12 base is made with debootstrap from
# Debian's archive and imported, unless the base image named by DEBIAN_IMAGE exists already.
#
# Usage: deploy/container/build-image.sh [TAG]        (TAG defaults to clearsky:VERSION)
# Environment: DEBIAN_IMAGE (default localhost/debian:12), DEBIAN_MIRROR
# (default http://deb.debian.org/debian), CLEARSKY_IMAGE_WORK (default /var/tmp/clearsky-image).
#
# Checks, each printed with its result:
#   - the image builds (both stages);
#   - its filesystem holds /usr/local/bin/clearsky, and every library the executable links is
#     found there (ldd inside the exported filesystem: no "not found");
#   - the image runs as the non-root user 10001, with volumes for the database and the cache;
#   - the executable, chrooted into the exported filesystem as that user, serves /healthz and a
#     radiance query, creating its database and cache on the volume paths.
#   - the browser viewer is in the image and served at /.
# Not checked here: `podman run` itself (the sandbox refuses to start containers), the
# HEALTHCHECK as the runtime runs it, and volumes as the runtime mounts them.
set -euo pipefail
cd "$(dirname "$0")/../.."

version=$(sed -n 's/^project(clearsky VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
tag=${1:-clearsky:${version:-dev}}
base=${DEBIAN_IMAGE:-localhost/debian:12}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
work=${CLEARSKY_IMAGE_WORK:-/var/tmp/clearsky-image}
mkdir -p "$work"

for tool in podman debootstrap curl; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "build-image: $tool is missing (apt-get install podman debootstrap curl)" >&2
    exit 77
  fi
done

if ! podman image exists "$base"; then
  echo "== base image $base: debootstrap bookworm from $mirror"
  rm -rf "$work/debian12"
  debootstrap --variant=minbase bookworm "$work/debian12" "$mirror"
  tar -C "$work/debian12" -c . | podman import - "$base"
fi

echo "== podman build $tag (base $base)"
start=$(date +%s)
# The host's CA bundle for npm (a TLS-inspecting proxy's CA is in it where there is one).
ca=${NODE_EXTRA_CA_CERTS:-/etc/ssl/certs/ca-certificates.crt}
secret=()
[ -s "$ca" ] && secret=(--secret "id=npm_ca,src=$ca")
podman build --isolation chroot --format docker --build-arg "DEBIAN_IMAGE=$base" "${secret[@]}" \
  -f deploy/container/Containerfile -t "$tag" .
echo "built in $(($(date +%s) - start)) s"

echo "== image configuration"
user=$(podman image inspect --format '{{.Config.User}}' "$tag")
volumes=$(podman image inspect --format '{{range $k, $v := .Config.Volumes}}{{$k}} {{end}}' "$tag")
size=$(podman image inspect --format '{{.Size}}' "$tag")
echo "user: $user; volumes: $volumes; size: $((size / 1024 / 1024)) MiB"
case "$user" in
  0 | 0:* | root | root:* | "")
    echo "FAIL: the image runs as root" >&2
    exit 1
    ;;
esac

echo "== exported filesystem"
fs="$work/rootfs"
rm -rf "$fs"
mkdir -p "$fs"
container=$(podman create "$tag")
trap 'podman rm -f "$container" >/dev/null 2>&1 || true' EXIT
podman export "$container" | tar -C "$fs" -x
test -x "$fs/usr/local/bin/clearsky" || {
  echo "FAIL: /usr/local/bin/clearsky missing" >&2
  exit 1
}
missing=$(chroot "$fs" /usr/bin/ldd /usr/local/bin/clearsky | grep "not found" || true)
if [ -n "$missing" ]; then
  echo "FAIL: libraries missing from the image:" >&2
  echo "$missing" >&2
  exit 1
fi
echo "every linked library present ($(chroot "$fs" /usr/bin/ldd /usr/local/bin/clearsky | wc -l) entries)"
chroot "$fs" /usr/local/bin/clearsky --version

echo "== serve from the exported filesystem as user ${user%%:*}"
mount --bind /proc "$fs/proc"
mount --bind /dev "$fs/dev"
cleanup() {
  [ -n "${server:-}" ] && kill "$server" 2>/dev/null && wait "$server" 2>/dev/null
  umount "$fs/proc" "$fs/dev" 2>/dev/null || true
  podman rm -f "$container" >/dev/null 2>&1 || true
}
trap cleanup EXIT
port=$((20000 + RANDOM % 20000))
chroot --userspec="$user" "$fs" /usr/local/bin/clearsky serve --host 127.0.0.1 --port "$port" \
  --db /var/lib/clearsky/clearsky.db --cache-dir /var/cache/clearsky --models preetham \
  --viewer-dir /usr/local/share/clearsky/viewer \
  >"$work/serve.log" 2>&1 &
server=$!
for _ in $(seq 1 120); do
  curl -fsS "http://127.0.0.1:$port/readyz" >/dev/null 2>&1 && break
  sleep 0.5
done
curl -fsS "http://127.0.0.1:$port/healthz"
echo
curl -fsS "http://127.0.0.1:$port/v1/radiance?model=preetham&sun_zenith=40&sun_azimuth=90&view_zenith=50&view_azimuth=180" |
  head -c 200
echo
viewer_page=$(curl -fsS "http://127.0.0.1:$port/" | head -c 2000)
case "$viewer_page" in
  *"<html"* | *"<!doctype html"* | *"<!DOCTYPE html"*) echo "viewer served at /" ;;
  *)
    echo "FAIL: no viewer page at /" >&2
    exit 1
    ;;
esac
test -s "$fs/var/lib/clearsky/clearsky.db" || {
  echo "FAIL: no database on the volume path" >&2
  exit 1
}
owner=$(stat -c %u "$fs/var/lib/clearsky/clearsky.db")
echo "database created on the volume path, owner uid $owner"
echo "OK: $tag"
