# Sourced by the deploy tests: podman as it works on these machines. crun fails on a kernel with
# hybrid cgroups, so runc; the default ulimits exceed the hard limits, so explicit ones.
# `podman_ok` says whether the engine can start a container at all (the tests skip otherwise).
PODMAN_ULIMITS=(--ulimit nofile=20000:20000 --ulimit nproc=32768:32768)
PODMAN_RUN_OPTS=(--runtime runc "${PODMAN_ULIMITS[@]}")
podman() { command podman --runtime runc "$@"; }
podman_ok() {
  command -v podman >/dev/null 2>&1 || { echo "podman is not installed"; return 1; }
  local out
  out=$(timeout 60 "$(type -P podman)" --runtime runc info --format '{{.Host.OCIRuntime.Name}}' 2>&1) ||
    { echo "podman info failed: ${out:0:300}"; return 1; }
}
