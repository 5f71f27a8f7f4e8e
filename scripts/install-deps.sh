#!/usr/bin/env bash
# Installs everything Geodesic needs to build and test on Debian 12 (bookworm), as root.
# Lavapipe with ray tracing needs Mesa >= 24.1, which bookworm only has in backports; the
# backports entry is derived from the machine's own Debian sources so no mirror is hard-coded.
#   install-deps.sh            build and test (the README's test command, CI)
#   install-deps.sh --build    build and run the daemon only: no test libraries, browser,
#                              Node.js, clang or container tools (scripts/run.sh, the image's
#                              build stage)
#   install-deps.sh --runtime  the container's last stage: lavapipe, the Vulkan loader and curl
#                              (the image copies the binary's own libraries, docker/bundle-libs.sh)
set -euo pipefail

mode=${1:---all}
case "$mode" in
  --all | --build | --runtime) ;;
  *) echo "usage: install-deps.sh [--build | --runtime]" >&2; exit 2 ;;
esac

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: run as root (apt-get needs it)" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
backports_file=/etc/apt/sources.list.d/geodesic-backports.sources

# Prints the URI of the first configured Debian archive that serves the plain 'bookworm' suite.
debian_archive_uri() {
  local f
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    awk '
      /^[[:space:]]*$/ { if (uri != "" && plain) { print uri; exit } uri=""; plain=0; next }
      /^URIs:/ { uri=$2 }
      /^Suites:/ { for (i = 2; i <= NF; i++) if ($i == "bookworm") plain=1 }
      END { if (uri != "" && plain) print uri }
    ' "$f" | head -n1
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    awk '$1 == "deb" && $3 == "bookworm" { print $2; exit }' "$f"
  done
}

if [ "$mode" = --runtime ]; then
  # The Vulkan loader (lavapipe follows below) and curl for the container's health check.
  # libegl1 (with libglvnd0), libx11-6, libxext6: NVIDIA's Vulkan driver (libGLX_nvidia.so.0,
  # which the NVIDIA Container Toolkit mounts) loads them and, without libEGL, answers no
  # vkCreateInstance: the loader then finds no driver (seen with driver 580 on an H200).
  packages=(libvulkan1 curl libegl1 libx11-6 libxext6)
else
  # zlib1g-dev: assimp's CMake package links libz.so, and libassimp-dev does not depend on it.
  # glslang-tools: glslang's CMake package names glslangValidator.
  packages=(
    build-essential cmake ninja-build pkg-config ca-certificates
    libvulkan-dev glslang-tools glslang-dev spirv-tools
    nlohmann-json3-dev libopenexr-dev libpng-dev libassimp-dev zlib1g-dev
    libboost-dev libsqlite3-dev libturbojpeg0-dev
  )
fi
# The test suites and their tools.
if [ "$mode" = --all ]; then
  packages+=(git python3 vulkan-tools openimageio-tools libgtest-dev libgmock-dev)
  # tests/deploy: the image built and probed with podman (runc: crun fails on hybrid cgroups)
  # from base images debootstrap makes, and a one-node Slurm cluster.
  packages+=(podman runc containernetworking-plugins podman-compose debootstrap curl
             slurmctld slurmd slurm-client munge)
fi
# Browser tests of the web client (tests/web): Debian's Chromium, driven by playwright-core
# from npm, which also brings the linters of docker/ and proto/openapi.json. Node.js only if
# the machine has none (an existing one may not be Debian's).
if [ "$mode" = --all ]; then
  packages+=(chromium)
  # scripts/test-hardening.sh: clang with its sanitizer and libFuzzer runtimes.
  packages+=(clang-14 libclang-rt-14-dev)
  { command -v node && command -v npm; } >/dev/null 2>&1 || packages+=(nodejs npm)
fi

# playwright-core, pinned by tests/web/package-lock.json; `npm ci` again only when the lock file
# is newer than the installed tree (npm ci writes node_modules/.package-lock.json).
install_web_test_deps() {
  [ "$mode" = --all ] || return 0
  local dir
  dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/tests/web"
  if [ "$dir/package-lock.json" -nt "$dir/node_modules/.package-lock.json" ]; then
    (cd "$dir" && npm ci --no-audit --no-fund)
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
mesa_version=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
mesa_major=${mesa_version%%.*}
mesa_major=${mesa_major#*:}
if [ ${#missing[@]} -eq 0 ] && [ -n "$mesa_major" ] && [ "$mesa_major" -ge 24 ]; then
  install_web_test_deps
  echo "install-deps: everything is installed (Mesa $mesa_version)"
  exit 0
fi

if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  uri=$(debian_archive_uri | head -n1)
  if [ -z "$uri" ]; then
    echo "install-deps: no Debian 'bookworm' entry found in /etc/apt/sources.list*; cannot derive bookworm-backports" >&2
    exit 1
  fi
  cat > "$backports_file" <<SRC
Types: deb
URIs: $uri
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  echo "install-deps: enabled bookworm-backports from $uri"
fi

apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Lavapipe with VK_KHR_ray_tracing_pipeline (Mesa >= 24.1) from backports.
apt-get install -y -qq --no-install-recommends -t bookworm-backports mesa-vulkan-drivers

install_web_test_deps
echo "install-deps: done"
