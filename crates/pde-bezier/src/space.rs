//! One-dimensional spline spaces on a uniform grid, with Bézier extraction per piece.
//!
//! The C^r piecewise polynomials of degree n on P uniform pieces of [0, 1] are the B-splines
//! on the clamped knot vector with interior knots of multiplicity n − r. Their coefficients
//! are the unknowns of the improved algorithm; Bézier extraction (Boehm knot insertion up to
//! multiplicity n) gives each piece's Bernstein coefficients as a linear map of them, so no
//! continuity constraint is ever carried. A periodic space keeps C^r across the seam t = 0 ≡ 1
//! by expressing the first r + 1 coefficients through the last r + 1.

use crate::bernstein_ops::bernstein_values;
use crate::error::PdeError;
use bez_core::binomial;
use nalgebra::DMatrix;

/// The Bézier extraction of one piece: its (n+1) Bernstein coefficients as a linear map
/// of the spline coefficients in `support`.
#[derive(Debug, Clone)]
pub(crate) struct Piece {
    /// Indices of the spline coefficients that act on this piece.
    pub(crate) support: Vec<usize>,
    /// (n+1) × support.len() extraction matrix.
    pub(crate) ext: DMatrix<f64>,
}

/// A uniform spline space on [0, 1].
#[derive(Debug, Clone)]
pub(crate) struct Space {
    pub(crate) degree: usize,
    pub(crate) pieces: Vec<Piece>,
    pub(crate) n_coef: usize,
    /// The clamped knot vector (interior multiplicity n − r).
    pub(crate) knots: Vec<f64>,
    /// Clamped B-spline coefficients as a map of the unknowns (None: the identity; periodic
    /// spaces express their first r + 1 coefficients through the last r + 1).
    pub(crate) to_clamped: Option<DMatrix<f64>>,
    /// One collocation abscissa per coefficient (Greville abscissae; those of the periodic
    /// knot sequence when periodic).
    pub(crate) greville: Vec<f64>,
}

impl Space {
    /// Builds the space of C^r piecewise polynomials of degree n on `pieces` uniform pieces.
    pub(crate) fn new(
        direction: &'static str,
        degree: usize,
        pieces: usize,
        smoothness: usize,
        periodic: bool,
    ) -> Result<Self, PdeError> {
        let n = degree;
        if n == 0 {
            return Err(PdeError::DegreeTooLow {
                direction,
                degree: n,
                needed: 1,
                why: "a surface needs degree at least 1",
            });
        }
        if (pieces > 1 || periodic) && smoothness >= n {
            return Err(PdeError::Smoothness {
                direction,
                smoothness,
                min: 0,
                max: n - 1,
                why: "C^n joins would make the pieces one polynomial",
            });
        }
        let mult = n - smoothness.min(n - 1);
        // Clamped knot vector.
        let mut knots: Vec<f64> = vec![0.0; n + 1];
        for p in 1..pieces {
            knots.extend(std::iter::repeat_n(p as f64 / pieces as f64, mult));
        }
        knots.extend(std::iter::repeat_n(1.0, n + 1));
        let n_coef = knots.len() - n - 1;
        let greville: Vec<f64> = (0..n_coef)
            .map(|i| knots[i + 1..=i + n].iter().sum::<f64>() / n as f64)
            .collect();
        let clamped_knots = knots.clone();
        // Boehm insertion of every interior knot up to multiplicity n, on the identity.
        let mut coefs = DMatrix::<f64>::identity(n_coef, n_coef);
        for p in 1..pieces {
            let x = p as f64 / pieces as f64;
            for _ in mult..n {
                (knots, coefs) = insert_knot(&knots, &coefs, n, x);
            }
        }
        let mut out = Vec::with_capacity(pieces);
        for p in 0..pieces {
            let rows = coefs.rows(p * n, n + 1).into_owned();
            out.push(local_piece(&rows));
        }
        let mut space = Self {
            knots: clamped_knots,
            to_clamped: None,
            degree: n,
            pieces: out,
            n_coef,
            greville,
        };
        if periodic {
            space = space.into_periodic(direction, smoothness)?;
        }
        Ok(space)
    }

    /// Width of one piece.
    pub(crate) fn width(&self) -> f64 {
        1.0 / self.pieces.len() as f64
    }

    /// The piece containing t and the local parameter in it.
    pub(crate) fn locate(&self, t: f64) -> (usize, f64) {
        let count = self.pieces.len();
        let scaled = t.clamp(0.0, 1.0) * count as f64;
        let p = (scaled.floor() as usize).min(count - 1);
        (p, scaled - p as f64)
    }

