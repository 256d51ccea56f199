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

/// A recorded drag: 1,000 steps of the end point α₃ (spatial) or α₂ (planar) on a seeded random
/// walk of 0.5 % of the chord per step from the Fig. 8 / Fig. 6 points. Each frame is one
/// `edit`: the curve (spatial: continued from the last frame by `TypicalSpatial::update`), its
/// proven certificate (torsion; planar: curvature) and the LTG / LCG slope of 17 samples. The
/// whole replay (time / 1000 is the mean frame) and its slowest frame.
fn drag(c: &mut Criterion) {
    let mut seed = 2014u64;
    let mut step = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    let a = cases::fig8_points();
    let scale = (a[3] - a[0]).norm() * 0.005;
    let mut spatial = vec![a];
    for _ in 0..1000 {
        let mut next = spatial[spatial.len() - 1];
        next[3] += bez_core::Vector3::new(step(), step(), step()) * scale;
        spatial.push(next);
    }
    let a = cases::fig6_points();
    let scale = (a[2] - a[0]).norm() * 0.005;
    let mut planar = vec![a];
    for _ in 0..1000 {
        let mut next = planar[planar.len() - 1];
        next[2] += bez_core::Vector2::new(step(), step()) * scale;
        planar.push(next);
    }
    // `edit`: the solution, its curve, the certificate and the LTG / LCG slope of 17 samples.
    let spatial_frame = |last: &TypicalSpatial, a: &[bez_core::Vector3; 4]| {
        last.edit(a).map_or((*last, false, None), |f| {
            let certified = f.certificate.is_ok_and(|c| c.is_monotone());
            (f.solution, certified, f.slope)
        })
    };
    let planar_frame = |a: &[bez_core::Vector2; 3]| {
        TypicalPlanar::edit(&a[0], &a[1], &a[2], 49)
            .ok()
            .map(|f| (f.certificate.is_ok_and(|c| c.is_monotone()), f.slope))
    };
    let Ok(start) = TypicalSpatial::from_points(&spatial[0], 7) else {
        return;
    };
    let mut g = c.benchmark_group("class_a_drag_1000");
    g.sample_size(10);
    g.bench_function("spatial_n7", |b| {
        b.iter(|| {
            let mut t = start;
            for a in &spatial[1..] {
                t = spatial_frame(&t, black_box(a)).0;
            }
            t
        });
    });
    g.bench_function("planar_n49", |b| {
        b.iter(|| {
            planar
                .iter()
                .filter_map(|a| planar_frame(black_box(a)))
                .count()
        });
    });
    // The slowest frame of each replay (best of 3 timings per frame), measured alone.
    let mut states = vec![start];
    for a in &spatial[1..] {
        let last = states[states.len() - 1];
        states.push(spatial_frame(&last, a).0);
    }
    let time = |f: &dyn Fn()| {
        (0..3)
            .map(|_| {
                let t0 = Instant::now();
                f();
                t0.elapsed()
            })
            .min()
            .unwrap_or_default()
    };
    if let Some(k) = (1..spatial.len()).max_by_key(|&k| {
        time(&|| {
            black_box(spatial_frame(&states[k - 1], &spatial[k]));
        })
    }) {
        g.bench_function("spatial_n7_worst_frame", |b| {
            b.iter(|| spatial_frame(&states[k - 1], black_box(&spatial[k])));
        });
    }
    if let Some(k) = (0..planar.len()).max_by_key(|&k| {
        time(&|| {
            black_box(planar_frame(&planar[k]));
        })
    }) {
        g.bench_function("planar_n49_worst_frame", |b| {
            b.iter(|| planar_frame(black_box(&planar[k])));
        });
    }
    g.finish();
}

criterion_group!(
    benches,
    drag,
    planar,
    spatial,
    certificates,
    certificate_worst_case
);
criterion_main!(benches);
