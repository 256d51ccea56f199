//! Flattens an SVG path to polylines with a guaranteed absolute tolerance, the way a renderer
//! would: parse the path data with kurbo, convert its segments to bez-core curves, flatten each
//! with the fast guaranteed mode, and print the polyline of each subpath as SVG points.
//!
//! ```text
//! cargo run -p bez-subdiv --example flatten_svg_path -- ["PATH DATA"] [TOLERANCE]
//! ```
//!
//! Without arguments it flattens a heart shape at tolerance 0.01.
#![allow(
    clippy::print_stdout,
    clippy::print_stderr,
    reason = "a command-line example reports on the terminal"
)]

use std::process::ExitCode;

use bez_core::{Vector2, bez_path_to_curves};
use bez_subdiv::{Flattener, Method};

const HEART: &str = "M 10,30 A 20,20 0,0,1 50,30 A 20,20 0,0,1 90,30 Q 90,60 50,90 Q 10,60 10,30 Z";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let data = args.first().map_or(HEART, String::as_str);
    let tolerance = match args.get(1).map(|s| s.parse::<f64>()) {
        None => 0.01,
        Some(Ok(t)) => t,
        Some(Err(e)) => {
            eprintln!("bad tolerance: {e}");
            return ExitCode::FAILURE;
        }
    };
    match run(data, tolerance) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(data: &str, tolerance: f64) -> Result<(), Box<dyn std::error::Error>> {
    // kurbo parses the path (arcs become cubics); bez-core turns its segments into curves.
    let path = kurbo::BezPath::from_svg(data)?;
    let subpaths = bez_path_to_curves(&path)?;
    let mut total = 0;
    for (i, curves) in subpaths.iter().enumerate() {
        let mut polyline: Vec<Vector2> = Vec::new();
        for curve in curves {
            // Every point of the curve is within `tolerance` of the polyline and back.
            let points = Flattener::new(tolerance)
                .with_method(Method::LocalWang)
                .flatten_to_vec(curve)?;
            let skip = usize::from(!polyline.is_empty()); // shared end point of the last piece
            polyline.extend(points.iter().skip(skip).map(|p| p.point));
        }
        total += polyline.len();
        let svg: Vec<String> = polyline
            .iter()
            .map(|p| format!("{:.3},{:.3}", p.x(), p.y()))
            .collect();
        println!(
            "<!-- subpath {i}: {} curves, {} points -->",
            curves.len(),
            polyline.len()
        );
        println!(
            "<polyline fill=\"none\" stroke=\"black\" points=\"{}\"/>",
            svg.join(" ")
        );
    }
    eprintln!(
        "{} subpaths, {total} points at tolerance {tolerance}",
        subpaths.len()
    );
    Ok(())
}
