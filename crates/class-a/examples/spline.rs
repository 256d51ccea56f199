//! Class A curves with prescribed end curvature, and curves of several segments.
//!
//! First a spline through knots of a log spiral, G1, G2 with the spiral's curvatures and G2 with
//! curvatures chosen from the G1 spline, with the joints' tangent and curvature jumps and each
//! segment's certificate. Then the reach of the G2 solve:
//! for G1 data of typical curves (degree n, total turn ψ, both branches of condition (4)), the
//! typical end curvatures (κ₀, κ₁) are scaled by factors on a grid and the outcomes counted.
//! Last, the G2 data of perturbed typical curves with monotone curvature are solved back.
//!
//! ```text
//! cargo run -p class-a --example spline
//! ```
#![allow(clippy::print_stdout, reason = "an example reports on the terminal")]

#[path = "../tests/common/g2.rs"]
mod g2;

use bez_core::{BezierCurve, Vector2};
use class_a::{
    ClassAError, ClassASpline, Knot, class_a_curve, curvature_certificate, end_curvatures,
    hermite_planar, typical_matrix2,
};

fn report(name: &str, spline: &ClassASpline) -> Result<(), ClassAError> {
    let segs = spline.to_bezier_segments();
    println!(
        "{name}: {} segments of degree {}",
        segs.len(),
        spline.degree()
    );
    for (i, w) in segs.windows(2).enumerate() {
        let (u, v) = (w[0].derivative()?.eval(1.0)?, w[1].derivative()?.eval(0.0)?);
        let (k0, k1) = (w[0].signed_curvature(1.0)?, w[1].signed_curvature(0.0)?);
        println!(
            "  joint {}: tangent jump {:.1e} rad, curvature {:.6} | {:.6}",
            i + 1,
            u.perp(&v).atan2(u.dot(&v)).abs(),
            k0,
            k1
        );
    }
    for (i, s) in segs.iter().enumerate() {
        println!("  segment {i}: {:?}", curvature_certificate(s)?.verdict);
    }
    Ok(())
}

/// G2 data of 400 perturbed typical curves (as in the test `g2_recovers_perturbed_class_a_curves`):
/// how many with proven monotone curvature are solved, and recover their matrix.
fn recovery() {
    let mut state = 12_345u64;
    let (mut known, mut solved, mut same) = (0, 0, 0);
    for _ in 0..400 {
        let (n, m) = g2::perturbed_typical(&mut state);
        if let Some(back) = g2::solve_back(n, Vector2::new(1.0, 0.0), &m, false) {
            known += 1;
            solved += usize::from(back.result.is_ok());
            same += usize::from(back.same);
        }
    }
    println!();
    println!(
        "perturbed Class A curves with monotone curvature: {known}; G2 data solved: {solved}; generating matrix recovered to 1e-6: {same}"
    );
}

/// G2 data of 200 random general-matrix curves that turn one way by less than π with proven
/// monotone curvature (as in the test `g2_solves_random_general_class_a_curves`): how many are
/// solved, and how many by the generating matrix.
fn random_general() {
    let mut state = 2_024u64;
    let (mut known, mut solved, mut same) = (0, 0, 0);
    while known < 200 {
        let (n, v, m) = g2::random_general(&mut state);
        if let Some(back) = g2::solve_back(n, v, &m, true) {
            known += 1;
            solved += usize::from(back.result.is_ok());
            same += usize::from(back.same);
        }
    }
    println!(
        "random general-matrix curves with monotone curvature: {known}; G2 data solved: {solved}; generating matrix recovered to 1e-6: {same}"
    );
}

/// G1 knots of the typical curve with scale s and angle θ per leg.
fn typical(s: f64, theta: f64, n: usize) -> Result<(Knot, Knot, BezierCurve<2>), ClassAError> {
    let c = class_a_curve(
        &Vector2::new(0.0, 0.0),
        &Vector2::new(1.0, 0.0),
        &typical_matrix2(s, theta),
        n,
    )?;
    let p = c.points();
    Ok((
        Knot::new(p[0], p[1] - p[0]),
        Knot::new(p[n], p[n] - p[n - 1]),
        c,
    ))
}

fn main() -> Result<(), ClassAError> {
    report("G1 spline", &ClassASpline::new(g2::spiral_knots(false), 6)?)?;
    report("G2 spline", &ClassASpline::new(g2::spiral_knots(true), 6)?)?;
    let auto = ClassASpline::with_g2_joints(g2::spiral_knots(false), 6)?;
    report("G2 spline, curvatures chosen from the G1 one", &auto)?;

    let factors = [0.5, 0.7, 0.85, 0.95, 1.0, 1.05, 1.15, 1.4, 2.0];
    println!();
    println!(
        "G2 reach: end curvatures of the typical curve scaled by {factors:?} each ({} targets per row)",
        2 * factors.len() * factors.len()
    );
    println!(
        "| n | turn ψ | reached | outside the bounds | not monotone | tolerance not met | no solution found |"
    );
    println!("|---|---|---|---|---|---|---|");
    for n in [4usize, 7, 12] {
        for turn in [0.3, 0.6, 1.2, 2.0, 2.8] {
            let theta = turn / (n - 1) as f64;
            let c = theta.cos();
            let mut counts = [0usize; 5];
            // Curvature decreasing from the start (s cos θ > 1) and increasing (s < cos θ).
            for s in [1.0 / c + 0.1, c - 0.1] {
                let (start, end, curve) = typical(s, theta, n)?;
                let (k0, k1) = end_curvatures(&curve)?;
                for f0 in factors {
                    for f1 in factors {
                        let r = hermite_planar(
                            &start.with_curvature(k0 * f0),
                            &end.with_curvature(k1 * f1),
                            n,
                        );
                        let slot = match r {
                            Ok(_) => 0,
                            Err(ClassAError::CurvatureUnreachable { .. }) => 1,
                            Err(ClassAError::CurvatureNotMonotone { .. }) => 2,
                            Err(ClassAError::ToleranceNotMet { .. }) => 3,
                            Err(_) => 4,
                        };
                        counts[slot] += 1;
                    }
                }
            }
            println!(
                "| {n} | {turn} | {} | {} | {} | {} | {} |",
                counts[0], counts[1], counts[2], counts[3], counts[4]
            );
        }
    }
    recovery();
    random_general();
    Ok(())
}
