#!/usr/bin/env python3
"""A Coxeter orthoscheme's scene, and the same space traced in the cell of its largest vertex.

    python3 bench/stabiliser_unfold.py GENERATORS.gen SCENE.json OUT_DIR

For issue 15's exact unfolding: a reflection group's chamber (the orthoscheme, SCENE's domain)
has vertices fixed by finite subgroups; the Dirichlet cell about the vertex with the largest one
(for [5,3,4], order 120: the right-angled dodecahedron) is the union of that many chambers, with
the content copied by the subgroup. The same set of spheres in H3, crossed by a geodesic about
a fourth as often. Writes into OUT_DIR:
- plain.json: SCENE without its domain edges (tubes along the chamber's inner edges have no
  counterpart in the larger cell), the camera as a pose;
- unfolded.json: the larger cell as "matrices" (its face reflections, conjugates of the one
  mirror that misses the vertex), everything moved so that the vertex is the origin, each
  sphere copied by the vertex's subgroup, and the light left single: its copies would be as
  many lights, each walked by light sampling, so one light bounds what the geometry costs.
Then, e.g.: build/bench/geodesic_bench --quotients OUT/plain.json OUT/unfolded.json --size 256.
"""
import itertools
import json
import math
import os
import sys

SIGN = (1, 1, 1, -1)  # the Lorentz form x^2 + y^2 + z^2 - w^2
IDENTITY = [[float(i == j) for j in range(4)] for i in range(4)]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def apply(a, v):
    return [sum(a[i][k] * v[k] for k in range(4)) for i in range(4)]


def inverse(a):  # of an O(3,1) matrix: J a^T J
    return [[SIGN[i] * a[j][i] * SIGN[j] for j in range(4)] for i in range(4)]


def same(a, b):
    return all(abs(a[i][j] - b[i][j]) < 1e-6 for i in range(4) for j in range(4))


def read_gen(path):  # Curved Spaces' row-vector matrices, transposed to act on columns
    rows = [line.split() for line in open(path, encoding="utf-8-sig")
            if line.strip() and not line.lstrip().startswith("#")]
    return [[list(r) for r in zip(*[[float(x) for x in row] for row in rows[i:i + 4]])]
            for i in range(0, len(rows), 4)]


def mirror_normal(r):  # r - 1 = -2 n n^T J / <n, n>: its largest column is along n
    j = max(range(4), key=lambda c: sum((r[i][c] - (i == c)) ** 2 for i in range(4)))
    return [r[i][j] - (i == j) for i in range(4)]


def cross(a, b, c):  # a vector Euclidean-orthogonal to a, b and c
    out = []
    for k in range(4):
        m = [[v[j] for j in range(4) if j != k] for v in (a, b, c)]
        det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
               - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
               + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
        out.append((-1) ** k * det)
    return out


def closure(generators, limit=5000):
    elements, frontier = [IDENTITY], [IDENTITY]
    while frontier and len(elements) < limit:
        grown = []
        for e in frontier:
            for g in generators:
                p = mul(g, e)
                if not any(same(p, q) for q in elements):
                    elements.append(p)
                    grown.append(p)
        frontier = grown
    return elements


def to_model(x):  # exponential coordinates -> hyperboloid
    d = math.sqrt(sum(c * c for c in x))
    s = math.sinh(d) / d if d > 0 else 1.0
    return [x[0] * s, x[1] * s, x[2] * s, math.cosh(d)]


def to_exponential(p):
    r = math.sqrt(p[0] ** 2 + p[1] ** 2 + p[2] ** 2)
    return [0.0, 0.0, 0.0] if r < 1e-15 else [c * math.asinh(r) / r for c in p[:3]]


def translation(p):  # the transvection taking the origin to the hyperboloid point p
    r = math.sqrt(p[0] ** 2 + p[1] ** 2 + p[2] ** 2)
    u = [c / r for c in p[:3]]
    m = [[(i == j) + (p[3] - 1) * u[i] * u[j] for j in range(3)] + [r * u[i]] for i in range(3)]
    return m + [[r * c for c in u] + [p[3]]]


def largest_vertex(reflections):
    """(order, the three mirrors through it, the vertex) of the chamber's largest stabiliser."""
    normals = [mirror_normal(r) for r in reflections]
    best = None
    for three in itertools.combinations(range(len(reflections)), 3):
        c = cross(*[normals[i] for i in three])
        v = [c[0], c[1], c[2], -c[3]]  # Lorentz-orthogonal to the three normals
        q = sum(SIGN[i] * v[i] * v[i] for i in range(4))
        if q >= 0:
            continue  # an ideal or ultra-ideal vertex
        v = [x / math.sqrt(-q) * (1 if v[3] > 0 else -1) for x in v]
        order = len(closure([reflections[i] for i in three]))
        print(f"vertex of mirrors {three}: stabiliser order {order}, "
              f"{math.acosh(v[3]):.4f} from the origin", file=sys.stderr)
        if best is None or order > best[0]:
            best = (order, three, v)
    return best


def main():
    gen_path, scene_path, out = sys.argv[1:4]
    reflections = read_gen(gen_path)
    scene = json.load(open(scene_path))
    _, three, vertex = largest_vertex(reflections)
    stabiliser = closure([reflections[i] for i in three])
    (missing,) = [i for i in range(len(reflections)) if i not in three]
    faces = []
    for s in stabiliser:
        f = mul(mul(s, reflections[missing]), inverse(s))
        if not any(same(f, g) for g in faces):
            faces.append(f)
    to_vertex = translation([-vertex[0], -vertex[1], -vertex[2], vertex[3]])  # vertex -> origin
    from_vertex = inverse(to_vertex)
    print(f"stabiliser {len(stabiliser)}, cell of {len(faces)} faces", file=sys.stderr)

    def moved(x, g):
        return to_exponential(apply(g, to_model(x)))

    plain = json.loads(json.dumps(scene))
    plain["manifold"]["file"] = os.path.abspath(gen_path)
    plain["objects"] = [o for o in scene["objects"] if o["type"] != "domain_edges"]
    if any(o["type"] != "sphere" for o in plain["objects"]):
        sys.exit("stabiliser_unfold.py: copies only spheres (and drops domain edges)")
    plain["camera"] = {"pose": IDENTITY, "fov_y": scene["camera"]["fov_y"]}
    unfolded = json.loads(json.dumps(plain))
    unfolded["manifold"] = dict(plain["manifold"], type="generators",
                                matrices=[mul(mul(to_vertex, f), from_vertex) for f in faces])
    del unfolded["manifold"]["file"]
    unfolded["camera"]["pose"] = to_vertex
    unfolded["objects"] = [dict(o, center=moved(o["center"], mul(to_vertex, s)))
                           for o in plain["objects"] for s in stabiliser]
    unfolded["lights"] = [dict(l, position=moved(l["position"], to_vertex))
                          for l in scene["lights"]]
    os.makedirs(out, exist_ok=True)
    for name, doc in (("plain", plain), ("unfolded", unfolded)):
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(doc, f, indent=1)


if __name__ == "__main__":
    main()
