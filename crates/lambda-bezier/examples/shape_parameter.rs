//! The shape parameter λ at work: the paper's half-circle example (Sec. 4.2), a quartic
//! λ-Bézier curve on four control points, for λ across its valid interval. For each λ it prints
//! the largest radial deviation from the unit circle and the curve's exact Bézier form (what a
//! CAD system would receive).
//!
//! ```text
//! cargo run -p lambda-bezier --example shape_parameter
//! ```
#![allow(clippy::print_stdout, reason = "an example reports on the terminal")]

use bez_core::{BezierForm, Vector2};
use lambda_bezier::{LambdaBezierCurve, LambdaError, LambdaRange};

fn main() -> Result<(), LambdaError> {
    let points = vec![
        Vector2::new(-1.0, 0.0),
        Vector2::new(-1.0, 1.2),
        Vector2::new(1.0, 1.2),
        Vector2::new(1.0, 0.0),
    ];
    let range = LambdaRange::new(points.len() - 1)?;
    println!(
        "valid λ for n = {}: [{}, {}]",
        points.len() - 1,
        range.min(),
        range.max()
    );
    println!("{:>6}  {:>22}", "λ", "max |radius − 1|");
    let mut curve = LambdaBezierCurve::new(points, 0.0)?;
    for lambda in [-3.0, -1.0, 0.0, 0.4, 0.56, 0.7, 1.0] {
        curve.set_lambda(lambda)?;
        let samples = curve.sample_uniform(2001)?;
        let deviation = samples
            .iter()
            .map(|p| (p.norm() - 1.0).abs())
            .fold(0.0, f64::max);
        println!("{lambda:>6}  {deviation:>22.6}");
    }

    curve.set_lambda(0.56)?;
    println!(
        "λ = 0.56 as an ordinary Bézier curve of degree {}:",
        curve.degree()
    );
    for q in curve.into_bezier().points() {
        println!("  ({:.6}, {:.6})", q[0], q[1]);
    }
    // Outside the valid interval the basis is no longer non-negative: a typed error.
    if let Err(e) = LambdaBezierCurve::new(vec![Vector2::new(0.0, 0.0); 4], 1.5) {
        println!("λ = 1.5: {e}");
    }
    Ok(())
}
