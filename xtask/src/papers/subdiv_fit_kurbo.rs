//! subdiv-fit against kurbo's `fit_to_bezpath_opt` on the same data at the same two-sided error.
//!
//! kurbo fits a smooth parametric source, not points; the source here is a uniform Catmull–Rom
//! interpolant of each run of data between consecutive sharp points (the corners subdiv-fit finds,
//! and the ends of open data), so both fits keep the same corners.
//! Both results are measured with the same global two-sided distance to the data: every data
//! point to dense samples of the curve, and every sample to the data polyline.

use std::fmt::Write as _;
use std::ops::Range;

use kurbo::{BezPath, CurveFitSample, ParamCurve, ParamCurveFit, Point, Vec2, fit_to_bezpath_opt};
use serde_json::{Value, json};
use subdiv_fit::cases::{closed_petals, open_wave};
use subdiv_fit::{FitOptions, SubdivCurve, Vector2, fit, point_polyline_distance, scaled_corners};

use super::subdiv_fit::median_ms;
use crate::DynError;
use crate::tables::Table;

/// Repetitions for the median times.
const REPS: usize = 21;

/// A uniform Catmull–Rom interpolant of a run of points, parameter t ∈ [0, 1].
struct CatmullRom {
    pts: Vec<Point>,
}

impl CatmullRom {
    fn tangent(&self, i: usize) -> Vec2 {
        let n = self.pts.len();
        if i == 0 {
            self.pts[1] - self.pts[0]
        } else if i + 1 == n {
            self.pts[n - 1] - self.pts[n - 2]
        } else {
            (self.pts[i + 1] - self.pts[i - 1]) * 0.5
        }
    }

    fn locate(&self, t: f64) -> (usize, f64) {
        let segs = self.pts.len() - 1;
        let s = (t.clamp(0.0, 1.0) * segs as f64).min(segs as f64);
        let i = (s.floor() as usize).min(segs - 1);
        (i, s - i as f64)
    }
}

impl ParamCurveFit for CatmullRom {
    fn sample_pt_tangent(&self, t: f64, _sign: f64) -> CurveFitSample {
        let (p, d) = self.sample_pt_deriv(t);
        CurveFitSample { p, tangent: d }
    }

    fn sample_pt_deriv(&self, t: f64) -> (Point, Vec2) {
        let (i, u) = self.locate(t);
        let (p0, p1) = (self.pts[i].to_vec2(), self.pts[i + 1].to_vec2());
        let (m0, m1) = (self.tangent(i), self.tangent(i + 1));
        let (u2, u3) = (u * u, u * u * u);
        let p = p0 * (2.0 * u3 - 3.0 * u2 + 1.0)
            + m0 * (u3 - 2.0 * u2 + u)
            + p1 * (-2.0 * u3 + 3.0 * u2)
            + m1 * (u3 - u2);
        let d = p0 * (6.0 * u2 - 6.0 * u)
            + m0 * (3.0 * u2 - 4.0 * u + 1.0)
            + p1 * (-6.0 * u2 + 6.0 * u)
            + m1 * (3.0 * u2 - 2.0 * u);
        let segs = (self.pts.len() - 1) as f64;
        (p.to_point(), d * segs)
    }

    fn break_cusp(&self, _range: Range<f64>) -> Option<f64> {
        None
    }
}

/// Runs of data between consecutive sharp points (indices inclusive, wrapping for closed data).
fn runs(data: &[Vector2], closed: bool) -> Vec<Vec<Point>> {
    let n = data.len();
    // The corners subdiv-fit makes sharp (and the ends of open data).
    let mut sharp = scaled_corners(
        data,
        subdiv_fit::Closure::from_closed(closed),
        &FitOptions::new(0.01),
    )
    .unwrap_or_default();
    if !closed {
        sharp.insert(0, 0);
        sharp.push(n - 1);
    }
    let pt = |i: usize| Point::from(data[i % n]);
    let mut out = Vec::new();
    let count = if closed { sharp.len() } else { sharp.len() - 1 };
    for j in 0..count {
        let a = sharp[j];
        let b = if j + 1 < sharp.len() {
            sharp[j + 1]
        } else {
            sharp[0] + n
        };
        out.push((a..=b).map(pt).collect());
    }
    out
}

/// Global two-sided distance between sampled curve pieces and the data.
pub(super) fn two_sided(samples: &[Vector2], data: &[Vector2], closed: bool) -> f64 {
    let mut poly = data.to_vec();
    if closed {
        poly.push(data[0]);
    }
    let d2c = data
        .iter()
        .map(|v| point_polyline_distance(v, samples))
        .fold(0.0, f64::max);
    let c2d = samples
        .iter()
        .map(|s| point_polyline_distance(s, &poly))
        .fold(0.0, f64::max);
    d2c.max(c2d)
}

