"""Smoothing cubic B-spline fits (SciPy's splprep) of subdiv-fit's test shapes.

The baseline a user would reach for: `splprep` with the smoothing factor s chosen, by bisection,
as the largest value whose two-sided max error (data to dense curve samples, curve samples to the
data polyline, the measure of subdiv-fit's tables) is at most the tolerance 0.01.
The shapes are re-created from the formulas documented in `subdiv_fit::cases`.
Run with `benches/scipy/run.sh`, which installs NumPy and SciPy into a private virtual
environment; `cargo test` never needs this.
"""

import math
import sys
import time

import numpy as np
from scipy.interpolate import splev, splprep

TOL = 0.01


def normalize(p):
    lo = p.min(axis=0)
    side = (p.max(axis=0) - lo).max()
    return (p - lo) / side


def closed_petals(density=1):
    n = 64 * density
    t = 2 * math.pi * np.arange(n) / n
    r = 1 + 0.4 * np.abs(np.sin(2 * t)) + 0.1 * np.cos(5 * t + 0.3)
    return normalize(np.stack([r * np.cos(t), r * np.sin(t)], axis=1))


def open_wave(density=1):
    m = 65 * density
    x = np.arange(m + 1) / m
    y = 0.2 * np.sin(5 * math.pi * x) + 0.8 * (np.abs(x - 22 / 65) + np.abs(x - 44 / 65))
    return normalize(np.stack([x, y], axis=1))


def point_polyline(points, poly):
    """Distance from each point to the polyline (vectorized over segments)."""
    a = poly[:-1][None, :, :]
    e = (poly[1:] - poly[:-1])[None, :, :]
    q = points[:, None, :]
    len2 = np.maximum((e * e).sum(-1), 1e-300)
    s = np.clip(((q - a) * e).sum(-1) / len2, 0, 1)
    d = np.linalg.norm(q - (a + e * s[..., None]), axis=-1)
    return d.min(axis=1)


def two_sided(tck, data, closed):
    u = np.linspace(0, 1, 64 * len(data) + 1)
    samples = np.stack(splev(u, tck), axis=1)
    poly = np.vstack([data, data[:1]]) if closed else data
    return max(point_polyline(data, samples).max(), point_polyline(samples, poly).max())


def fit(data, closed, s):
    pts = np.vstack([data, data[:1]]) if closed else data
    tck, _ = splprep([pts[:, 0], pts[:, 1]], s=s, k=3, per=int(closed), quiet=2)
    return tck


def main():
    print("| shape | points | smoothing s | B-spline control points | two-sided max error | time (ms) |")
    print("|---|---|---|---|---|---|")
    for name, make, closed in [("closed petals", closed_petals, True), ("open wave", open_wave, False)]:
        for density in (1, 10):
            data = make(density)
            lo, hi = 1e-12, 1.0
            for _ in range(50):
                mid = math.sqrt(lo * hi)
                if two_sided(fit(data, closed, mid), data, closed) <= TOL:
                    lo = mid
                else:
                    hi = mid
            start = time.perf_counter()
            tck = fit(data, closed, lo)
            ms = (time.perf_counter() - start) * 1e3
            coefs = len(tck[1][0]) - (3 if closed else 0)
            err = two_sided(tck, data, closed)
            print(f"| {name} | {len(data)} | {lo:.3e} | {coefs} | {err:.5f} | {ms:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
