#!/usr/bin/env python3
"""Where lavapipe's machine code for a scene's shader spends its time.

    python3 bench/jit_profile.py SCENE.json [--size N] [--spp N] [--blocks K] [--show J]

Renders SCENE with `geodesic render` on one lavapipe thread under `perf record`, with Mesa's
shader cache off and GALLIVM_DEBUG=asm, so that llvmpipe prints the disassembly of the compute
shader it compiles (`cs_variant`, then the coroutine `cs_co_variant` that holds the shader's
body). The JIT code has no symbols: the samples are mapped to the listing by the largest
anonymous executable mapping of the process, and the offset of `cs_co_variant` in it is the one
at which the most samples land on instruction boundaries (the share printed: near 100 % when the
mapping is right). Prints the share of samples in each run of 32 instructions, the K largest
(default 25), and the instructions of the J largest (default 0) with their sample counts.

Samples outside the JIT code (LLVM compiling the shader, the driver, the host) are left out:
the shares are of the shader's own time. Needs `perf` (Debian's linux-perf) and a build
(scripts/build.sh). A development tool: benchmarks measure speed (bench/run.sh), this shows
where it goes.
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLOCK = 32


def record(args, work):
    env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true", GALLIVM_DEBUG="asm",
               LP_NUM_THREADS="1")
    data = os.path.join(work, "perf.data")
    with open(os.path.join(work, "asm.txt"), "w") as listing:
        subprocess.run(["perf", "record", "-q", "-o", data, os.path.join(ROOT, "build", "geodesic"),
                        "render", args.scene, "--width", str(args.size), "--height",
                        str(args.size), "--spp", str(args.spp), "-o",
                        os.path.join(work, "out.png")],
                       env=env, stdout=subprocess.DEVNULL, stderr=listing, check=True)
    return subprocess.run(["perf", "script", "-i", data, "--show-mmap-events", "-F", "ip,dso"],
                          capture_output=True, text=True, check=True).stdout


def jit_mapping(script):
    """The largest anonymous executable mapping: (start, length)."""
    best = (0, 0)
    for start, length in re.findall(r"\[(0x[0-9a-f]+)\((0x[0-9a-f]+)\) @ [^\]]*\]: r-xp //anon",
                                    script):
        best = max(best, (int(length, 16), int(start, 16)))
    return best[1], best[0]


def listing_of(path, name="cs_co_variant"):
    """The (offset, instruction) pairs of the last function called `name` in the listing."""
    functions, current = {}, None
    for line in open(path, errors="replace"):
        header = re.match(r"^([A-Za-z_.]+):$", line)
        if header:
            current = header.group(1)
            functions[current] = []
            continue
        instruction = re.match(r"^\s+([0-9a-f]+):\s+(.*)$", line)
        if instruction and current:
            functions[current].append((int(instruction.group(1), 16), instruction.group(2)))
    return functions.get(name, [])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=8)
    parser.add_argument("--blocks", type=int, default=25)
    parser.add_argument("--show", type=int, default=0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        script = record(args, work)
        start, length = jit_mapping(script)
        body = listing_of(os.path.join(work, "asm.txt"))
    if not length or not body:
        sys.exit("jit_profile: no JIT mapping or no cs_co_variant listing (is GALLIVM_DEBUG "
                 "honoured by this Mesa?)")
    # Samples per offset into the mapping, counted once for the search over shifts below.
    samples = collections.Counter(
        int(ip, 16) - start for ip, dso in re.findall(r"^\s*([0-9a-f]+) \((.*)\)$", script, re.M)
        if dso.startswith("/tmp/perf-") or dso.startswith("[JIT]"))
    index = {offset: i for i, (offset, _) in enumerate(body)}

    def landing(shift):
        return sum(n for o, n in samples.items() if o - shift in index)

    shift = max(range(0, min(length, 1 << 16), 16), key=landing)
    counts = collections.Counter()
    for o, n in samples.items():
        if o - shift in index:
            counts[index[o - shift]] += n
    landed = sum(counts.values())
    total = sum(samples.values())
    print(f"{args.scene}: {total} samples in JIT code, {100 * landed / max(1, total):.1f} % "
          f"on instruction boundaries of cs_co_variant (at +{shift:#x}; {len(body)} instructions)")
    blocks = collections.Counter()
    for i, n in counts.items():
        blocks[i // BLOCK] += n
    print(f"share of the shader's samples per {BLOCK} instructions, largest first:")
    for rank, (block, n) in enumerate(blocks.most_common(args.blocks)):
        first = block * BLOCK
        print(f"  {100 * n / landed:5.1f} %  instructions {first}-{first + BLOCK - 1} "
              f"(offset {body[first][0]:#x})")
        if rank < args.show:
            for i in range(first, min(first + BLOCK, len(body))):
                print(f"      {body[i][0]:6x} {counts.get(i, ''):>5} {body[i][1]}")


if __name__ == "__main__":
    main()
