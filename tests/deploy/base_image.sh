#!/usr/bin/env bash
# Makes the Debian 12 base images docker/Dockerfile starts from (debian:bookworm and
# debian:bookworm-slim) without a registry: debootstrap --variant=minbase from the Debian archive
# this machine's own apt sources name, the host's deb822 sources copied in, imported into podman.
# Does nothing when podman already has the image. Needs root, podman and debootstrap.
#   base_image.sh [--force]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/podman_env.sh"
if [ "${1:-}" != --force ] && podman image exists debian:bookworm; then
  podman image exists debian:bookworm-slim || podman tag debian:bookworm debian:bookworm-slim
  echo "base image: debian:bookworm is already there"
  exit 0
fi
# The first Debian archive serving plain 'bookworm' in the machine's sources (deb822 or one-line).
mirror=$(
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    awk '/^[[:space:]]*$/ { if (u != "" && p) { print u; exit } u=""; p=0; next }
         /^URIs:/ { u=$2 } /^Suites:/ { for (i = 2; i <= NF; i++) if ($i == "bookworm") p=1 }
         END { if (u != "" && p) print u }' "$f"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] && awk '$1 == "deb" && $3 == "bookworm" { print $2; exit }' "$f"
  done
  true
)
mirror=$(head -n1 <<<"$mirror")
[ -n "$mirror" ] || { echo "base image: no Debian 'bookworm' archive in /etc/apt sources" >&2; exit 1; }
root=$(mktemp -d)
# debootstrap mounts proc and sys inside; never delete through a mount.
trap 'umount -R "$root/proc" "$root/sys" 2>/dev/null || true; rm -rf --one-file-system "$root"' EXIT
echo "base image: debootstrap --variant=minbase bookworm from $mirror"
start=$(date +%s)
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.log" 2>&1 ||
  { tail -20 "$root.log" >&2; rm -f "$root.log"; exit 1; }
rm -f "$root.log"
# The host's sources (deb822 and one-line), so apt inside finds the same archives.
rm -f "$root/etc/apt/sources.list"
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] && cp "$f" "$root$f"
done
rm -rf "$root"/var/cache/apt/archives/*.deb "$root"/var/lib/apt/lists/*
tar -C "$root" -c . | podman import - debian:bookworm >/dev/null
podman tag debian:bookworm debian:bookworm-slim
echo "base image: debian:bookworm and debian:bookworm-slim in $(( $(date +%s) - start )) s"
