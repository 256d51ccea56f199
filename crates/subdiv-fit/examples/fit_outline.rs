//! Fits a subdivision curve with sharp corners to a sampled outline and writes it as SVG: the
//! fitted curve as exact cubic Béziers over the data points.
//!
//! ```text
//! cargo run -p subdiv-fit --example fit_outline -- [TOLERANCE] > outline.svg
//! ```
//!
//! The outline is a "D": a half disc on a straight back, 400 samples, two corners.
#![allow(
    clippy::print_stdout,
    clippy::print_stderr,
    reason = "a command-line example reports on the terminal"
)]

use std::f64::consts::PI;
use std::process::ExitCode;

use subdiv_fit::{Closure, FitOptions, SubdivFitError, Vector2, fit, svg_path};

/// 200 samples on the straight back from (0, 1) down to (0, −1), then 200 on the half circle
/// of radius 1 back up: corners at both ends of the back.
fn outline() -> Vec<Vector2> {
    let back = (0..200).map(|k| Vector2::new(0.0, 1.0 - 2.0 * f64::from(k) / 200.0));
    let arc = (0..200).map(|k| {
        let a = -PI / 2.0 + PI * f64::from(k) / 200.0;
        Vector2::new(a.cos(), a.sin())
    });
    back.chain(arc).collect()
}

fn run(tolerance: f64) -> Result<(), SubdivFitError> {
    let data = outline();
    let result = fit(&data, Closure::Closed, &FitOptions::new(tolerance))?;
    let last = result.last().copied();
    let corners = result.curve.kinds().iter().filter(|k| k.is_sharp()).count();
    eprintln!(
        "{} data points -> {} control points ({corners} sharp), {} rounds; error data->curve {:.2e}, curve->data {:.2e}",
        data.len(),
        result.curve.points().len(),
        result.reports.len(),
        last.map_or(f64::NAN, |r| r.max_data_to_curve),
        last.map_or(f64::NAN, |r| r.max_curve_to_data),
    );
    let dots: String = data
        .iter()
        .map(|p| {
            format!(
                "<circle cx=\"{:.4}\" cy=\"{:.4}\" r=\"0.006\"/>",
                p.x(),
                -p.y()
            )
        })
        .collect();
    println!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-0.2 -1.2 1.4 2.4\">\n<g fill=\"red\">{dots}</g>\n<path transform=\"scale(1,-1)\" fill=\"none\" stroke=\"black\" stroke-width=\"0.005\" d=\"{}\"/>\n</svg>",
        svg_path(&result.curve)?
    );
    Ok(())
}

fn main() -> ExitCode {
    let tolerance = match std::env::args().nth(1).map(|s| s.parse::<f64>()) {
        None => 1e-3,
        Some(Ok(t)) => t,
        Some(Err(e)) => {
            eprintln!("bad tolerance: {e}");
            return ExitCode::FAILURE;
        }
    };
    match run(tolerance) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
