//! bez-subdiv: flattening with each split rule; cubics beside kurbo's and lyon_geom's flattening;
//! quadratics beside lyon_geom's; degree 25 per output point.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_subdiv::{FlattenOptions, Flattener, Method, SplitRule, flatten, flatten_fixed_into};
use bezkit_benches::random_curve;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

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

/// The peer cubics at the same absolute tolerance (1e-5 × curve size): ours (eq. (3), fixed
/// rule, general and allocation-free path), kurbo's `flatten` and lyon_geom's
/// `for_each_flattened`. Throughput: output segments of each method.
fn versus_peers(c: &mut Criterion) {
    use lyon_geom::{CubicBezierSegment, point};
    let options = FlattenOptions::default();
    let mut g = c.benchmark_group("cubic_flatten_peers");
    for (name, curve) in bez_subdiv::cases::peer_cubics() {
        let p = curve.points();
        let tol = 1e-5 * bez_subdiv::curve_size(&curve);
        let Ok(path) = bez_core::curves_to_bez_path(std::slice::from_ref(&curve)) else {
            continue;
        };
        let lyon = CubicBezierSegment {
            from: point(p[0].x(), p[0].y()),
            ctrl1: point(p[1].x(), p[1].y()),
            ctrl2: point(p[2].x(), p[2].y()),
            to: point(p[3].x(), p[3].y()),
        };
        let Ok(ours) = flatten(&curve, &options) else {
            continue;
        };
        let ours_segments = ours.polyline.len() as u64 - 1;
        g.throughput(Throughput::Elements(ours_segments));
        g.bench_function(BenchmarkId::new("bezkit flatten, fixed rule", &name), |b| {
            b.iter(|| flatten(black_box(&curve), &options));
        });
        let mut polyline = Vec::new();
        g.bench_function(BenchmarkId::new("bezkit flatten_fixed_into", &name), |b| {
            b.iter(|| {
                flatten_fixed_into(black_box(&curve), 1e-5, 40, &mut polyline).map(|s| s.pieces)
            });
        });
        let mut kurbo_points = Vec::new();
        kurbo::flatten(&path, tol, |el| kurbo_points.push(el));
        g.throughput(Throughput::Elements(kurbo_points.len() as u64 - 1));
        g.bench_function(BenchmarkId::new("kurbo flatten", &name), |b| {
            b.iter(|| {
                kurbo_points.clear();
                kurbo::flatten(black_box(&path), tol, |el| kurbo_points.push(el));
                kurbo_points.len()
            });
        });
        let mut wang_points = Vec::new();
        let fast = Flattener::new(tol);
        let Ok(wang_segments) = fast.flatten(&curve, |p| wang_points.push(p.point)) else {
            continue;
        };
        g.throughput(Throughput::Elements(wang_segments as u64));
        g.bench_function(BenchmarkId::new("bezkit Method::Fast", &name), |b| {
            b.iter(|| {
                wang_points.clear();
                fast.flatten(black_box(&curve), |p| wang_points.push(p.point))
            });
        });
        let mut lyon_points = Vec::new();
        lyon.for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
        assert_eq!(
            lyon_points.len(),
            wang_segments,
            "{name}: Wang's count as lyon_geom's"
        );
        g.throughput(Throughput::Elements(lyon_points.len() as u64));
        g.bench_function(
            BenchmarkId::new("lyon_geom for_each_flattened", &name),
            |b| {
                b.iter(|| {
                    lyon_points.clear();
                    black_box(&lyon).for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
                    lyon_points.len()
                });
            },
        );
    }
    g.finish();
}

