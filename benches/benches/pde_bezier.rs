//! pde-bezier: assembly + solve of one bi-quintic patch and of bi-quintic patch grids.

#![allow(missing_docs, reason = "criterion macros generate undocumented items")]

use std::hint::black_box;

use bez_core::{BezierSurface, Vector3};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use pde_bezier::{Assembly, Discretization, Method, Operator, Problem, cases};

// Assembly includes the clamped least-squares fits of the sampled boundary data.

fn single_patch(c: &mut Criterion) {
    let mut group = c.benchmark_group("pde_bezier_single_patch");
    for n in [3usize, 5, 7, 9] {
        let Ok(mut case) = cases::circle_sphere_blend(1.0, 1.0) else {
            return;
        };
        case.disc = Discretization::single(n, n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &case, |b, case| {
            b.iter(|| {
                Assembly::new(black_box(&case.problem), &case.disc)
                    .and_then(|a| a.solve(Method::BernsteinLeastSquares))
            });
        });
    }
    group.finish();
}

fn patch_grid(c: &mut Criterion) {
    let mut group = c.benchmark_group("pde_bezier_grid_c1");
    group.sample_size(10);
    for p in [2usize, 4, 8] {
        let Ok(mut case) = cases::enneper(3, p, p) else {
            return;
        };
        case.disc.smoothness_u = 1;
        case.disc.smoothness_v = 1;
        group.bench_with_input(BenchmarkId::from_parameter(p), &case, |b, case| {
            b.iter(|| {
                Assembly::new(black_box(&case.problem), &case.disc)
                    .and_then(|a| a.solve(Method::BernsteinLeastSquares))
            });
        });
    }
    group.finish();
}

fn methods_8x8(c: &mut Criterion) {
    let mut group = c.benchmark_group("pde_bezier_8x8_c1_solve");
    group.sample_size(10);
    let Ok(mut case) = cases::enneper(3, 8, 8) else {
        return;
    };
    case.disc.smoothness_u = 1;
    case.disc.smoothness_v = 1;
    let Ok(assembly) = Assembly::new(&case.problem, &case.disc) else {
        return;
    };
    for method in Method::ALL {
        group.bench_with_input(
            BenchmarkId::from_parameter(method.name()),
            &method,
            |b, &method| b.iter(|| black_box(&assembly).solve(method)),
        );
    }
    group.finish();
}

/// Sparse Galerkin at design scale (assembly + solve): bi-quintic C¹ patches on Laplace's
/// equation with a quintic exact solution, 16 x 16 (4,096 unknowns), 32 x 32 (16,384) and a
/// 1 x 800 strip (12,800); the same runs as the pde-bezier-scale table.
fn scale_galerkin(c: &mut Criterion) {
    let pts = (0..36)
        .map(|i| {
            let t = f64::from(i);
            Vector3::new((0.7 * t).sin(), (1.3 * t).cos(), (0.37 * t).sin())
        })
        .collect();
    let Ok(x) = BezierSurface::from_flat(5, 5, pts) else {
        return;
    };
    let Ok(op) = Operator::second_order(1.0, 1.0) else {
        return;
    };
    let Ok(problem) = Problem::manufactured(op, &x) else {
        return;
    };
    let mut group = c.benchmark_group("pde_bezier_scale_galerkin");
    group.sample_size(10);
    for (pu, pv) in [(16usize, 16usize), (32, 32), (1, 800)] {
        let disc = Discretization {
            degree_u: 5,
            degree_v: 5,
            patches_u: pu,
            patches_v: pv,
            smoothness_u: 1,
            smoothness_v: 1,
        };
        group.bench_with_input(
            BenchmarkId::from_parameter(format!("{pu}x{pv}")),
            &disc,
            |b, disc| {
                b.iter(|| {
                    Assembly::new(black_box(&problem), disc).and_then(|a| a.solve(Method::Galerkin))
                });
            },
        );
    }
    group.finish();
}

criterion_group!(
    benches,
    single_patch,
    patch_grid,
    methods_8x8,
    scale_galerkin
);
criterion_main!(benches);
