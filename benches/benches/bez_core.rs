//! bez-core: evaluation, splitting, elevation and surface evaluation.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_core::{de_casteljau_halve, de_casteljau_split};
use bezkit_benches::{random_curve, uniform_parameters};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};

fn eval(c: &mut Criterion) {
    let mut g = c.benchmark_group("eval_single");
    for n in [3, 12, 25, 49] {
        let curve = random_curve::<2>(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
            b.iter(|| cv.eval(black_box(0.37)));
        });
    }
    g.finish();
    let mut g = c.benchmark_group("eval_1000_points");
    let ts = uniform_parameters(1000);
    for n in [3, 12, 25, 49, 100] {
        let curve = random_curve::<2>(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
            let mut out = Vec::with_capacity(1000);
            b.iter(|| {
                out.clear();
                cv.eval_many(black_box(&ts), &mut out)
            });
        });
    }
    g.finish();
}

fn split_and_elevate(c: &mut Criterion) {
    let mut g = c.benchmark_group("split");
    for n in [3, 12, 25, 49] {
        let curve = random_curve::<2>(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
            b.iter(|| cv.split(black_box(0.43)));
        });
    }
    g.finish();
    // The slice kernels at t = ½: de Casteljau's averages against pairwise sums.
    let mut g = c.benchmark_group("split_at_one_half");
    for n in [3, 12, 25, 49] {
        let curve = random_curve::<2>(n, n as u64);
        let (mut left, mut right) = (curve.points().to_vec(), curve.points().to_vec());
        g.bench_function(BenchmarkId::new("de_casteljau_split", n), |b| {
            b.iter(|| de_casteljau_split(black_box(curve.points()), 0.5, &mut left, &mut right));
        });
        g.bench_function(BenchmarkId::new("de_casteljau_halve", n), |b| {
            b.iter(|| de_casteljau_halve(black_box(curve.points()), &mut left, &mut right));
        });
    }
    g.finish();
    let mut g = c.benchmark_group("elevate_by_1");
    for n in [3, 12, 25, 49] {
        let curve = random_curve::<2>(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
            b.iter(|| cv.elevate(black_box(1)));
        });
    }
    g.finish();
}

/// Cubic evaluation and split side by side with kurbo's `CubicBez` on the same control points.
fn versus_kurbo(c: &mut Criterion) {
    use bez_core::{Vector, de_casteljau_split};
    use kurbo::{CubicBez, ParamCurve};
    let ours = random_curve::<2>(3, 3);
    let p = ours.points();
    let Ok(theirs) = CubicBez::try_from(&ours) else {
        return;
    };
    let mut g = c.benchmark_group("cubic_vs_kurbo");
    g.bench_function("bezkit eval", |b| b.iter(|| ours.eval(black_box(0.37))));
    g.bench_function("bezkit eval_clamped", |b| {
        b.iter(|| ours.eval_clamped(black_box(0.37)));
    });
    g.bench_function("bezkit eval (slice kernel)", |b| {
        b.iter(|| bez_core::de_casteljau(black_box(p), black_box(0.37)));
    });
    g.bench_function("kurbo eval", |b| b.iter(|| theirs.eval(black_box(0.37))));
    g.bench_function("bezkit split", |b| b.iter(|| ours.split(black_box(0.37))));
    let mut left = [Vector::<2>::zeros(); 4];
    let mut right = [Vector::<2>::zeros(); 4];
    g.bench_function("bezkit split (slice kernel)", |b| {
        b.iter(|| de_casteljau_split(black_box(p), black_box(0.37), &mut left, &mut right));
    });
    g.bench_function("kurbo split (two subsegments)", |b| {
        b.iter(|| {
            let t = black_box(0.37);
            (theirs.subsegment(0.0..t), theirs.subsegment(t..1.0))
        });
    });
    g.finish();
}

fn surface(c: &mut Criterion) {
    use bez_core::{BezierSurface, Vector};
    let pts: Vec<Vector<3>> = (0..36)
        .map(|k| {
            let (i, j) = ((k / 6) as f64, (k % 6) as f64);
            Vector::<3>::new(i, j, (0.7 * i - 0.3 * j).sin())
        })
        .collect();
    let s =
        BezierSurface::from_flat(5, 5, pts).unwrap_or_else(|_| unreachable!("36 finite points"));
    c.bench_function("surface_eval_biquintic", |b| {
        b.iter(|| s.eval(black_box(0.3), black_box(0.6)));
    });
}

criterion_group!(benches, eval, split_and_elevate, versus_kurbo, surface);
criterion_main!(benches);
