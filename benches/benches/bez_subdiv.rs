//! bez-subdiv: flattening with each split rule; cubics beside kurbo's `flatten`.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_subdiv::{FlattenOptions, SplitRule, flatten, flatten_fixed_into};
use bezkit_benches::random_curve;
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};

fn rules(c: &mut Criterion) {
    for (name, rule) in [
        ("fixed", SplitRule::Fixed),
        ("flatness", SplitRule::flatness()),
        ("hull", SplitRule::hull_area()),
    ] {
        let mut g = c.benchmark_group(format!("flatten_{name}"));
        for n in [3, 12, 25] {
            let curve = random_curve::<2>(n, 100 + n as u64);
            let options = FlattenOptions {
                rule,
                ..FlattenOptions::default()
            };
            g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
                b.iter(|| flatten(black_box(cv), &options));
            });
        }
        g.finish();
    }
}

/// The same cubic at the same absolute tolerance: ours (eq. (3), ε relative to the curve size)
/// and kurbo's `flatten` (its tolerance is an absolute distance).
fn versus_kurbo(c: &mut Criterion) {
    use kurbo::{BezPath, CubicBez, PathEl};
    let curve = random_curve::<2>(3, 103);
    let p = curve.points();
    let size = bez_subdiv::curve_size(&curve);
    let tol = 1e-5 * size;
    let cubic = CubicBez::new(
        (p[0].x, p[0].y),
        (p[1].x, p[1].y),
        (p[2].x, p[2].y),
        (p[3].x, p[3].y),
    );
    let path = BezPath::from_vec(vec![
        PathEl::MoveTo(cubic.p0),
        PathEl::CurveTo(cubic.p1, cubic.p2, cubic.p3),
    ]);
    let options = FlattenOptions::default();
    let mut g = c.benchmark_group("cubic_flatten_vs_kurbo");
    g.bench_function("bezkit fixed rule", |b| {
        b.iter(|| flatten(black_box(&curve), &options));
    });
    let mut polyline = Vec::new();
    g.bench_function("bezkit fixed rule, flatten_fixed_into", |b| {
        b.iter(|| {
            flatten_fixed_into(black_box(&curve), 1e-5, 40, &mut polyline).map(|s| s.pieces)
        });
    });
    g.bench_function("kurbo flatten", |b| {
        b.iter(|| {
            let mut count = 0usize;
            kurbo::flatten(black_box(&path), tol, |_| count += 1);
            count
        });
    });
    g.finish();
}

/// 64 curves of degree 12: one by one on one thread, and `flatten_batch` with rayon.
fn batch(c: &mut Criterion) {
    let curves = bez_subdiv::cases::random_curves(12, 64, 5);
    let options = FlattenOptions::default();
    let mut g = c.benchmark_group("flatten_64_curves");
    g.bench_function("sequential", |b| {
        b.iter(|| {
            curves
                .iter()
                .map(|cv| flatten(black_box(cv), &options))
                .collect::<Vec<_>>()
        });
    });
    g.bench_function("rayon batch", |b| {
        b.iter(|| bez_subdiv::flatten_batch(black_box(&curves), &options));
    });
    g.finish();
}

criterion_group!(benches, rules, versus_kurbo, batch);
criterion_main!(benches);
