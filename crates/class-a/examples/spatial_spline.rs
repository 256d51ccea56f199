//! Spatial Class A curves with prescribed end curvature and osculating plane, and spatial
//! curves of several segments.
//!
//! First a spline through knots of a conical spiral, G1, G2 with the spiral's curvatures and
//! binormals, and G2 with both chosen from the G1 spline, with the joints' tangent, curvature
//! and binormal jumps and each segment's certificates. Then the reach of the spatial G2 solve:
//! for G1 data of typical spatial curves (degree n, total turn ψ, both s > 1 and s < 1), the
//! typical end curvatures are scaled by factors on a grid, and separately the osculating planes
//! turned about the tangents, and the outcomes counted. Last, the full G2 data (curvatures and
//! binormals at both ends) of perturbed typical curves with proven monotone curvature and
//! torsion are solved back.
//!
//! ```text
//! cargo run -p class-a --example spatial_spline
//! ```
#![allow(clippy::print_stdout, reason = "an example reports on the terminal")]

#[path = "../tests/common/spatial_g2.rs"]
mod spatial_g2;

use bez_core::{BezierCurve, Vector3};
use class_a::{
    ClassAError, SpatialClassASpline, SpatialKnot, TypicalSpatial, curvature_certificate,
    hermite_spatial, rotation, torsion_certificate,
};

/// Unit tangent, curvature and unit binormal at t.
fn frame(c: &BezierCurve<3>, t: f64) -> Result<(Vector3, f64, Vector3), ClassAError> {
    let d = c.eval_derivatives(t, 2)?;
    let b = d[1].cross(&d[2]);
    Ok((d[1] / d[1].norm(), c.curvature(t)?, b / b.norm()))
}

fn report(name: &str, spline: &SpatialClassASpline) -> Result<(), ClassAError> {
    let segs = spline.to_bezier_segments();
    println!(
        "{name}: {} segments of degree {}",
        segs.len(),
        spline.degree()
    );
    for (i, w) in segs.windows(2).enumerate() {
        let (ta, ka, ba) = frame(&w[0], 1.0)?;
        let (tb, kb, bb) = frame(&w[1], 0.0)?;
        println!(
            "  joint {}: tangent jump {:.1e}, curvature {:.6} | {:.6}, binormal jump {:.1e}",
            i + 1,
            (ta - tb).norm(),
            ka,
            kb,
            (ba - bb).norm()
        );
    }
    for (i, s) in segs.iter().enumerate() {
        println!(
            "  segment {i}: curvature {:?}, torsion {:?}",
            curvature_certificate(s)?.verdict,
            torsion_certificate(s)?.verdict
        );
    }
    Ok(())
}

/// The outcome of one G2 target: reached, curvature / torsion not monotone, no convergence,
/// other error.
fn outcome(r: &Result<class_a::ClassACurve<3>, ClassAError>) -> usize {
    match r {
        Ok(_) => 0,
        Err(ClassAError::CurvatureNotMonotone { .. }) => 1,
        Err(ClassAError::TorsionNotMonotone { .. }) => 2,
        Err(ClassAError::NoConvergence { .. }) => 3,
        Err(_) => 4,
    }
}

