#!/usr/bin/env python3
"""Issue 15's targets for the quotient spaces, measured in one invocation and printed as one
table against their thresholds (docs/benchmarks.md, "Quotient spaces against the Cornell box"):

  paths/s    every scene `geodesic_bench --quotients` samples, at 512², each at its own depth,
             >= 0.5x the Cornell box's paths/s in the same run (the median ratio of five
             paired rounds, each scene's run beside one of the Cornell box; its range beside);
  still 5 %  from a still camera at 512² (`geodesic_bench_walkthrough`), the mirrored
             dodecahedron and the Poincaré sphere reach 5 % estimated error within 30 s (when
             the 60-s still phase ends above 5 %, extrapolated along t^-1/2 and marked ~);
  t(1 %)     time to 1 % true error at 64x64 (`bench/convergence.sh`), every quotient within
             3x the Cornell box's, in paired rounds as for paths/s: in each round every scene's
             run comes right beside one of the Cornell box (before it in even rounds, after it
             in odd ones); the median time, the median ratio and the ratios' range are printed
             (~ where the tool extrapolated the time in most rounds).

  python3 bench/quotient_targets.py [--build DIR] [--device SEL] [--time S] [--ref-time S]
                                    [--rounds R] [--skip still,convergence]

Each figure is the tool's own printed one: this script runs the three tools one after the other
(on a 2-core lavapipe machine about 20 minutes at the default three rounds with the
convergence references cached in BUILD/bench-cache, 30 without) and reads what they print.
The scenes are those geodesic_bench --quotients measures, so that part always runs; --skip
leaves out the others. --device goes to the two binaries that take it; bench/convergence.sh
renders on the default device.
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STILL_SCENES = ["cornell-box", "mirrored-dodecahedron", "poincare-sphere"]


def run(command):
    print("$ " + " ".join(command), file=sys.stderr, flush=True)
    result = subprocess.run(command, cwd=ROOT, stdout=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit(f"quotient_targets: {command[0]} failed ({result.returncode})")
    sys.stderr.write(result.stdout)
    return result.stdout


def paths_per_second(build, device):
    """{scene: (M paths/s, x Cornell, its range)} from geodesic_bench --quotients at 512²."""
    command = [f"{build}/bench/geodesic_bench", "--quotients", "--size", "512", "--spp", "2",
               "--repeat", "5"] + (["--device", device] if device else [])
    rows = {}
    for line in run(command).splitlines():
        fields = line.split()
        if len(fields) == 9 and fields[3].replace(".", "", 1).isdigit():
            rows[fields[0]] = (float(fields[3]), float(fields[7]), fields[8])
    return rows


def still_view(build, device, scene):
    """(seconds to 5 %, extrapolated?) from a still camera at 512²."""
    command = [f"{build}/bench/geodesic_bench_walkthrough", scene, "--width", "512", "--height",
               "512"] + (["--device", device] if device else [])
    out = run(command)
    reached = re.search(r"still -> error < 5%:\s+([\d.]+) s", out)
    if reached:
        return float(reached.group(1)), False
    missed = re.search(r"still -> error < 5%:\s+not in ([\d.]+) s \(([\d.]+) %", out)
    if not missed:
        sys.exit(f"quotient_targets: no still-view figure for {scene}")
    seconds, error = float(missed.group(1)), float(missed.group(2))
    return seconds * (error / 5) ** 2, True


def scene_file(name):
    for path in (f"scenes/{name}.json", f"scenes/catalogue/{name}.json"):
        if os.path.exists(os.path.join(ROOT, path)):
            return path
    sys.exit(f"quotient_targets: no scene file for {name}")


def median(values):
    v = sorted(values)
    return (v[(len(v) - 1) // 2] + v[len(v) // 2]) / 2


def time_to_one_percent(build, names, seconds, ref_seconds, rounds):
    """{scene: (median t(1 %) in s, extrapolated in most rounds?, median x Cornell, range)} at
    64x64, from `rounds` paired rounds: one bench/convergence.sh call per round, its scene list
    the Cornell box beside each quotient in turn, so that a pair's two runs are seconds apart
    and the machine's drift in speed over the minutes of a round stays out of the ratio."""
    others = [n for n in names if n != "cornell-box"]
    seen = {n: [] for n in names}  # (t, extrapolated) per round
    ratios = {n: [] for n in others}
    for r in range(rounds):
        pairs = [("cornell-box", n) if r % 2 == 0 else (n, "cornell-box") for n in others]
        order = [n for pair in pairs for n in pair]
        command = ["bash", "bench/convergence.sh", "--build", build, "--time", str(seconds),
                   "--ref-time", str(ref_seconds)] + [scene_file(n) for n in order]
        rows = []
        for line in run(command).splitlines():
            # scene size ref spp slope (cpu) (spp) t(5%) t(1%) ...;
            # a time is "X s" or "X s (extrap.)"
            m = re.match(r"(\S+)\s+\d+x\d+\s+\d+\s+\d+(?:\s+\S+){3}\s+"
                         r"(?:[\d.e+-]+ s(?: \(extrap\.\))?)\s+([\d.e+-]+) s( \(extrap\.\))?", line)
            if m:
                rows.append((m.group(1), float(m.group(2)), bool(m.group(3))))
        if [row[0] for row in rows] != order:
            sys.exit("quotient_targets: bench/convergence.sh printed other rows than its scenes")
        times = {}
        for name, t, extrapolated in rows:
            seen[name].append((t, extrapolated))
            times.setdefault(name, []).append(t)
        for scene, cornell in zip(others, times["cornell-box"]):  # the k-th pair's Cornell run
            ratios[scene].append(times[scene][0] / cornell)
    result = {}
    for name in names:
        if not seen[name]:
            continue
        t = median([v[0] for v in seen[name]])
        extrapolated = 2 * sum(v[1] for v in seen[name]) > len(seen[name])
        r = ratios.get(name)
        result[name] = (t, extrapolated, median(r), f"{min(r):.2f}-{max(r):.2f}") if r else (
            t, extrapolated, 1.0, "")
    return result


