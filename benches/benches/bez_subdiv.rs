//! bez-subdiv: flattening with each split rule; cubics beside kurbo's and lyon_geom's flattening;
//! quadratics beside lyon_geom's; degree 25 per output point.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_core::{BezierCurve, Vector2};
use bez_subdiv::{FlattenOptions, Flattener, Method, SplitRule, flatten, flatten_fixed_into};
use bezkit_benches::random_curve;
use criterion::measurement::WallTime;
use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main,
};

fn rules(c: &mut Criterion) {
    for (name, rule) in [
        ("fixed", SplitRule::Fixed),
        ("flatness", SplitRule::flatness()),
        ("hull", SplitRule::hull_area()),
    ] {
        let mut g = c.benchmark_group(format!("flatten_{name}"));
        for n in [3, 12, 25] {
            let curve = random_curve::<2>(n, 100 + n as u64);
            let options = FlattenOptions::default().with_rule(rule);
            g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
                b.iter(|| flatten(black_box(cv), &options));
            });
        }
        g.finish();
    }
}

/// A flattener of the peer comparisons.
#[derive(Clone, Copy)]
enum Peer {
    Bezkit(Method),
    /// `Method::Fast` fixed at compile time (`Flattener::new`), as a caller writes it.
    Fast,
    /// kurbo's `flatten` of a one-curve path.
    Kurbo,
    /// lyon_geom's `for_each_flattened` (quadratic or cubic segment).
    Lyon,
}

/// The polyline of `curve` at `tol` by `peer` into `out` (cleared first); returns the number of
/// segments.
fn polyline(
    peer: Peer,
    curve: &BezierCurve<2>,
    path: &kurbo::BezPath,
    tol: f64,
    out: &mut Vec<Vector2>,
) -> usize {
    use lyon_geom::{CubicBezierSegment, QuadraticBezierSegment, point};
    out.clear();
    match peer {
        Peer::Bezkit(method) => {
            let flattener = Flattener::new(tol).with_method(method);
            // The benchmarked curves are valid: an error sends no point and counts none.
            let _ = flattener.flatten(curve, |q| out.push(q.point));
        }
        Peer::Fast => {
            let _ = Flattener::new(tol).flatten(curve, |q| out.push(q.point));
        }
        Peer::Kurbo => kurbo::flatten(path, tol, |el| {
            if let kurbo::PathEl::MoveTo(q) | kurbo::PathEl::LineTo(q) = el {
                out.push(Vector2::new(q.x, q.y));
            }
        }),
        Peer::Lyon => {
            let p = curve.points();
            let q = |i: usize| point(p[i].x(), p[i].y());
            out.push(p[0]);
            let mut push = |s: &lyon_geom::LineSegment<f64>| out.push(Vector2::new(s.to.x, s.to.y));
            if p.len() == 3 {
                let segment = QuadraticBezierSegment {
                    from: q(0),
                    ctrl: q(1),
                    to: q(2),
                };
                segment.for_each_flattened(tol, &mut push);
            } else {
                let segment = CubicBezierSegment {
                    from: q(0),
                    ctrl1: q(1),
                    ctrl2: q(2),
                    to: q(3),
                };
                segment.for_each_flattened(tol, &mut push);
            }
        }
    }
    out.len().saturating_sub(1)
}

/// Benchmarks each of `peers` on `curve` (a quadratic or a cubic) at the absolute tolerance
/// `tol` in `g`, named `label/name`, throughput its own segment count; checks that
/// `Method::Fast` and lyon_geom make the same count (Wang's) when both are compared.
fn compare(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    curve: &BezierCurve<2>,
    tol: f64,
    peers: &[(&str, Peer)],
) {
    let Ok(path) = bez_core::curves_to_bez_path(std::slice::from_ref(curve)) else {
        return;
    };
    let mut out = Vec::new();
    let mut wang = Vec::new();
    for &(label, peer) in peers {
        let segments = polyline(peer, curve, &path, tol, &mut out);
        if matches!(peer, Peer::Fast | Peer::Lyon) {
            wang.push(segments);
        }
        g.throughput(Throughput::Elements(segments as u64));
        g.bench_function(BenchmarkId::new(label, name), |b| {
            b.iter(|| polyline(peer, black_box(curve), &path, tol, &mut out));
        });
    }
    assert!(
        wang.windows(2).all(|w| w[0] == w[1]),
        "{name}: Method::Fast's count is lyon_geom's: {wang:?}"
    );
}

