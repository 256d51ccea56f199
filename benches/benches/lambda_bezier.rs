//! lambda-bezier: evaluation of a degree n + 1 λ-curve against an ordinary Bézier curve of the
//! same degree (1,000 points), and the direct basis-sum evaluation for contrast.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_core::BezierForm;
use bezkit_benches::{random_curve, uniform_parameters};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use lambda_bezier::{LambdaBasis, LambdaBezierCurve};

fn eval_1000(c: &mut Criterion) {
    let ts = uniform_parameters(1000);
    for n in [3usize, 4, 10] {
        // λ-curve on n + 1 random points (degree n + 1) and a random Bézier curve of degree n + 1.
        let points = random_curve::<2>(n, n as u64).into_points();
        let lambda_curve = LambdaBezierCurve::new(points.clone(), -1.0)
            .unwrap_or_else(|_| unreachable!("random points, λ = −1 is valid for n ≥ 2"));
        let bezier = random_curve::<2>(n + 1, n as u64 + 100);
        let basis =
            LambdaBasis::new(n, -1.0).unwrap_or_else(|_| unreachable!("λ = −1 is valid for n ≥ 2"));
        let mut g = c.benchmark_group(format!("eval_1000_points_degree_{}", n + 1));
        g.bench_with_input(
            BenchmarkId::from_parameter("lambda"),
            &lambda_curve,
            |b, cv| {
                let mut out = Vec::with_capacity(1000);
                b.iter(|| cv.eval_many(black_box(&ts), &mut out));
            },
        );
        g.bench_with_input(BenchmarkId::from_parameter("bezier"), &bezier, |b, cv| {
            let mut out = Vec::with_capacity(1000);
            b.iter(|| cv.eval_many(black_box(&ts), &mut out));
        });
        g.bench_with_input(
            BenchmarkId::from_parameter("lambda_basis_sum"),
            &points,
            |b, pts| {
                let mut row = vec![0.0; n + 1];
                let mut out = Vec::with_capacity(1000);
                b.iter(|| {
                    out.clear();
                    for &t in black_box(&ts) {
                        if basis.row(t, &mut row).is_ok() {
                            out.push(
                                pts.iter()
                                    .zip(&row)
                                    .map(|(p, w)| p * *w)
                                    .sum::<bez_core::Vector2>(),
                            );
                        }
                    }
                });
            },
        );
        g.bench_with_input(BenchmarkId::from_parameter("convert"), &points, |b, pts| {
            b.iter(|| LambdaBezierCurve::new(black_box(pts.clone()), black_box(0.5)));
        });
        g.finish();
    }
}

criterion_group!(benches, eval_1000);
criterion_main!(benches);