/// The `Flattener` modes beside kurbo's `flatten` and lyon_geom's `for_each_flattened` on the
/// peer cubics at the same absolute tolerance, 1e-3 × the curve's size (the standing
/// comparison's tolerance). Throughput: output segments of each method.
fn flattener_versus_peers(c: &mut Criterion) {
    use lyon_geom::{CubicBezierSegment, point};
    let mut g = c.benchmark_group("flattener_vs_peers");
    for (name, curve) in bez_subdiv::cases::peer_cubics() {
        let p = curve.points();
        let tol = 1e-3 * bez_subdiv::curve_size(&curve);
        let Ok(path) = bez_core::curves_to_bez_path(std::slice::from_ref(&curve)) else {
            continue;
        };
        let lyon = CubicBezierSegment {
            from: point(p[0].x(), p[0].y()),
            ctrl1: point(p[1].x(), p[1].y()),
            ctrl2: point(p[2].x(), p[2].y()),
            to: point(p[3].x(), p[3].y()),
        };
        for (label, method) in [
            ("bezkit Optimal", Method::Optimal),
            ("bezkit Fast", Method::Fast),
        ] {
            let flattener = Flattener::new(tol).with_method(method);
            let mut points = Vec::new();
            let Ok(segments) = flattener.flatten(&curve, |q| points.push(q.point)) else {
                continue;
            };
            g.throughput(Throughput::Elements(segments as u64));
            g.bench_function(BenchmarkId::new(label, &name), |b| {
                b.iter(|| {
                    points.clear();
                    flattener.flatten(black_box(&curve), |q| points.push(q.point))
                });
            });
        }
        let mut kurbo_points = Vec::new();
        kurbo::flatten(&path, tol, |el| kurbo_points.push(el));
        g.throughput(Throughput::Elements(kurbo_points.len() as u64 - 1));
        g.bench_function(BenchmarkId::new("kurbo flatten", &name), |b| {
            b.iter(|| {
                kurbo_points.clear();
                kurbo::flatten(black_box(&path), tol, |el| kurbo_points.push(el));
                kurbo_points.len()
            });
        });
        let mut lyon_points = Vec::new();
        lyon.for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
        g.throughput(Throughput::Elements(lyon_points.len() as u64));
        g.bench_function(
            BenchmarkId::new("lyon_geom for_each_flattened", &name),
            |b| {
                b.iter(|| {
                    lyon_points.clear();
                    black_box(&lyon).for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
                    lyon_points.len()
                });
            },
        );
    }
    g.finish();
}

/// `Method::Fast` beside lyon_geom's quadratic `for_each_flattened` (the same uniform Wang
/// count) on three seeded random quadratics at 1e-3 and 1e-5 × the curve's size; the counts are
/// asserted equal. Throughput: output segments.
fn quadratics_versus_lyon(c: &mut Criterion) {
    use lyon_geom::{QuadraticBezierSegment, point};
    let mut g = c.benchmark_group("quadratic_flatten_vs_lyon");
    for seed in 1..=3_u64 {
        let curve = random_curve::<2>(2, 500 + seed);
        let p = curve.points();
        let lyon = QuadraticBezierSegment {
            from: point(p[0].x(), p[0].y()),
            ctrl: point(p[1].x(), p[1].y()),
            to: point(p[2].x(), p[2].y()),
        };
        for rel in [1e-3, 1e-5] {
            let tol = rel * bez_subdiv::curve_size(&curve);
            let name = format!("quadratic {seed} at {rel:e}");
            let fast = Flattener::new(tol).with_method(Method::Fast);
            let mut points = Vec::new();
            let Ok(segments) = fast.flatten(&curve, |q| points.push(q.point)) else {
                continue;
            };
            let mut lyon_points = Vec::new();
            lyon.for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
            assert_eq!(lyon_points.len(), segments, "{name}: lyon_geom's count");
            g.throughput(Throughput::Elements(segments as u64));
            g.bench_function(BenchmarkId::new("bezkit Method::Fast", &name), |b| {
                b.iter(|| {
                    points.clear();
                    fast.flatten(black_box(&curve), |q| points.push(q.point))
                });
            });
            g.bench_function(
                BenchmarkId::new("lyon_geom for_each_flattened", &name),
                |b| {
                    b.iter(|| {
                        lyon_points.clear();
                        black_box(&lyon).for_each_flattened(tol, &mut |s| lyon_points.push(s.to));
                        lyon_points.len()
                    });
                },
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