    /// Values of the basis functions at t: (support, values).
    pub(crate) fn basis_at(&self, t: f64) -> (&[usize], Vec<f64>) {
        let (p, s) = self.locate(t);
        let piece = &self.pieces[p];
        let b = bernstein_values(self.degree, s);
        let vals = (0..piece.support.len())
            .map(|c| (0..=self.degree).map(|i| b[i] * piece.ext[(i, c)]).sum())
            .collect();
        (&piece.support, vals)
    }

    /// Derivatives of orders 0..count at the start (`at_end = false`) or the end of [0, 1]:
    /// a count × n_coef matrix D with D[d][l] = N_l^(d)(end).
    pub(crate) fn end_derivatives(&self, at_end: bool, count: usize) -> DMatrix<f64> {
        let n = self.degree;
        let piece = if at_end {
            &self.pieces[self.pieces.len() - 1]
        } else {
            &self.pieces[0]
        };
        let h = self.width();
        let mut d = DMatrix::<f64>::zeros(count, self.n_coef);
        for order in 0..count.min(n + 1) {
            // d-th derivative of a Bézier piece at an end, in the global parameter:
            // n!/(n−d)! h^{−d} Σ_l (−1)^{d−l} C(d,l) b_{start+l}.
            let falling: f64 = (0..order).map(|i| (n - i) as f64).product();
            let scale = falling / h.powi(order as i32);
            let start = if at_end { n - order } else { 0 };
            for l in 0..=order {
                let sign = if (order - l) % 2 == 0 { 1.0 } else { -1.0 };
                let w = scale * sign * binomial(order, l);
                for (c, &g) in piece.support.iter().enumerate() {
                    d[(order, g)] += w * piece.ext[(start + l, c)];
                }
            }
        }
        d
    }

    /// Closes the clamped space periodically with C^r at the seam: the first r + 1
    /// coefficients become T · (last r + 1), T = D₀⁻¹ D₁ from the end derivatives.
    fn into_periodic(self, direction: &'static str, smoothness: usize) -> Result<Self, PdeError> {
        let r1 = smoothness + 1;
        let n = self.n_coef;
        if n < 2 * r1 {
            return Err(PdeError::DegreeTooLow {
                direction,
                degree: self.degree,
                needed: 2 * smoothness + 1,
                why: "a periodic closure with C^r at the seam needs 2(r + 1) coefficients",
            });
        }
        let d0 = self.end_derivatives(false, r1).columns(0, r1).into_owned();
        let d1 = self
            .end_derivatives(true, r1)
            .columns(n - r1, r1)
            .into_owned();
        let t = d0.lu().solve(&d1).ok_or(PdeError::SingularSystem {
            method: "periodic closure",
            unknowns: r1,
            pivot_ratio: 0.0,
        })?;
        // c = Z w with w = (c_{r+1}, …, c_{n−1}).
        let nw = n - r1;
        let mut z = DMatrix::<f64>::zeros(n, nw);
        for i in 0..nw {
            z[(r1 + i, i)] = 1.0;
        }
        for i in 0..r1 {
            for j in 0..r1 {
                z[(i, nw - r1 + j)] = t[(i, j)];
            }
        }
        let pieces = self
            .pieces
            .iter()
            .map(|piece| {
                let sub =
                    DMatrix::from_fn(piece.support.len(), nw, |a, b| z[(piece.support[a], b)]);
                local_piece(&(&piece.ext * sub))
            })
            .collect();
        // Clamped Greville abscissae cluster at the seam: use those of the periodic knot
        // sequence t_k = ⌊k/μ⌋ h (every knot of multiplicity μ = n − r), modulo 1.
        let mu = self.degree - smoothness;
        let h = self.width();
        let greville = (0..nw)
            .map(|i| {
                let sum: usize = (i + 1..=i + self.degree).map(|k| k / mu).sum();
                (sum as f64 * h / self.degree as f64).rem_euclid(1.0)
            })
            .collect();
        Ok(Self {
            knots: self.knots,
            to_clamped: Some(z),
            degree: self.degree,
            pieces,
            n_coef: nw,
            greville,
        })
    }
}

/// Keeps the nonzero columns of a full extraction block.
fn local_piece(rows: &DMatrix<f64>) -> Piece {
    let support: Vec<usize> = (0..rows.ncols())
        .filter(|&c| rows.column(c).iter().any(|&x| x != 0.0))
        .collect();
    let ext = DMatrix::from_fn(rows.nrows(), support.len(), |i, c| rows[(i, support[c])]);
    Piece { support, ext }
}

