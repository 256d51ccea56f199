//! bez-core: evaluation, splitting, elevation and surface evaluation.
#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

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
    let mut g = c.benchmark_group("elevate_by_1");
    for n in [3, 12, 25, 49] {
        let curve = random_curve::<2>(n, n as u64);
        g.bench_with_input(BenchmarkId::from_parameter(n), &curve, |b, cv| {
            b.iter(|| cv.elevate(black_box(1)));
        });
    }
    g.finish();
}

criterion_group!(benches, eval, split_and_elevate);
criterion_main!(benches);