/// The peer cubics at the same absolute tolerance (1e-5 × curve size): ours (eq. (3), fixed
/// rule, general and allocation-free path; `Method::Fast`), kurbo's `flatten` and lyon_geom's
/// `for_each_flattened`. Throughput: output segments of each method.
fn versus_peers(c: &mut Criterion) {
    let options = FlattenOptions::default();
    let mut g = c.benchmark_group("cubic_flatten_peers");
    for (name, curve) in bez_subdiv::cases::peer_cubics() {
        let Ok(ours) = flatten(&curve, &options) else {
            continue;
        };
        g.throughput(Throughput::Elements(ours.polyline.len() as u64 - 1));
        g.bench_function(BenchmarkId::new("bezkit flatten, fixed rule", &name), |b| {
            b.iter(|| flatten(black_box(&curve), &options));
        });
        let mut polyline = Vec::new();
        g.bench_function(BenchmarkId::new("bezkit flatten_fixed_into", &name), |b| {
            b.iter(|| {
                flatten_fixed_into(black_box(&curve), 1e-5, 40, &mut polyline).map(|s| s.pieces)
            });
        });
        let tol = 1e-5 * bez_subdiv::curve_size(&curve);
        let peers = [
            ("kurbo flatten", Peer::Kurbo),
            ("bezkit Method::Fast", Peer::Fast),
            ("lyon_geom for_each_flattened", Peer::Lyon),
        ];
        compare(&mut g, &name, &curve, tol, &peers);
    }
    g.finish();
}

/// The `Flattener` modes beside kurbo's `flatten` and lyon_geom's `for_each_flattened` on the
/// peer cubics at the same absolute tolerance, 1e-3 × the curve's size (the standing
/// comparison's tolerance). Throughput: output segments of each method.
fn flattener_versus_peers(c: &mut Criterion) {
    let mut g = c.benchmark_group("flattener_vs_peers");
    let peers = [
        ("bezkit Optimal", Peer::Bezkit(Method::Optimal)),
        ("bezkit Fast", Peer::Fast),
        ("kurbo flatten", Peer::Kurbo),
        ("lyon_geom for_each_flattened", Peer::Lyon),
    ];
    for (name, curve) in bez_subdiv::cases::peer_cubics() {
        let tol = 1e-3 * bez_subdiv::curve_size(&curve);
        compare(&mut g, &name, &curve, tol, &peers);
    }
    g.finish();
}

/// `Method::Fast` beside lyon_geom's quadratic `for_each_flattened` (the same uniform Wang
/// count) on three seeded random quadratics at 1e-3 and 1e-5 × the curve's size; the counts are
/// asserted equal. Throughput: output segments.
fn quadratics_versus_lyon(c: &mut Criterion) {
    let mut g = c.benchmark_group("quadratic_flatten_vs_lyon");
    let peers = [
        ("bezkit Method::Fast", Peer::Fast),
        ("lyon_geom for_each_flattened", Peer::Lyon),
    ];
    for seed in 1..=3_u64 {
        let curve = random_curve::<2>(2, 500 + seed);
        for rel in [1e-3, 1e-5] {
            let tol = rel * bez_subdiv::curve_size(&curve);
            compare(
                &mut g,
                &format!("quadratic {seed} at {rel:e}"),
                &curve,
                tol,
                &peers,
            );
        }
    }
    g.finish();
}

/// One degree-25 curve, each mode, throughput in output points (target: < 0.3 µs per point).
fn degree_25_per_point(c: &mut Criterion) {
    let Some(curve) = bez_subdiv::cases::degree25_curve() else {
        return;
    };
    let options = FlattenOptions::default();
    let tol = options.tolerance * bez_subdiv::curve_size(&curve);
    let mut g = c.benchmark_group("flatten_degree25_per_point");
    let count = |r: Result<usize, bez_subdiv::SubdivError>| r.map_or(1, |k| k as u64);
    g.throughput(Throughput::Elements(count(
        flatten(&curve, &options).map(|f| f.polyline.len()),
    )));
    g.bench_function("fixed rule, flatten", |b| {
        b.iter(|| flatten(black_box(&curve), &options));
    });
    let mut polyline = Vec::new();
    g.bench_function("fixed rule, flatten_fixed_into", |b| {
        b.iter(|| flatten_fixed_into(black_box(&curve), 1e-5, 40, &mut polyline).map(|s| s.pieces));
    });
    for (label, method) in [
        ("guaranteed", Method::Halving),
        ("local Wang", Method::LocalWang),
        ("near-optimal", Method::Optimal),
    ] {
        let flattener = Flattener::new(tol).with_method(method);
        let mut points = Vec::new();
        g.throughput(Throughput::Elements(count(
            flattener.flatten(&curve, |p| points.push(p.point)),
        )));
        g.bench_function(label, |b| {
            b.iter(|| {
                points.clear();
                flattener.flatten(black_box(&curve), |p| points.push(p.point))
            });
        });
    }
    g.finish();
}

/// 64 curves of degree 12 with `Method::Optimal`: one by one on one thread, and
/// `Flattener::flatten_batch` with rayon.
fn batch(c: &mut Criterion) {
    let curves = bez_subdiv::cases::random_curves(12, 64, 5);
    let flattener = Flattener::new(1e-3).with_method(Method::Optimal);
    let mut g = c.benchmark_group("flatten_64_curves");
    g.bench_function("sequential", |b| {
        b.iter(|| {
            curves
                .iter()
                .map(|cv| flattener.flatten_to_vec(black_box(cv)))
                .collect::<Vec<_>>()
        });
    });
    g.bench_function("rayon batch", |b| {
        b.iter(|| flattener.flatten_batch(black_box(&curves)));
    });
    g.finish();
}

criterion_group!(
    benches,
    rules,
    versus_peers,
    flattener_versus_peers,
    quadratics_versus_lyon,
    degree_25_per_point,
    batch
);
criterion_main!(benches);
