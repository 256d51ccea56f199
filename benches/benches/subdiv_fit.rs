//! subdiv-fit: exact evaluation, fitting of the test shapes, growth with the number of points, a
//! noisy 100,000-point circle, and kurbo's curve simplification on the same polylines.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use kurbo::simplify::{SimplifyOptions, simplify_bezpath};
use kurbo::{BezPath, Point};
use subdiv_fit::cases::{closed_petals, open_wave};
use subdiv_fit::{FitMode, FitOptions, SubdivCurve, Vector2, fit};

fn eval(c: &mut Criterion) {
    let data = closed_petals(1);
    let curve = fit(&data, subdiv_fit::Closure::Closed, &FitOptions::new(0.01))
        .map(|f| f.curve)
        .unwrap_or_else(|_| {
            SubdivCurve::smooth(data.clone(), subdiv_fit::Closure::Closed)
                .unwrap_or_else(|_| unreachable!())
        });
    let segs = curve.segment_count() as f64;
    let params: Vec<f64> = (0..1000).map(|k| k as f64 * segs / 999.0).collect();
    let mut out = Vec::with_capacity(1000);
    c.bench_function("subdiv_eval_1000_points", |b| {
        b.iter(|| curve.eval_many(black_box(&params), &mut out));
    });
}

fn fitting(c: &mut Criterion) {
    let mut g = c.benchmark_group("subdiv_fit_closed_petals");
    for density in [1, 10, 100] {
        let data = closed_petals(density);
        g.bench_with_input(BenchmarkId::from_parameter(data.len()), &data, |b, d| {
            b.iter(|| {
                fit(
                    black_box(d),
                    subdiv_fit::Closure::Closed,
                    &FitOptions::new(0.01),
                )
            });
        });
    }
    g.finish();
    let mut g = c.benchmark_group("subdiv_fit_open_wave");
    for density in [1, 10, 100] {
        let data = open_wave(density);
        g.bench_with_input(BenchmarkId::from_parameter(data.len()), &data, |b, d| {
            b.iter(|| {
                fit(
                    black_box(d),
                    subdiv_fit::Closure::Open,
                    &FitOptions::new(0.01),
                )
            });
        });
    }
    g.finish();
}

/// 100,000 points of the unit circle with uniform radial noise of ±2.5e-4 (a deterministic
/// generator), fitted at tolerance 1e-3: the least-squares mode's banded solve and the
/// scale-aware initial points on dense noisy data.
fn noisy_circle(c: &mut Criterion) {
    let n = 100_000;
    let mut state: u64 = 7;
    let data: Vec<Vector2> = (0..n)
        .map(|k| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let noise = 2.0 * ((state >> 11) as f64 / (1u64 << 53) as f64) - 1.0;
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            let r = 1.0 + 2.5e-4 * noise;
            Vector2::new(r * t.cos(), r * t.sin())
        })
        .collect();
    let mut g = c.benchmark_group("subdiv_fit_noisy_circle_100k");
    g.sample_size(10);
    for mode in [FitMode::Interpolate, FitMode::LeastSquares] {
        let opts = FitOptions::new(1e-3).with_mode(mode);
        g.bench_function(format!("{mode:?}"), |b| {
            b.iter(|| fit(black_box(&data), subdiv_fit::Closure::Closed, &opts));
        });
    }
    g.finish();
}

fn polyline(data: &[Vector2], closed: bool) -> BezPath {
    let mut p = BezPath::new();
    for (i, v) in data.iter().enumerate() {
        let q = Point::new(v.x(), v.y());
        if i == 0 {
            p.move_to(q);
        } else {
            p.line_to(q);
        }
    }
    if closed {
        p.close_path();
    }
    p
}

fn kurbo_simplify(c: &mut Criterion) {
    let mut g = c.benchmark_group("kurbo_simplify_closed_petals");
    for density in [1, 10, 100] {
        let path = polyline(&closed_petals(density), true);
        g.bench_with_input(BenchmarkId::from_parameter(64 * density), &path, |b, p| {
            b.iter(|| simplify_bezpath(black_box(p.iter()), 0.01, &SimplifyOptions::default()));
        });
    }
    g.finish();
}

criterion_group!(benches, eval, fitting, noisy_circle, kurbo_simplify);
criterion_main!(benches);
