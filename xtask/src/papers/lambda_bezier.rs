//! Wu 2006, λ-Bézier curves: Figs. 1–8, the valid λ interval, and the circle table.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::brent::BrentOpt;
use bez_core::{BezierCurve, BezierForm, Vector2};
use lambda_bezier::cases::{
    AKIMA_LAMBDAS, CIRCLE_LAMBDA, QUARTIC_LAMBDAS, QUINTIC_LAMBDAS, akima_data, arch_points,
    circle_error, circle_halves, circle_points, cubic_half_circle, cubic_quarter_circle,
    lambda_half_circle_error, leaf_points, max_radial_error, vase_profile,
};
use lambda_bezier::{LambdaBasis, LambdaBezierCurve, LambdaRange, shape_preserving_curves};
use serde_json::json;

use crate::DynError;
use crate::plot::{Plot, Series, Style};
use crate::tables::Table;

type Xy = Vec<(f64, f64)>;

fn xy(points: &[Vector2]) -> Xy {
    points.iter().map(|p| (p.x(), p.y())).collect()
}

fn polyline(curves: &[LambdaBezierCurve<2>], per_curve: usize) -> Result<Xy, DynError> {
    let mut out = Xy::new();
    for c in curves {
        out.extend(xy(&c.sample_uniform(per_curve)?));
    }
    Ok(out)
}

