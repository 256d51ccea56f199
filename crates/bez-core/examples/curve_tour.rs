//! A tour of bez-core on one planar cubic: evaluation, subdivision, degree elevation,
//! derivatives and curvature, arc length, nearest point and bounding box, and what happens with
//! bad input.
//!
//! ```text
//! cargo run -p bez-core --example curve_tour
//! ```
#![allow(clippy::print_stdout, reason = "an example reports on the terminal")]

use bez_core::{BezierCurve, CoreError, Vector2};

fn main() -> Result<(), CoreError> {
    let curve = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 2.0),
        Vector2::new(3.0, 2.0),
        Vector2::new(4.0, 0.0),
    ])?;
    println!(
        "degree {} curve from {:?} to {:?}",
        curve.degree(),
        curve.start(),
        curve.end()
    );

    // Evaluation by de Casteljau, and O(n) per point for many parameters.
    let mid = curve.eval(0.5)?;
    println!("B(0.5) = ({:.6}, {:.6})", mid[0], mid[1]);
    let ts: Vec<f64> = (0..=4).map(|k| f64::from(k) / 4.0).collect();
    let mut samples = Vec::new();
    curve.eval_many(&ts, &mut samples)?;
    println!("B at t = 0, 1/4, .., 1: {samples:?}");

    // Subdivision: the two pieces meet exactly at B(0.5).
    let (left, right) = curve.split(0.5)?;
    assert_eq!(left.end(), right.start());
    println!("split at 1/2: left ends at {:?}", left.end());

    // Degree elevation keeps the curve.
    let quintic = curve.elevate(2)?;
    let gap = (quintic.eval(0.3)? - curve.eval(0.3)?).norm();
    println!(
        "elevated to degree {}: |difference| at t = 0.3 is {gap:.1e}",
        quintic.degree()
    );

    // Derivatives, curvature, arc length.
    let hodograph = curve.derivative()?;
    println!("B'(0) = {:?}", hodograph.eval(0.0)?);
    println!(
        "signed curvature at t = 0.25: {:.6}",
        curve.signed_curvature(0.25)?
    );
    println!("arc length: {:.12}", curve.arc_length(1e-12)?);

    // Nearest point and bounding box.
    let query = Vector2::new(2.0, 3.0);
    let nearest = curve.nearest(&query)?;
    println!(
        "nearest point to {query:?}: t = {:.9}, distance {:.9}",
        nearest.t, nearest.distance
    );
    println!("bounding box: {:?}", curve.bounding_box());

    // Bad input is a typed error, never a panic.
    match curve.eval(1.5) {
        Err(e) => println!("eval(1.5): {e}"),
        Ok(p) => println!("unexpected: {p:?}"),
    }
    match BezierCurve::new(vec![Vector2::new(f64::NAN, 0.0)]) {
        Err(e) => println!("a NaN control point: {e}"),
        Ok(c) => println!("unexpected: {c:?}"),
    }
    Ok(())
}
