//! A Bloor–Wilson blend between two circles, solved as a PDE surface and written as STEP.
//!
//! The blend X(u, v) runs from a circle of radius 1 at height 0 (u = 0) to a circle of radius
//! 0.5 at height 1 (u = 1), leaving both vertically (position and ∂X/∂u prescribed, the
//! conditions of the 4th-order Bloor–Wilson operator (∂²/∂u² + a²∂²/∂v²)², here with the
//! smoothing parameter a = 0.15: a larger a pulls the middle of the blend inwards), and closes
//! around in v. The result is
//! one C³ bi-quintic B-spline surface (the 4th-order operator needs C³ joins), exported to STEP AP214.
//!
//! ```text
//! cargo run -p pde-bezier --example blend_to_step -- [OUT.step]
//! ```
#![allow(
    clippy::print_stdout,
    clippy::print_stderr,
    reason = "a command-line example reports on the terminal"
)]

use std::f64::consts::TAU;
use std::process::ExitCode;

use bez_core::Vector3;
use pde_bezier::{
    Discretization, Method, Operator, PdeError, Problem, Side, SideCurve, solve, write_step,
};

/// Position (d = 0) and its v-derivatives (d ≥ 1) of a horizontal circle, parameter v ∈ [0, 1].
fn circle(radius: f64, height: f64, v: f64, d: usize) -> Vector3 {
    let w = TAU * v;
    let k = TAU.powi(i32::try_from(d).unwrap_or(i32::MAX));
    // d-th derivative of (cos w, sin w): rotate by d quarter turns.
    let (c, s) = (w + d as f64 * TAU / 4.0).sin_cos();
    let z = if d == 0 { height } else { 0.0 };
    Vector3::new(radius * k * s, radius * k * c, z)
}

/// Position and cross-boundary derivative ∂X/∂u = (0, 0, 2) of one end of the blend.
fn end(radius: f64, height: f64) -> Result<Side, PdeError> {
    let position = SideCurve::from_function(65, 2, move |v, d| circle(radius, height, v, d))?;
    let lift = SideCurve::from_function(65, 2, |_, d| {
        Vector3::new(0.0, 0.0, if d == 0 { 2.0 } else { 0.0 })
    })?;
    Ok(Side::Fixed(vec![position, lift]))
}

fn run(out: Option<&str>) -> Result<(), PdeError> {
    let problem = Problem {
        operator: Operator::bloor_wilson(0.15)?,
        rhs: None,
        u0: end(1.0, 0.0)?,
        u1: end(0.5, 1.0)?,
        v0: Side::Periodic,
        v1: Side::Periodic,
    };
    let disc = Discretization {
        degree_u: 5,
        degree_v: 5,
        patches_u: 2,
        patches_v: 8,
        smoothness_u: 3,
        smoothness_v: 3,
    };
    let solution = solve(&problem, &disc, Method::Galerkin)?;
    println!(
        "{} unknowns; boundary data fitted to {:.1e}",
        solution.unknowns, solution.boundary_fit_error
    );
    for u in [0.0, 0.5, 1.0] {
        let p = solution.surface.eval(u, 0.0)?;
        let radius = (p.x() * p.x() + p.y() * p.y()).sqrt();
        println!("u = {u}: radius {radius:.4}, height {:.4}", p.z());
    }
    let mut step = Vec::new();
    write_step(&solution.spline, "bloor-wilson blend", &mut step)?;
    match out {
        Some(path) => match std::fs::write(path, &step) {
            Ok(()) => println!("wrote {path} ({} bytes)", step.len()),
            Err(e) => eprintln!("cannot write {path}: {e}"),
        },
        None => println!(
            "STEP file of {} bytes (pass a path to write it)",
            step.len()
        ),
    }
    Ok(())
}

fn main() -> ExitCode {
    let out = std::env::args().nth(1);
    match run(out.as_deref()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