/// Writes the figures into `dir`.
pub(crate) fn figures(dir: &Path) -> Result<Vec<PathBuf>, DynError> {
    let mut out = Vec::new();
    // Figs. 1–2: the basis at λ = −1, degrees 4 and 5.
    for (fig, n) in [(1, 3), (2, 4)] {
        let b = LambdaBasis::new(n, -1.0)?;
        let mut rows: Vec<Xy> = vec![Vec::new(); n + 1];
        let mut row = vec![0.0; n + 1];
        for i in 0..=200 {
            let t = f64::from(i) / 200.0;
            b.row(t, &mut row)?;
            for (k, v) in row.iter().enumerate() {
                rows[k].push((t, *v));
            }
        }
        let mut p = Plot::new(
            format!("Fig. {fig}: λ-B basis of degree {}, λ = −1", n + 1),
            "t",
            "b(k, n+1)(t)",
        );
        for (k, pts) in rows.into_iter().enumerate() {
            p = p.with(Series::new(format!("b({k},{})", n + 1), pts, Style::Line));
        }
        out.push(p.write_svg(&dir.join(format!("fig{fig}-basis-degree{}.svg", n + 1)))?);
    }
    // Figs. 3–4: one control polygon, the paper's λ values.
    for (fig, n, lambdas) in [(3, 3, &QUARTIC_LAMBDAS[..]), (4, 4, &QUINTIC_LAMBDAS[..])] {
        let pts = arch_points(n);
        let mut p = Plot::new(
            format!("Fig. {fig}: λ-Bézier curves of degree {}", n + 1),
            "x",
            "y",
        )
        .equal()
        .with(Series::new("control polygon", xy(&pts), Style::LinePoints));
        for &l in lambdas {
            let c = LambdaBezierCurve::new(pts.clone(), l)?;
            p = p.with(Series::new(
                format!("λ = {l}"),
                xy(&c.sample_uniform(200)?),
                Style::Line,
            ));
        }
        out.push(p.write_svg(&dir.join(format!("fig{fig}-curves-degree{}.svg", n + 1)))?);
    }
    // Fig. 5: shape-preserving G1 interpolation of Akima's data (our construction).
    let data = akima_data();
    for (sub, lambdas) in ["a", "b"].iter().zip(AKIMA_LAMBDAS.iter()) {
        let curves = shape_preserving_curves(&data, lambdas)?;
        let mut polygon: Vec<Vector2> = Vec::new();
        for c in &curves {
            polygon.extend_from_slice(&c.points()[..2]);
        }
        polygon.push(data[data.len() - 1]);
        let p = Plot::new(
            format!("Fig. 5({sub}): G1 cubic λ-curves on Akima's data, λ cycling {lambdas:?}"),
            "x",
            "y",
        )
        .with(Series::new(
            "control polygons",
            xy(&polygon),
            Style::LinePoints,
        ))
        .with(Series::new(
            "interpolant",
            polyline(&curves, 100)?,
            Style::Line,
        ))
        .with(Series::new("data", xy(&data), Style::Points));
        out.push(p.write_svg(&dir.join(format!("fig5{sub}-akima.svg")))?);
    }
    // Fig. 6: the circle at λ = 0.56, and at the λ minimizing the radial error.
    let best = best_circle_lambda()?;
    let circle: Xy = (0..=360)
        .map(|i| f64::from(i).to_radians())
        .map(|a| (a.cos(), a.sin()))
        .collect();
    let mut p = Plot::new("Fig. 6: quartic λ-Bézier circle, λ = 0.56", "x", "y")
        .equal()
        .with(Series::new("unit circle", circle, Style::Line))
        .with(Series::new(
            "control polygon",
            xy(&circle_points()),
            Style::LinePoints,
        ));
    for l in [CIRCLE_LAMBDA, best] {
        let halves = circle_halves(l)?;
        p = p.with(Series::new(
            // Four decimals: the last digits of Brent's minimizer are rounding noise.
            format!("λ = {l:.4}"),
            polyline(&halves, 200)?,
            Style::Line,
        ));
    }
    out.push(p.write_svg(&dir.join("fig6-circle.svg"))?);
    let mut e = Plot::new(
        "Fig. 6 (detail): radial error |B(t)| − 1 of the upper half",
        "t",
        "|B(t)| − 1",
    );
    for (label, l) in [
        ("λ = 0.56 (paper)".to_owned(), CIRCLE_LAMBDA),
        (format!("λ = {best:.4} (minimax)"), best),
        ("λ = 0 (cubic Bézier)".to_owned(), 0.0),
    ] {
        let [upper, _] = circle_halves(l)?;
        let pts = (0..=400)
            .map(|i| {
                let t = f64::from(i) / 400.0;
                Ok((t, upper.eval(t)?.norm() - 1.0))
            })
            .collect::<Result<Xy, DynError>>()?;
        e = e.with(Series::new(label, pts, Style::Line));
    }
    out.push(e.write_svg(&dir.join("fig6-circle-radial-error.svg"))?);
    // Fig. 7: closed leaves, P0 = P3, λ = 1, 0, −1, −2, −3; and a five-petal flower.
    let mut p = Plot::new("Fig. 7: closed quartic λ-curves (leaf)", "x", "y").equal();
    p = p.with(Series::new(
        "control polygon",
        xy(&leaf_points(0.0)),
        Style::LinePoints,
    ));
    for &l in &QUARTIC_LAMBDAS {
        let c = LambdaBezierCurve::new(leaf_points(0.0), l)?;
        p = p.with(Series::new(
            format!("λ = {l}"),
            xy(&c.sample_uniform(200)?),
            Style::Line,
        ));
    }
    out.push(p.write_svg(&dir.join("fig7-leaf.svg"))?);
    let mut p = Plot::new("Fig. 7: petal pattern, one petal per λ", "x", "y").equal();
    for (i, &l) in QUARTIC_LAMBDAS.iter().enumerate() {
        let angle = std::f64::consts::TAU * i as f64 / QUARTIC_LAMBDAS.len() as f64;
        let c = LambdaBezierCurve::new(leaf_points(angle), l)?;
        p = p.with(Series::new(
            format!("λ = {l}"),
            xy(&c.sample_uniform(200)?),
            Style::Line,
        ));
    }
    out.push(p.write_svg(&dir.join("fig7-petals.svg"))?);
    // Fig. 8: the vase, six C1-joined segments, degrees 4 and 5, two λ settings each.
    for (sub, n) in [("a", 3), ("b", 4)] {
        let mut p = Plot::new(
            format!("Fig. 8({sub}): vase of six degree-{} λ-curves", n + 1),
            "x",
            "y",
        )
        .equal();
        for lambdas in [vec![0.0], vec![1.0, -2.0, 1.0, -2.0, 1.0, -2.0]] {
            let right = polyline(&vase_profile(n, &lambdas)?, 80)?;
            // One outline: left side top to bottom, the base, right side bottom to top.
            let mut outline: Xy = right.iter().rev().map(|&(x, y)| (-x, y)).collect();
            outline.extend_from_slice(&right);
            p = p.with(Series::new(
                format!("λ = {lambdas:?}"),
                outline,
                Style::Line,
            ));
        }
        out.push(p.write_svg(&dir.join(format!("fig8{sub}-vase-degree{}.svg", n + 1)))?);
    }
    // The valid interval's lower end against −n.
    let lows: Xy = (2..=60)
        .map(|n| Ok((n as f64, LambdaRange::new(n)?.min())))
        .collect::<Result<_, DynError>>()?;
    let minus_n: Xy = (2..=8).map(|n| (f64::from(n), -f64::from(n))).collect();
    let p = Plot::new(
        "Lower end of the valid λ interval",
        "n (degree n + 1)",
        "λ min",
    )
    .with(Series::new(
        "exact −n(n−1)/max j(n+1−2j)",
        lows,
        Style::LinePoints,
    ))
    .with(Series::new(
        "−n (the paper's pattern)",
        minus_n,
        Style::Line,
    ))
    .with(Series::new(
        "−8 (limit)",
        vec![(2.0, -8.0), (60.0, -8.0)],
        Style::Line,
    ));
    out.push(p.write_svg(&dir.join("lambda-range.svg"))?);
    Ok(out)
}

