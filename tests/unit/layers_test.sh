#!/usr/bin/env bash
# The build's layers (CMakeLists.txt): each layer compiles against an include root that holds
# its own folder and those below it only. For every layer: a header of its own folder and of
# the layer below compiles there, and a header of the layer above does not ("No such file").
#   layers_test.sh BUILD_DIR CXX
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: layers_test.sh BUILD_DIR CXX} cxx=${2:?}
layers=(geometry scene prepare device service jobs net cli)
declare -A folder=([geometry]=geometry [scene]=scene [prepare]=render/prepare
                   [device]=render/device [service]=render/service [jobs]=jobs [net]=net [cli]=cli)
compiles() {  # layer header
  echo "#include \"$2\"" | "$cxx" -std=c++20 -fsyntax-only -I"$build/layers/$1" \
    -x c++ - 2>"$build/layers/last.err"
}
# A header of each folder that includes nothing of the layers above it, and little else: the
# include roots are what is checked, and headers that pull in Beast or Vulkan make this check
# 47 s of compiling instead of 13.
declare -A header=([geometry]=geometry/vec.h [scene]=scene/text_chars.h
                   [prepare]=render/prepare/image.h [device]=render/device/fault_injection.h
                   [service]=render/service/render_service.h [jobs]=jobs/subprocess.h
                   [net]=net/openapi.h [cli]=cli/progress_bar.h)
for i in "${!layers[@]}"; do
  layer=${layers[$i]}
  [ -d "$build/layers/$layer" ] || { echo "layers: no include root for $layer" >&2; exit 1; }
  compiles "$layer" "${header[$layer]}" ||
    { cat "$build/layers/last.err" >&2; echo "layers: $layer cannot include its own ${header[$layer]}" >&2; exit 1; }
  if [ "$i" -gt 0 ]; then
    below=${layers[$((i - 1))]}
    compiles "$layer" "${header[$below]}" ||
      { cat "$build/layers/last.err" >&2; echo "layers: $layer cannot include ${header[$below]}" >&2; exit 1; }
  fi
  if [ "$i" -lt $(( ${#layers[@]} - 1 )) ]; then
    above=${layers[$((i + 1))]}
    if compiles "$layer" "${header[$above]}"; then
      echo "layers: $layer includes ${header[$above]} of the layer above it" >&2; exit 1
    fi
    # GCC: "scene/scene.h: No such file or directory"; clang: "'scene/scene.h' file not found".
    grep -q -E "${header[$above]}(: No such file|' file not found)" "$build/layers/last.err" ||
      { cat "$build/layers/last.err" >&2; echo "layers: $layer failed on ${header[$above]} for another reason" >&2; exit 1; }
  fi
done
# And the sources as they are: no file includes a layer above its own.
for i in "${!layers[@]}"; do
  for above in "${layers[@]:$((i + 1))}"; do
    if grep -rn "#include \"${folder[$above]}/" "$repo/server/${folder[${layers[$i]}]}"; then
      echo "layers: server/${folder[${layers[$i]}]} includes ${folder[$above]}/" >&2; exit 1
    fi
  done
done
echo "layers: ${layers[*]}: each sees its own folder and those below only"
