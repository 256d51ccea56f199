//! Boundary data: clamped least-squares fit of side curves into the side's spline space, and
//! the control-point rows they fix.

use crate::error::PdeError;
use crate::problem::SideCurve;
use crate::space::Space;
use bez_core::Vector3;
use nalgebra::{DMatrix, Dyn, U3};

/// A side curve expressed in a spline space: coefficients and the fit's max sample error.
pub(crate) struct Fitted {
    pub(crate) coefs: Vec<Vector3>,
    pub(crate) error: f64,
}

/// Fits a side curve into `space`: the first `clamp_start` and last `clamp_end` coefficients
/// interpolate the curve's end derivatives (orders 0..clamp), the rest minimize the squared
/// error at the samples. Polynomial data of a degree the space holds is reproduced exactly.
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
    let mut coefs: Vec<Option<Vector3>> = vec![None; n];
    for (at_end, count) in [(false, clamp_start), (true, clamp_end)] {
        if count == 0 {
            continue;
        }
        let jet = jet(side, curve, at_end, count)?;
        let d = space.end_derivatives(at_end, count);
        let cols: Vec<usize> = if at_end {
            (n - count..n).collect()
        } else {
            (0..count).collect()
        };
        let block = DMatrix::from_fn(count, count, |a, b| d[(a, cols[b])]);
        let rhs = DMatrix::from_fn(count, 3, |a, c| jet[a][c]);
        let sol = block.lu().solve(&rhs).ok_or(PdeError::SingularSystem {
            method: "boundary clamping",
            unknowns: count,
            pivot_ratio: 0.0,
        })?;
        for (a, &col) in cols.iter().enumerate() {
            coefs[col] = Some(Vector3::new(sol[(a, 0)], sol[(a, 1)], sol[(a, 2)]));
        }
    }
    let free: Vec<usize> = (0..n).filter(|&i| coefs[i].is_none()).collect();
    if !free.is_empty() {
        let mut index = vec![usize::MAX; n];
        for (k, &i) in free.iter().enumerate() {
            index[i] = k;
        }
        let mut a = DMatrix::<f64>::zeros(ts.len(), free.len());
        let mut b = nalgebra::OMatrix::<f64, Dyn, U3>::zeros(ts.len());
        for (row, (&t, value)) in ts.iter().zip(&values).enumerate() {
            let (support, vals) = space.basis_at(t);
            let mut target = *value;
            for (&g, &w) in support.iter().zip(&vals) {
                match coefs[g] {
                    Some(c) => target -= c * w,
                    None => a[(row, index[g])] += w,
                }
            }
            b.set_row(row, &nalgebra::RowVector3::from(target.to_array()));
        }
        let svd = a.svd(true, true);
        let smax = svd.singular_values.max();
        let smin = svd.singular_values.min();
        if smin.is_nan() || smin <= 1e-10 * smax || ts.len() < free.len() {
            return Err(PdeError::TooFewSamples {
                side,
                what: "samples",
                given: ts.len(),
                needed: free.len() + clamp_start + clamp_end,
            });
        }
        let x = svd.solve(&b, 0.0).map_err(|_| PdeError::SingularSystem {
            method: "boundary fit",
            unknowns: free.len(),
            pivot_ratio: smin / smax,
        })?;
        for (k, &i) in free.iter().enumerate() {
            coefs[i] = Some(Vector3::new(x[(k, 0)], x[(k, 1)], x[(k, 2)]));
        }
    }
    let coefs: Vec<Vector3> = coefs.into_iter().map(Option::unwrap_or_default).collect();
    let mut error: f64 = 0.0;
    for (&t, value) in ts.iter().zip(&values) {
        let (support, vals) = space.basis_at(t);
        let p: Vector3 = support.iter().zip(&vals).map(|(&g, &w)| coefs[g] * w).sum();
        error = error.max((p - value).norm());
    }
    Ok(Fitted { coefs, error })
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
    at_end: bool,
    count: usize,
) -> Result<Vec<Vector3>, PdeError> {
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
        let curve = SideCurve::from_function(101, 3, f);
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
        let curve = SideCurve::from_function(101, 2, g);
        let fitted = fit("v=0", &curve, &space, 2, 2).unwrap();
        assert!(
            fitted.error > 1e-9 && fitted.error < 1e-3,
            "{}",
            fitted.error
        );
        let d0 = space.end_derivatives(false, 2);
        let d1 = space.end_derivatives(true, 2);
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