/// A one-dimensional cost for argmin's Brent minimizer.
struct Cost<F: Fn(f64) -> Result<f64, DynError>>(F);

impl<F: Fn(f64) -> Result<f64, DynError>> CostFunction for Cost<F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, x: &f64) -> Result<f64, argmin::core::Error> {
        (self.0)(*x).map_err(|e| argmin::core::Error::msg(e.to_string()))
    }
}

/// Minimizes f on [a, b]: a 401-point scan brackets the minimum, Brent refines it.
fn minimize(f: impl Fn(f64) -> Result<f64, DynError>, a: f64, b: f64) -> Result<f64, DynError> {
    let step = (b - a) / 400.0;
    let mut best = (f64::INFINITY, a);
    for i in 0..=400 {
        let x = a + step * f64::from(i);
        let v = f(x)?;
        if v < best.0 {
            best = (v, x);
        }
    }
    let lo = (best.1 - step).max(a);
    let hi = (best.1 + step).min(b);
    let solver = BrentOpt::new(lo, hi).set_tolerance(f64::EPSILON.sqrt(), 1e-13);
    let res = Executor::new(Cost(f), solver)
        .configure(|s| s.max_iters(200))
        .run()
        .map_err(|e| e.to_string())?;
    res.state()
        .get_best_param()
        .copied()
        .ok_or_else(|| "Brent returned no parameter".into())
}

/// λ of the quartic half circles with the least radial error, by the library's optimizer.
fn best_circle_lambda() -> Result<f64, DynError> {
    let range = LambdaRange::new(3)?;
    Ok(lambda_bezier::minimize_over_range(&range, |l| {
        circle_error(l).unwrap_or(f64::INFINITY)
    })?)
}

fn err(c: &BezierCurve<2>) -> f64 {
    max_radial_error(c).0
}

/// The circle table and the valid-interval table.
pub(crate) fn tables() -> Result<Vec<Table>, DynError> {
    Ok(vec![circle_table()?, range_table()?])
}

