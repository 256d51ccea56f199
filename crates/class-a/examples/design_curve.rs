//! Designs Class A curves as a curve editor would: a planar one from three points (end points
//! and the corner of the tangent triangle) and a spatial one from four, then prints the proven
//! monotonicity certificates of curvature and torsion and the slope of the logarithmic curvature
//! graph (a straight graph of slope α is the signature of an aesthetic curve).
//!
//! ```text
//! cargo run -p class-a --example design_curve
//! ```
#![allow(clippy::print_stdout, reason = "an example reports on the terminal")]

use bez_core::{Vector2, Vector3};
use class_a::{
    ClassAError, TypicalPlanar, TypicalSpatial, curvature_certificate, curvature_samples,
    log_graph, torsion_certificate,
};

fn main() -> Result<(), ClassAError> {
    // Planar: from a0 to a2, tangent to a0a1 at the start and to a1a2 at the end.
    let (a0, a1, a2) = (
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 0.0),
        Vector2::new(1.6, 1.0),
    );
    let planar = TypicalPlanar::from_points(&a0, &a1, &a2, 7)?;
    let curve = planar.curve()?;
    println!(
        "planar degree {} Class A curve, margin of condition (4): {:.4}",
        curve.degree(),
        planar.margin()
    );
    for (i, p) in curve.points().iter().enumerate() {
        println!("  b{i} = ({:.6}, {:.6})", p[0], p[1]);
    }
    let certificate = curvature_certificate(&curve)?;
    println!(
        "curvature: {:?} (proven: {})",
        certificate.verdict,
        certificate.is_monotone()
    );
    let graph = log_graph(&curvature_samples(&curve, 200)?)?;
    println!(
        "log curvature graph: slope {:.4}, straightness {:.2e}",
        graph.slope, graph.straightness
    );

    // Spatial: end points a0, a3 with tangents along a1 − a0 and a3 − a2.
    let a = [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 0.0, 0.0),
        Vector3::new(1.5, 1.0, 0.3),
        Vector3::new(1.2, 2.0, 1.0),
    ];
    match TypicalSpatial::from_points(&a, 6) {
        Ok(spatial) => {
            let curve = spatial.curve()?;
            println!(
                "spatial degree {} curve, Class A margin {:.4}",
                curve.degree(),
                spatial.class_a_margin()
            );
            println!("  curvature: {:?}", curvature_certificate(&curve)?.verdict);
            println!("  torsion:   {:?}", torsion_certificate(&curve)?.verdict);
        }
        Err(e) => println!("no spatial Class A curve for these points: {e}"),
    }

    // Input the family cannot meet is a typed error.
    if let Err(e) = TypicalPlanar::from_points(&a0, &a1, &a0, 7) {
        println!("a closed tangent triangle: {e}");
    }
    Ok(())
}
