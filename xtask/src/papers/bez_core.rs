//! bez-core's illustrations: the Bernstein basis and de Casteljau subdivision.

use std::path::{Path, PathBuf};

use bez_core::{BezierCurve, Vector2, bernstein_row};

use crate::DynError;
use crate::plot::{Plot, Series, Style};

/// Writes `bernstein-basis-5.svg` and `subdivision.svg`.
pub(crate) fn figures(dir: &Path) -> Result<Vec<PathBuf>, DynError> {
    let n = 5;
    let samples = 201;
    let mut rows = vec![Vec::with_capacity(samples); n + 1];
    let mut row = vec![0.0; n + 1];
    for k in 0..samples {
        let t = k as f64 / (samples - 1) as f64;
        bernstein_row(t, &mut row);
        for (i, r) in row.iter().enumerate() {
            rows[i].push((t, *r));
        }
    }
    let mut basis = Plot::new("Bernstein basis of degree 5", "t", "B(i,5)(t)");
    for (i, pts) in rows.into_iter().enumerate() {
        basis = basis.with(Series::new(format!("B({i},5)"), pts, Style::Line));
    }

    let curve = BezierCurve::new(vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 2.5),
        Vector2::new(3.0, 3.0),
        Vector2::new(4.5, -0.5),
        Vector2::new(6.0, 1.0),
    ])?;
    let (left, right) = curve.split(0.4)?;
    let xy = |p: &[Vector2]| p.iter().map(|q| (q.x(), q.y())).collect::<Vec<_>>();
    let split = Plot::new("de Casteljau subdivision at t = 0.4", "x", "y")
        .equal()
        .with(Series::new(
            "curve",
            xy(&curve.sample_uniform(200)?),
            Style::Line,
        ))
        .with(Series::new(
            "control polygon",
            xy(curve.points()),
            Style::LinePoints,
        ))
        .with(Series::new(
            "left piece",
            xy(left.points()),
            Style::LinePoints,
        ))
        .with(Series::new(
            "right piece",
            xy(right.points()),
            Style::LinePoints,
        ))
        .with(Series::new("B(0.4)", xy(&[left.end()]), Style::Points));
    Ok(vec![
        basis.write_svg(&dir.join("bernstein-basis-5.svg"))?,
        split.write_svg(&dir.join("subdivision.svg"))?,
    ])
}