fn circle_table() -> Result<Table, DynError> {
    let best_l = best_circle_lambda()?;
    let best_h = minimize(|h| Ok(err(&cubic_half_circle(h)?)), 1.0, 1.6)?;
    let best_k = minimize(|k| Ok(err(&cubic_quarter_circle(k)?)), 0.5, 0.6)?;
    let mid_k = 4.0 * (2f64.sqrt() - 1.0) / 3.0;
    // Beyond the paper: free height h and λ together (nested Brent searches).
    let inner = |h: f64| minimize(|l| Ok(lambda_half_circle_error(h, l)?), -3.0, 1.0);
    let joint_h = minimize(|h| Ok(lambda_half_circle_error(h, inner(h)?)?), 1.0, 1.6)?;
    let joint_l = inner(joint_h)?;
    let rows: Vec<(String, String, f64, &str)> = vec![
        (
            "quartic λ-curve, 2 halves, P as in §4.2".into(),
            format!("λ = {CIRCLE_LAMBDA}"),
            circle_error(CIRCLE_LAMBDA)?,
            "λ = 0.56, \"approximates the circle well\" (no error given)",
        ),
        (
            "quartic λ-curve, 2 halves, P as in §4.2".into(),
            format!("λ* = {best_l:.8} (argmin Brent)"),
            circle_error(best_l)?,
            "—",
        ),
        (
            "quartic λ-curve, 2 halves, free height h".into(),
            format!("h* = {joint_h:.8}, λ* = {joint_l:.8} (nested Brent)"),
            lambda_half_circle_error(joint_h, joint_l)?,
            "—",
        ),
        (
            "same points, λ = 0: cubic Bézier".into(),
            "λ = 0".into(),
            circle_error(0.0)?,
            "—",
        ),
        (
            "cubic Bézier half circle, midpoint on circle".into(),
            "h = 4/3".into(),
            err(&cubic_half_circle(4.0 / 3.0)?),
            "—",
        ),
        (
            "cubic Bézier half circle, best h".into(),
            format!("h* = {best_h:.8} (argmin Brent)"),
            err(&cubic_half_circle(best_h)?),
            "—",
        ),
        (
            "cubic Bézier quarter circle (4 pieces), midpoint on circle".into(),
            "k = 4(√2−1)/3".into(),
            err(&cubic_quarter_circle(mid_k)?),
            "—",
        ),
        (
            "cubic Bézier quarter circle (4 pieces), best k".into(),
            format!("k* = {best_k:.8} (argmin Brent)"),
            err(&cubic_quarter_circle(best_k)?),
            "—",
        ),
    ];
    let mut md = String::from(
        "### λ-Bézier circle (Wu 2006, §4.2, Fig. 6): max radial error max_t ||B(t)| − 1|\n\n\
         | curve | parameter | max radial error (ours) | paper |\n|---|---|---|---|\n",
    );
    for (curve, param, e, paper) in &rows {
        writeln!(md, "| {curve} | {param} | {e:.4e} | {paper} |")?;
    }
    let checked = json!({
        "lambda_056_error": rows[0].2,
        "best_lambda": best_l,
        "best_lambda_error": rows[1].2,
        "joint_h": joint_h,
        "joint_lambda": joint_l,
        "joint_error": rows[2].2,
        "lambda_0_error": rows[3].2,
        "half_circle_h43_error": rows[4].2,
        "best_h": best_h,
        "best_h_error": rows[5].2,
        "quarter_mid_error": rows[6].2,
        "best_k": best_k,
        "best_k_error": rows[7].2,
    });
    Ok(Table {
        name: "lambda-bezier-circle".into(),
        markdown: md,
        checked,
    })
}

fn range_table() -> Result<Table, DynError> {
    let mut md = String::from(
        "### Valid λ interval of the degree n + 1 λ-B basis (all basis functions ≥ 0 on [0, 1])\n\n\
         | n | degree | ours: exact min | ours: min | binding j | paper | −n |\n|---|---|---|---|---|---|---|\n",
    );
    let mut checked = Vec::new();
    for n in (2..=16).chain([20, 30, 50, 100, 1000, 100_000]) {
        let r = LambdaRange::new(n)?;
        let (num, den) = r.min_fraction();
        let g = gcd(num, den);
        let paper = match n {
            2 => "[−2, 1]",
            3 => "[−3, 1]",
            4 => "[−4, 1]",
            _ => "—",
        };
        writeln!(
            md,
            "| {n} | {} | [−{}/{}, 1] | {:.6} | {} | {paper} | {} |",
            n + 1,
            num / g,
            den / g,
            r.min(),
            r.binding_index(),
            -(n as i64)
        )?;
        checked.push(json!({"n": n, "num": num / g, "den": den / g, "j": r.binding_index()}));
    }
    Ok(Table {
        name: "lambda-bezier-range".into(),
        markdown: md,
        checked: json!(checked),
    })
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}