/// Boehm's knot insertion of x, applied to the rows of a coefficient matrix.
fn insert_knot(knots: &[f64], coefs: &DMatrix<f64>, n: usize, x: f64) -> (Vec<f64>, DMatrix<f64>) {
    // k: last index with knots[k] ≤ x; s: multiplicity of x already present.
    let k = knots.iter().rposition(|&u| u <= x).unwrap_or(0);
    let s = knots.iter().filter(|&&u| u == x).count();
    let rows = coefs.nrows();
    let mut out = DMatrix::<f64>::zeros(rows + 1, coefs.ncols());
    for i in 0..=rows {
        if i + n <= k {
            out.set_row(i, &coefs.row(i));
        } else if i + s > k {
            out.set_row(i, &coefs.row(i - 1));
        } else {
            let alpha = (x - knots[i]) / (knots[i + n] - knots[i]);
            let row = coefs.row(i) * alpha + coefs.row(i - 1) * (1.0 - alpha);
            out.set_row(i, &row);
        }
    }
    let mut new_knots = knots.to_vec();
    new_knots.insert(k + 1, x);
    (new_knots, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval_piecewise(space: &Space, c: &[f64], t: f64) -> f64 {
        let (support, vals) = space.basis_at(t);
        support.iter().zip(&vals).map(|(&i, v)| c[i] * v).sum()
    }

    #[test]
    fn space_dimension_and_partition_of_unity() {
        let s = Space::new("u", 5, 4, 2, false).unwrap();
        assert_eq!(s.n_coef, 6 + 3 * 3);
        for k in 0..=40 {
            let t = k as f64 / 40.0;
            let (_, vals) = s.basis_at(t);
            assert!((vals.iter().sum::<f64>() - 1.0).abs() < 1e-13);
        }
    }

    #[test]
    fn space_is_cr_across_knots() {
        // A random spline of C^2 smoothness: derivatives 0..2 agree across each knot, 3 not.
        let s = Space::new("u", 5, 3, 2, false).unwrap();
        let c: Vec<f64> = (0..s.n_coef)
            .map(|i| ((i * 7 + 3) % 5) as f64 - 2.0)
            .collect();
        let n = 5;
        for p in 0..2 {
            let left = &s.pieces[p];
            let right = &s.pieces[p + 1];
            let bez = |piece: &Piece| -> Vec<f64> {
                (0..=n)
                    .map(|i| {
                        piece
                            .support
                            .iter()
                            .enumerate()
                            .map(|(a, &g)| piece.ext[(i, a)] * c[g])
                            .sum()
                    })
                    .collect()
            };
            let (bl, br) = (bez(left), bez(right));
            for d in 0..=2 {
                let dl: f64 = (0..=d)
                    .map(|l| {
                        let sign = if (d - l) % 2 == 0 { 1.0 } else { -1.0 };
                        sign * binomial(d, l) * bl[n - d + l]
                    })
                    .sum();
                let dr: f64 = (0..=d)
                    .map(|l| {
                        let sign = if (d - l) % 2 == 0 { 1.0 } else { -1.0 };
                        sign * binomial(d, l) * br[l]
                    })
                    .sum();
                assert!((dl - dr).abs() < 1e-12, "piece {p} order {d}");
            }
        }
    }

    #[test]
    fn space_reproduces_polynomials() {
        // Greville identity: Σ ξ_i N_i(t) = t for degree ≥ 1.
        let s = Space::new("u", 4, 5, 1, false).unwrap();
        for k in 0..=50 {
            let t = k as f64 / 50.0;
            assert!((eval_piecewise(&s, &s.greville, t) - t).abs() < 1e-13);
        }
    }

    #[test]
    fn periodic_space_closes_smoothly() {
        let s = Space::new("v", 5, 4, 3, true).unwrap();
        assert_eq!(s.n_coef, 6 + 3 * 2 - 4);
        let c: Vec<f64> = (0..s.n_coef).map(|i| (i as f64 * 1.3).sin()).collect();
        let d0 = s.end_derivatives(false, 4);
        let d1 = s.end_derivatives(true, 4);
        for d in 0..4 {
            let a: f64 = (0..s.n_coef).map(|i| d0[(d, i)] * c[i]).sum();
            let b: f64 = (0..s.n_coef).map(|i| d1[(d, i)] * c[i]).sum();
            assert!(
                (a - b).abs() < 1e-9 * (1.0 + a.abs()),
                "order {d}: {a} vs {b}"
            );
        }
    }

    #[test]
    fn periodic_space_rejects_too_few_coefficients() {
        assert!(matches!(
            Space::new("v", 3, 1, 2, true),
            Err(PdeError::DegreeTooLow { .. })
        ));
    }
}