const SAMPLES: usize = 64;

/// [`two_sided`] for a fitted subdivision curve, sampled `SAMPLES` times per segment.
pub(super) fn curve_two_sided(
    curve: &SubdivCurve<2>,
    data: &[Vector2],
    closed: bool,
) -> Result<f64, DynError> {
    let segs = curve.segment_count();
    let count = segs * SAMPLES;
    let params: Vec<f64> = (0..=count)
        .map(|k| k as f64 * segs as f64 / count as f64)
        .collect();
    let mut samples = Vec::new();
    curve.eval_many(&params, &mut samples)?;
    Ok(two_sided(&samples, data, closed))
}

/// kurbo's fit of every run at `accuracy` (what the time column measures).
fn kurbo_paths(runs: &[Vec<Point>], accuracy: f64) -> Vec<BezPath> {
    runs.iter()
        .map(|run| fit_to_bezpath_opt(&CatmullRom { pts: run.clone() }, accuracy))
        .collect()
}

/// kurbo's fit at `accuracy`: (segments, samples); a line segment counts like a cubic.
fn kurbo_fit(runs: &[Vec<Point>], accuracy: f64) -> (usize, Vec<Vector2>) {
    let mut segs = 0;
    let mut samples = Vec::new();
    for path in kurbo_paths(runs, accuracy) {
        for seg in path.segments() {
            segs += 1;
            for k in 0..=SAMPLES {
                let p = seg.eval(k as f64 / SAMPLES as f64);
                samples.push(p.into());
            }
        }
    }
    (segs, samples)
}

pub(crate) fn table() -> Result<Table, DynError> {
    let mut md = format!(
        "## subdiv-fit against kurbo's `fit_to_bezpath_opt` at the same two-sided error\n\n\
         subdiv-fit: tolerance 0.01, two-sided, interpolation and least squares.\n\
         kurbo: `fit_to_bezpath_opt` on a uniform Catmull–Rom interpolant of each run of data between the same sharp points, with the largest accuracy (bisection) whose two-sided error does not exceed subdiv-fit's.\n\
         Both errors are the same global measure: data to dense curve samples and curve samples to the data polyline.\n\
         Bézier control points count shared end points once.\n\
         Times (not checked) are the median wall-clock of {REPS} release-mode runs on the machine that ran `cargo xtask tables`: subdiv-fit's whole loop (`fit`), and kurbo's `fit_to_bezpath_opt` on all runs at the accuracy found (without the Catmull–Rom set-up or the bisection for the accuracy).\n\n\
         | shape | method | cubic segments | Bézier control points | subdivision control points | two-sided max error | kurbo accuracy | time (ms) |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    let mut rows = Vec::new();
    for (name, data, closed) in [
        ("closed petals", closed_petals(1), true),
        ("open wave", open_wave(1), false),
    ] {
        let extra = usize::from(!closed);
        let mut target = f64::INFINITY;
        for (label, mode) in [
            (
                "subdiv-fit, interpolation",
                subdiv_fit::FitMode::Interpolate,
            ),
            (
                "subdiv-fit, least squares",
                subdiv_fit::FitMode::LeastSquares,
            ),
        ] {
            let opts = FitOptions::new(0.01).with_mode(mode);
            let (f, ms) = median_ms(REPS, || {
                Ok(fit(&data, subdiv_fit::Closure::from_closed(closed), &opts)?)
            })?;
            let segs = f.curve.segment_count();
            let err = curve_two_sided(&f.curve, &data, closed)?;
            target = target.min(err);
            writeln!(
                md,
                "| {name} | {label} | {segs} | {} | {} | {err:.5} | | {ms:.3} |",
                3 * segs + extra,
                f.curve.points().len()
            )?;
            rows.push(json!({"shape": name, "method": label, "segments": segs, "error": err}));
        }
        let runs = runs(&data, closed);
        let (mut lo, mut hi) = (1e-6_f64.ln(), 0.1_f64.ln());
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            let (_, s) = kurbo_fit(&runs, mid.exp());
            if two_sided(&s, &data, closed) <= target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let acc = lo.exp();
        let (segs, s) = kurbo_fit(&runs, acc);
        let err = two_sided(&s, &data, closed);
        let (_, ms) = median_ms(REPS, || Ok(kurbo_paths(&runs, acc)))?;
        writeln!(
            md,
            "| {name} | kurbo `fit_to_bezpath_opt` | {segs} | {} | | {err:.5} | {acc:.5} | {ms:.3} |",
            3 * segs + extra
        )?;
        rows.push(json!({"shape": name, "method": "kurbo", "segments": segs, "error": err}));
    }
    Ok(Table {
        name: "subdiv-fit-kurbo".into(),
        markdown: md,
        checked: Value::Array(rows),
    })
}
