//! Boundary data: clamped least-squares fit of side curves into the side's spline space, and
//! the control-point rows they fix.

use crate::dense::Dense;
use crate::error::PdeError;
use crate::problem::SideCurve;
use crate::space::{End, Space};
use crate::sparse::{Kind, Storage, System};
use bez_core::Vector3;

/// A side curve expressed in a spline space: coefficients and the fit's max sample error.
pub(crate) struct Fitted {
    pub(crate) coefs: Vec<Vector3>,
    pub(crate) error: f64,
}

/// Fits a side curve into `space`: the first `clamp_start` and last `clamp_end` coefficients
/// interpolate the curve's end derivatives (orders 0..clamp), the rest minimize the squared
/// error at the samples (a sparse QR least-squares solve). A Bézier curve of a degree the
/// (non-periodic) space holds is converted exactly by blossoming instead.
pub(crate) fn fit(
    side: &'static str,
    curve: &SideCurve,
    space: &Space,
    clamp_start: usize,
    clamp_end: usize,
) -> Result<Fitted, PdeError> {
    let n = space.n_coef;
    if clamp_start + clamp_end > n {
        return Err(PdeError::DegreeTooLow {
            direction: side,
            degree: space.degree,
            needed: space.degree + clamp_start + clamp_end - n,
            why: "the clamped ends of a boundary curve overlap",
        });
    }
    let default_count = (4 * n).max(64);
    let (ts, values) = samples(side, curve, space, default_count)?;
    let coefs = match curve {
        SideCurve::Bezier(c) if c.degree() <= space.degree && space.to_clamped.is_none() => {
            blossom_coefficients(c, space)?
        }
        _ => fit_samples(side, curve, space, (clamp_start, clamp_end), &ts, &values)?,
    };
    let mut error: f64 = 0.0;
    for (&t, value) in ts.iter().zip(&values) {
        let (support, vals) = space.basis_at(t);
        let p: Vector3 = support.iter().zip(&vals).map(|(&g, &w)| coefs[g] * w).sum();
        error = error.max((p - value).norm());
    }
    Ok(Fitted { coefs, error })
}

/// The B-spline coefficients of a polynomial curve of degree ≤ n: c_i is the blossom of the
/// curve (elevated to degree n) at the knots t_{i+1}, …, t_{i+n} (de Boor–Fix dual
/// functionals), evaluated by de Casteljau steps with one knot per level. Exact up to
/// rounding, with convex combinations only, at any degree.
fn blossom_coefficients(
    curve: &bez_core::BezierCurve<3>,
    space: &Space,
) -> Result<Vec<Vector3>, PdeError> {
    let n = space.degree;
    let elevated = curve.elevate(n - curve.degree())?;
    let points = elevated.points();
    Ok((0..space.n_coef)
        .map(|i| {
            let mut p = points.to_vec();
            for (level, &t) in space.knots[i + 1..=i + n].iter().enumerate() {
                for j in 0..n - level {
                    p[j] = p[j] * (1.0 - t) + p[j + 1] * t;
                }
            }
            p[0]
        })
        .collect())
}

/// The clamped least-squares fit of samples.
fn fit_samples(
    side: &'static str,
    curve: &SideCurve,
    space: &Space,
    (clamp_start, clamp_end): (usize, usize),
    ts: &[f64],
    values: &[Vector3],
) -> Result<Vec<Vector3>, PdeError> {
    let n = space.n_coef;
    let mut coefs: Vec<Option<Vector3>> = vec![None; n];
    for (end, count) in [(End::Start, clamp_start), (End::Finish, clamp_end)] {
        if count == 0 {
            continue;
        }
        let jet = jet(side, curve, end, count)?;
        let d = space.end_derivatives(end, count);
        let cols: Vec<usize> = if end == End::Finish {
            (n - count..n).collect()
        } else {
            (0..count).collect()
        };
        let block = Dense::from_fn(count, count, |a, b| d[(a, cols[b])]);
        let rhs = Dense::from_fn(count, 3, |a, c| jet[a][c]);
        let sol = block.solve(&rhs).ok_or(PdeError::Undetermined {
            method: "boundary clamping",
            unknowns: count,
            condition: f64::INFINITY,
        })?;
        for (a, &col) in cols.iter().enumerate() {
            coefs[col] = Some(Vector3::new(sol[(a, 0)], sol[(a, 1)], sol[(a, 2)]));
        }
    }
    let free: Vec<usize> = (0..n).filter(|&i| coefs[i].is_none()).collect();
    if !free.is_empty() {
        let too_few = PdeError::TooFewSamples {
            side,
            what: "samples",
            given: ts.len(),
            needed: free.len() + clamp_start + clamp_end,
        };
        if ts.len() < free.len() {
            return Err(too_few);
        }
        let mut index = vec![usize::MAX; n];
        for (k, &i) in free.iter().enumerate() {
            index[i] = k;
        }
        let mut system = System::new(ts.len(), free.len());
        for (row, (&t, value)) in ts.iter().zip(values).enumerate() {
            let (support, vals) = space.basis_at(t);
            let mut target = *value;
            for (&g, &w) in support.iter().zip(&vals) {
                match coefs[g] {
                    Some(c) => target -= c * w,
                    None => system.push(row, index[g], w),
                }
            }
            system.rhs[row] = target.to_array();
        }
        let solved = match system.solve(Kind::LeastSquares, Storage::Auto, "boundary fit") {
            Err(PdeError::Undetermined { .. }) => return Err(too_few),
            other => other?,
        };
        for (k, &i) in free.iter().enumerate() {
            let [x, y, z] = solved.x[k];
            coefs[i] = Some(Vector3::new(x, y, z));
        }
    }
    Ok(coefs.into_iter().map(Option::unwrap_or_default).collect())
}