/// A fixed-seed generator of uniform numbers in [0, 1) (64-bit LCG, top 53 bits).
fn uniform(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// G2 data of 300 perturbed typical spatial curves: how many with proven monotone curvature and
/// torsion are solved (every `Ok` verified by `hermite_spatial` itself).
fn recovery() -> Result<(), ClassAError> {
    let mut state = 2014u64;
    let (mut known, mut solved) = (0, 0);
    let mut failures = [0usize; 5];
    for _ in 0..300 {
        let n = 3 + (uniform(&mut state) * 8.0) as usize;
        let theta = (0.3 + 1.7 * uniform(&mut state)) / (n - 1) as f64;
        let sigma = 1.0 / (2.0 * theta.cos() - 1.0) + 0.3 * uniform(&mut state);
        let s = if uniform(&mut state) < 0.5 {
            sigma
        } else {
            1.0 / sigma
        };
        let polar = 0.3 + 2.5 * uniform(&mut state);
        let t = TypicalSpatial {
            b0: Vector3::zeros(),
            v0: Vector3::new(1.0, 0.0, 0.0),
            length: 1.0,
            s,
            phi: 0.0,
            axis: Vector3::new(polar.cos(), polar.sin(), 0.0),
            theta,
            degree: n,
        };
        let mut m = t.matrix();
        for r in 0..3 {
            for c in 0..3 {
                m[(r, c)] += 0.03 * (2.0 * uniform(&mut state) - 1.0);
            }
        }
        let curve = class_a::class_a_curve(&Vector3::zeros(), &Vector3::new(1.0, 0.0, 0.0), &m, n)?;
        let proven = curvature_certificate(&curve).is_ok_and(|c| c.is_monotone())
            && torsion_certificate(&curve).is_ok_and(|c| c.is_monotone());
        if !proven {
            continue;
        }
        known += 1;
        let p = curve.points();
        let (_, k0, b0) = frame(&curve, 0.0)?;
        let (_, k1, b1) = frame(&curve, 1.0)?;
        let r = hermite_spatial(
            &SpatialKnot::new(p[0], p[1] - p[0])
                .with_curvature(k0)
                .with_binormal(b0),
            &SpatialKnot::new(p[n], p[n] - p[n - 1])
                .with_curvature(k1)
                .with_binormal(b1),
            n,
        );
        if r.is_ok() {
            solved += 1;
        }
        failures[outcome(&r)] += 1;
    }
    println!();
    println!(
        "perturbed typical spatial curves with proven monotone curvature and torsion: {known}; full G2 data solved: {solved} (reached / κ not monotone / τ not monotone / no convergence / other: {failures:?})"
    );
    Ok(())
}

fn main() -> Result<(), ClassAError> {
    report(
        "G1 spline",
        &SpatialClassASpline::new(spatial_g2::spiral_knots(4, false), 6)?,
    )?;
    report(
        "G2 spline",
        &SpatialClassASpline::new(spatial_g2::spiral_knots(4, true), 6)?,
    )?;
    let auto = SpatialClassASpline::with_g2_joints(spatial_g2::spiral_knots(4, false), 6)?;
    report(
        "G2 spline, curvatures and binormals chosen from the G1 one",
        &auto,
    )?;

    let factors = [0.7, 0.85, 0.95, 1.0, 1.05, 1.15, 1.4];
    let turns = [-0.3, -0.1, -0.03, 0.03, 0.1, 0.3];
    println!();
    println!(
        "spatial G2 reach: G1 data of typical curves (axis 0.8 rad from the start tangent, s and 1/s = 1/(2 cos θ − 1) + 0.1), end curvatures scaled by {factors:?} each, binormals turned by {turns:?} rad each"
    );
    println!(
        "| n | turn ψ | curvature targets: reached / κ not monotone / τ not monotone / no convergence / other | binormal targets: same |"
    );
    println!("|---|---|---|---|");
    for n in [4usize, 7, 12] {
        for turn in [0.3, 0.6, 1.2, 2.0] {
            let theta = turn / (n - 1) as f64;
            let sigma = 1.0 / (2.0 * theta.cos() - 1.0) + 0.1;
            let (mut by_curvature, mut by_binormal) = ([0usize; 5], [0usize; 5]);
            for s in [sigma, 1.0 / sigma] {
                let t = TypicalSpatial {
                    b0: Vector3::zeros(),
                    v0: Vector3::new(1.0, 0.0, 0.0),
                    length: 1.0,
                    s,
                    phi: 0.0,
                    axis: Vector3::new(0.8f64.cos(), 0.8f64.sin(), 0.0),
                    theta,
                    degree: n,
                };
                let c = t.curve()?;
                let p = c.points();
                let start = SpatialKnot::new(p[0], p[1] - p[0]);
                let end = SpatialKnot::new(p[n], p[n] - p[n - 1]);
                let [(k0, _), (k1, _)] = t.end_curvatures_torsions()?;
                for f0 in factors {
                    for f1 in factors {
                        let r = hermite_spatial(
                            &start.with_curvature(k0 * f0),
                            &end.with_curvature(k1 * f1),
                            n,
                        );
                        by_curvature[outcome(&r)] += 1;
                    }
                }
                let (t0, _, b0) = frame(&c, 0.0)?;
                let (t1, _, b1) = frame(&c, 1.0)?;
                for a in turns {
                    for b in turns {
                        let r = hermite_spatial(
                            &start
                                .with_curvature(k0)
                                .with_binormal(rotation(&t0, a) * b0),
                            &end.with_curvature(k1).with_binormal(rotation(&t1, b) * b1),
                            n,
                        );
                        by_binormal[outcome(&r)] += 1;
                    }
                }
            }
            let show = |c: [usize; 5]| c.map(|v| v.to_string()).join(" / ");
            println!(
                "| {n} | {turn} | {} | {} |",
                show(by_curvature),
                show(by_binormal)
            );
        }
    }
    recovery()
}
