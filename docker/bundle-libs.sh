#!/usr/bin/env bash
# Copies the shared libraries a binary loads (its ldd closure, less the C and C++ runtimes every
# Debian image has) into DIR, for the image's runtime stage. Installing their packages instead
# brings their package dependencies (e.g. assimp's), which the daemon never loads
# (docker/README.md).
#   bundle-libs.sh BINARY DIR
set -euo pipefail
binary=${1:?usage: bundle-libs.sh BINARY DIR} dir=${2:?usage: bundle-libs.sh BINARY DIR}
mkdir -p "$dir"
missing=$(ldd "$binary" | awk '/not found/ { print $1 }')
[ -z "$missing" ] || { echo "bundle-libs: $binary needs missing libraries: $missing" >&2; exit 1; }
ldd "$binary" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' |
  grep -Ev '/(libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+|ld-linux-x86-64)\.so' |
  while read -r lib; do cp -L "$lib" "$dir/"; done
echo "bundle-libs: $(ls "$dir" | wc -l) libraries, $(du -sh "$dir" | cut -f1)"