def verdict(ok):
    return "met" if ok else "NOT MET"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--device", default="")
    parser.add_argument("--time", type=float, default=15, help="convergence test run, s")
    parser.add_argument("--ref-time", type=float, default=45, help="convergence reference, s")
    parser.add_argument("--rounds", type=int, default=3, help="convergence's paired rounds")
    parser.add_argument("--skip", default="", help="still and/or convergence, comma-separated")
    args = parser.parse_args()
    skip = set(args.skip.split(","))
    build = os.path.abspath(args.build)

    paths = paths_per_second(build, args.device)
    names = list(paths)
    still = {s: still_view(build, args.device, s) for s in STILL_SCENES} if "still" not in skip else {}
    converge = (time_to_one_percent(build, names, args.time, args.ref_time, args.rounds)
                if "convergence" not in skip else {})

    def mark(value, extrapolated):
        return ("~" if extrapolated else "") + f"{value:.3g} s"

    print(f"\n{'scene':<24} {'M paths/s':>9} {'x Cornell':>9} {'range':>11} {'>= 0.5':>8}   "
          f"{'t(1 %) 64²':>11} {'x Cornell':>9} {'range':>11} {'<= 3':>8}   "
          f"{'still 5 % 512²':>14} {'<= 30 s':>8}")
    for name in names:
        cells = []
        rate, ratio, spread = paths[name]
        cells.append(f"{rate:>9.3f} {ratio:>9.3f} {spread:>11} "
                     f"{'' if name == 'cornell-box' else verdict(ratio >= 0.5):>8}")
        if name in converge:
            t, extrapolated, ratio, spread = converge[name]
            cells.append(f"{mark(t, extrapolated):>11} {ratio:>9.2f} {spread:>11} "
                         f"{'' if name == 'cornell-box' else verdict(ratio <= 3):>8}")
        else:
            cells.append(" " * 42)
        if name in still:
            t, extrapolated = still[name]
            cells.append(f"{mark(t, extrapolated):>14} "
                         f"{'' if name == 'cornell-box' else verdict(t <= 30):>8}")
        print(f"{name:<24} " + "   ".join(cells).rstrip())


if __name__ == "__main__":
    main()
