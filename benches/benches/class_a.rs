//! class-a: interactive planar and spatial updates (points in, control points out).
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;
use std::time::Instant;

use class_a::{
    TypicalPlanar, TypicalSpatial, cases, curvature_certificate, planar_nelder_mead,
    torsion_certificate,
};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};

fn planar(c: &mut Criterion) {
    let a = cases::fig6_points();
    let mut g = c.benchmark_group("class_a_planar_update");
    for n in [7, 49] {
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, &n| {
            let mut out = Vec::with_capacity(n + 1);
            b.iter(|| {
                if let Ok(t) = TypicalPlanar::from_points(black_box(&a[0]), &a[1], &a[2], n) {
                    t.control_points_into(&mut out);
                }
            });
        });
    }
    g.finish();
    let mut g = c.benchmark_group("class_a_planar_nelder_mead");
    for n in [7, 49] {
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, &n| {
            b.iter(|| planar_nelder_mead(black_box(&a[0]), &a[1], &a[2], n, 2000));
        });
    }
    g.finish();
}

fn spatial(c: &mut Criterion) {
    let a = cases::fig8_points();
    let mut g = c.benchmark_group("class_a_spatial_update");
    for n in [4, 7, 20] {
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, &n| {
            b.iter(|| TypicalSpatial::from_points(black_box(&a), n).and_then(|t| t.curve()));
        });
    }
    g.finish();
    let mut g = c.benchmark_group("class_a_spatial_nelder_mead");
    g.bench_with_input(BenchmarkId::from_parameter(7), &7, |b, &n| {
        b.iter(|| TypicalSpatial::nelder_mead(black_box(&a), n, 2000));
    });
    g.finish();
}

/// The exact certificates: cost growth with the degree (numerator degree 6n − 9 / 7n − 13).
fn certificates(c: &mut Criterion) {
    let a = cases::fig6_points();
    let mut g = c.benchmark_group("class_a_curvature_certificate_planar");
    g.sample_size(10);
    for n in [7, 13, 25, 49] {
        if let Ok(curve) =
            TypicalPlanar::from_points(&a[0], &a[1], &a[2], n).and_then(|t| t.curve())
        {
            g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, curve| {
                b.iter(|| curvature_certificate(black_box(curve)));
            });
        }
    }
    g.finish();
    let a = cases::fig8_points();
    let mut g = c.benchmark_group("class_a_torsion_certificate_spatial");
    g.sample_size(10);
    for n in [7, 15, 30] {
        if let Ok(curve) = TypicalSpatial::from_points(&a, n).and_then(|t| t.curve()) {
            g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, curve| {
                b.iter(|| torsion_certificate(black_box(curve)));
            });
        }
    }
    g.finish();
}

/// Both certificates of one spatial curve (curvature and torsion).
fn both(curve: &bez_core::BezierCurve<3>) -> bool {
    let k = curvature_certificate(curve).is_ok_and(|c| c.is_monotone());
    let t = torsion_certificate(curve).is_ok_and(|c| c.is_monotone());
    k && t
}

/// The worst single case over a random set: 300 spatial typical curves of degree 3..10 (seed 7,
/// the solver comparison's generator), each certificate pair timed (best of 3) to find the
/// slowest curve, which criterion then measures; and the whole set, for the mean.
fn certificate_worst_case(c: &mut Criterion) {
    let curves: Vec<_> = cases::random_spatial_inputs(300, 7)
        .iter()
        .filter_map(|(a, n)| {
            TypicalSpatial::from_points(a, *n)
                .and_then(|t| t.curve())
                .ok()
        })
        .collect();
    let cost = |curve: &bez_core::BezierCurve<3>| {
        (0..3)
            .map(|_| {
                let t0 = Instant::now();
                black_box(both(curve));
                t0.elapsed()
            })
            .min()
            .unwrap_or_default()
    };
    let mut g = c.benchmark_group("class_a_certificates_random_n3_10");
    g.sample_size(10);
    if let Some(worst) = curves.iter().max_by_key(|c| cost(c)) {
        g.bench_function("worst", |b| b.iter(|| both(black_box(worst))));
    }
    g.bench_function("all_300", |b| {
        b.iter(|| curves.iter().filter(|c| both(black_box(c))).count());
    });
    g.finish();
}

criterion_group!(
    benches,
    planar,
    spatial,
    certificates,
    certificate_worst_case
);
criterion_main!(benches);