fn check_finite(v: &Vector3) -> Result<(), PdeError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(&value) => Err(PdeError::NonFinite {
            what: "boundary sample",
            value,
        }),
        None => Ok(()),
    }
}

fn samples(
    side: &'static str,
    curve: &SideCurve,
    space: &Space,
    count: usize,
) -> Result<(Vec<f64>, Vec<Vector3>), PdeError> {
    let uniform =
        |count: usize| -> Vec<f64> { (0..count).map(|i| i as f64 / (count - 1) as f64).collect() };
    let out = match curve {
        SideCurve::Bezier(c) => {
            let ts = uniform(count);
            let mut vals = Vec::with_capacity(count);
            c.eval_many(&ts, &mut vals)?;
            (ts, vals)
        }
        SideCurve::Pieces(pieces) => {
            if pieces.len() != space.pieces.len() {
                return Err(PdeError::PieceCount {
                    side,
                    given: pieces.len(),
                    expected: space.pieces.len(),
                });
            }
            let per = (count / pieces.len()).max(2 * space.degree + 2);
            let mut ts = Vec::new();
            let mut vals = Vec::new();
            let h = 1.0 / pieces.len() as f64;
            for (p, piece) in pieces.iter().enumerate() {
                for k in 0..per {
                    let s = k as f64 / (per - 1) as f64;
                    ts.push((p as f64 + s) * h);
                    vals.push(piece.eval(s)?);
                }
            }
            (ts, vals)
        }
        SideCurve::Sampled { values, .. } => {
            if values.len() < 2 {
                return Err(PdeError::TooFewSamples {
                    side,
                    what: "samples",
                    given: values.len(),
                    needed: space.n_coef,
                });
            }
            (uniform(values.len()), values.clone())
        }
    };
    for v in &out.1 {
        check_finite(v)?;
    }
    Ok(out)
}

fn jet(
    side: &'static str,
    curve: &SideCurve,
    end: End,
    count: usize,
) -> Result<Vec<Vector3>, PdeError> {
    let at_end = end == End::Finish;
    let t = if at_end { 1.0 } else { 0.0 };
    let out = match curve {
        SideCurve::Bezier(c) => c.eval_derivatives(t, count - 1)?,
        SideCurve::Pieces(pieces) => {
            let piece = if at_end {
                pieces.last()
            } else {
                pieces.first()
            };
            let Some(piece) = piece else {
                return Err(PdeError::PieceCount {
                    side,
                    given: 0,
                    expected: 1,
                });
            };
            let scale = pieces.len() as f64;
            piece
                .eval_derivatives(t, count - 1)?
                .into_iter()
                .enumerate()
                .map(|(d, v)| v * scale.powi(d as i32))
                .collect()
        }
        SideCurve::Sampled {
            start_jet, end_jet, ..
        } => {
            let jet = if at_end { end_jet } else { start_jet };
            if jet.len() < count {
                return Err(PdeError::TooFewSamples {
                    side,
                    what: "end derivatives",
                    given: jet.len(),
                    needed: count,
                });
            }
            jet[..count].to_vec()
        }
    };
    for v in &out {
        check_finite(v)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamped_fit_reproduces_polynomials_and_interpolates_ends() {
        let space = Space::new("v", 5, 3, 2, false).unwrap();
        // A cubic: exact in the space.
        let f = |t: f64, d: usize| -> Vector3 {
            match d {
                0 => Vector3::new(t * t * t - t, 2.0 * t, 1.0 - t * t),
                1 => Vector3::new(3.0 * t * t - 1.0, 2.0, -2.0 * t),
                _ => Vector3::new(6.0 * t, 0.0, -2.0),
            }
        };
        let curve = SideCurve::from_function(101, 3, f).unwrap();
        let fitted = fit("v=0", &curve, &space, 2, 3).unwrap();
        assert!(fitted.error < 1e-13, "{}", fitted.error);
        // A non-polynomial function: the clamped ends still interpolate value and slope.
        let g = |t: f64, d: usize| -> Vector3 {
            let s = if d == 0 {
                (4.0 * t).sin()
            } else {
                4.0 * (4.0 * t).cos()
            };
            Vector3::new(s, 0.0, 0.0)
        };
        let curve = SideCurve::from_function(101, 2, g).unwrap();
        let fitted = fit("v=0", &curve, &space, 2, 2).unwrap();
        assert!(
            fitted.error > 1e-9 && fitted.error < 1e-3,
            "{}",
            fitted.error
        );
        let d0 = space.end_derivatives(End::Start, 2);
        let d1 = space.end_derivatives(End::Finish, 2);
        for (d, at, end) in [(&d0, 0.0, 0), (&d1, 1.0, 1)] {
            for order in 0..2 {
                let value: f64 = (0..space.n_coef)
                    .map(|i| d[(order, i)] * fitted.coefs[i].x())
                    .sum();
                assert!(
                    (value - g(at, order).x()).abs() < 1e-12,
                    "end {end} order {order}"
                );
            }
        }
    }
}
