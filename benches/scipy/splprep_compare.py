"""Smoothing cubic B-spline fits (SciPy's splprep) of subdiv-fit's test shapes.

The baseline a user would reach for: `splprep` (cubic, periodic for closed data) with the
smoothing factor s chosen, by bisection, as the largest value whose two-sided max error (data to
dense curve samples, curve samples to the data polyline, the measure of subdiv-fit's tables) is at
most the tolerance.

Run by `cargo xtask scipy`, which installs NumPy and SciPy into a private virtual environment,
writes the shapes (from `subdiv_fit::cases`) as JSON, runs this script with
`python splprep_compare.py SHAPES.json TOLERANCE REPETITIONS`, and reads the JSON it prints:
one object per shape with the smoothing factor, the number of B-spline control points, the
two-sided error and the median time of one `splprep` call at that smoothing factor.
`cargo test` and `cargo xtask tables` never need this.
"""

import json
import math
import statistics
import sys
import time

import numpy as np
from scipy.interpolate import splev, splprep
from scipy.spatial import cKDTree


def point_polyline(points, poly, candidates=8):
    """Distance from each point to the polyline: exact distances to the segments next to the
    `candidates` nearest polyline vertices (a KD-tree query), which holds the nearest segment for
    polylines whose segments are short against the distances of interest, as here."""
    tree = cKDTree(poly)
    k = min(candidates, len(poly))
    _, idx = tree.query(points, k=k)
    idx = idx.reshape(len(points), k)
    best = np.full(len(points), np.inf)
    cand = np.concatenate([idx - 1, idx], axis=1).clip(0, len(poly) - 2)
    for c in range(cand.shape[1]):
        a = poly[cand[:, c]]
        e = poly[cand[:, c] + 1] - a
        len2 = np.maximum((e * e).sum(-1), 1e-300)
        t = np.clip(((points - a) * e).sum(-1) / len2, 0, 1)
        best = np.minimum(best, np.linalg.norm(points - (a + e * t[:, None]), axis=-1))
    return best


def two_sided(tck, data, closed):
    """Data to dense curve samples (64 per knot span, the sampling of the Rust side), and the
    samples to the data polyline."""
    knots = np.unique(tck[0][3:-3])
    u = np.concatenate(
        [np.linspace(a, b, 64, endpoint=False) for a, b in zip(knots[:-1], knots[1:])] + [knots[-1:]]
    )
    samples = np.stack(splev(u, tck), axis=1)
    poly = np.vstack([data, data[:1]]) if closed else data
    d2c = point_polyline(data, samples).max()
    c2d = point_polyline(samples, poly).max()
    return max(d2c, c2d)


def fit(data, closed, s):
    pts = np.vstack([data, data[:1]]) if closed else data
    tck, _ = splprep([pts[:, 0], pts[:, 1]], s=s, k=3, per=int(closed), quiet=2)
    return tck


def compare(shape, tol, reps):
    data = np.asarray(shape["points"], dtype=float)
    closed = shape["closed"]
    lo, hi = 1e-12, 1.0
    for _ in range(50):
        mid = math.sqrt(lo * hi)
        if two_sided(fit(data, closed, mid), data, closed) <= tol:
            lo = mid
        else:
            hi = mid
    times = []
    for _ in range(max(reps, 1)):
        start = time.perf_counter()
        tck = fit(data, closed, lo)
        times.append((time.perf_counter() - start) * 1e3)
    return {
        "shape": shape["name"],
        "density": shape["density"],
        "points": len(data),
        "smoothing": lo,
        # A periodic fit repeats its first 3 coefficients at the end.
        "control_points": len(tck[1][0]) - (3 if closed else 0),
        "error": float(two_sided(tck, data, closed)),
        "time_ms": statistics.median(times),
    }


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as f:
        shapes = json.load(f)
    tol, reps = float(argv[2]), int(argv[3])
    json.dump([compare(s, tol, reps) for s in shapes], sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
