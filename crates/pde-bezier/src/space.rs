//! One-dimensional spline spaces on a uniform grid, with Bézier extraction per piece.
//!
//! The C^r piecewise polynomials of degree n on P uniform pieces of [0, 1] are the B-splines
//! on the clamped knot vector with interior knots of multiplicity n − r. Their coefficients
//! are the unknowns of the improved algorithm; Bézier extraction (Boehm knot insertion up to
//! multiplicity n) gives each piece's Bernstein coefficients as a linear map of them, so no
//! continuity constraint is ever carried. A periodic space keeps C^r across the seam t = 0 ≡ 1
//! by expressing the first r + 1 coefficients through the last r + 1.

use crate::bernstein_ops::bernstein_values;
use crate::dense::Dense;
use crate::error::PdeError;
use bez_core::binomial;

/// The Bézier extraction of one piece: its (n+1) Bernstein coefficients as a linear map
/// of the spline coefficients in `support`.
#[derive(Debug, Clone)]
pub(crate) struct Piece {
    /// Indices of the spline coefficients that act on this piece.
    pub(crate) support: Vec<usize>,
    /// (n+1) × support.len() extraction matrix.
    pub(crate) ext: Dense,
}

/// A uniform spline space on [0, 1].
#[derive(Debug, Clone)]
pub(crate) struct Space {
    pub(crate) degree: usize,
    pub(crate) pieces: Vec<Piece>,
    pub(crate) n_coef: usize,
    /// The clamped knot vector (interior multiplicity n − r).
    pub(crate) knots: Vec<f64>,
    /// Clamped B-spline coefficients as a sparse map of the unknowns: entry k lists
    /// (unknown, weight) pairs (None: the identity; periodic spaces express their first
    /// r + 1 coefficients through the last r + 1).
    pub(crate) to_clamped: Option<Vec<Vec<(usize, f64)>>>,
    /// One collocation abscissa per coefficient (Greville abscissae; those of the periodic
    /// knot sequence when periodic).
    pub(crate) greville: Vec<f64>,
}

impl Space {
    /// Builds the space of C^r piecewise polynomials of degree n on `pieces` uniform pieces.
    ///
    /// The extraction of each piece comes from Boehm insertion on that piece's own 2n + 2
    /// knots, so building the space costs O(P n³), linear in the number of pieces.
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
        let out = (0..pieces)
            .map(|p| {
                // Span k = [knots[k], knots[k+1]) carries B-splines k − n ..= k.
                let k = n + p * mult;
                Piece {
                    support: (k - n..=k).collect(),
                    ext: local_extraction(&knots[k - n..=k + n + 1], n),
                }
            })
            .collect();
        let mut space = Self {
            knots,
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

    /// Derivatives of orders 0..count at the start (`End::Start`) or the end of [0, 1]:
    /// a count × n_coef matrix D with D[d][l] = N_l^(d)(end).
    pub(crate) fn end_derivatives(&self, end: End, count: usize) -> Dense {
        let n = self.degree;
        let piece = match end {
            End::Finish => &self.pieces[self.pieces.len() - 1],
            End::Start => &self.pieces[0],
        };
        let h = self.width();
        let mut d = Dense::zeros(count, self.n_coef);
        for order in 0..count.min(n + 1) {
            // d-th derivative of a Bézier piece at an end, in the global parameter:
            // n!/(n−d)! h^{−d} Σ_l (−1)^{d−l} C(d,l) b_{start+l}.
            let falling: f64 = (0..order).map(|i| (n - i) as f64).product();
            let scale = falling / h.powi(order as i32);
            let start = if end == End::Finish { n - order } else { 0 };
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
        let d0 = self.end_derivatives(End::Start, r1);
        let d1 = self.end_derivatives(End::Finish, r1);
        let d0 = Dense::from_fn(r1, r1, |i, j| d0[(i, j)]);
        let d1 = Dense::from_fn(r1, r1, |i, j| d1[(i, n - r1 + j)]);
        let t = d0.solve(&d1).ok_or(PdeError::Undetermined {
            method: "periodic closure",
            unknowns: r1,
            condition: f64::INFINITY,
        })?;
        // c = Z w with w = (c_{r+1}, …, c_{n−1}).
        let nw = n - r1;
        let z: Vec<Vec<(usize, f64)>> = (0..n)
            .map(|k| {
                if k < r1 {
                    (0..r1).map(|j| (nw - r1 + j, t[(k, j)])).collect()
                } else {
                    vec![(k - r1, 1.0)]
                }
            })
            .collect();
        let pieces = self
            .pieces
            .iter()
            .map(|piece| {
                let mut support: Vec<usize> = piece
                    .support
                    .iter()
                    .flat_map(|&g| z[g].iter().map(|&(w, _)| w))
                    .collect();
                support.sort_unstable();
                support.dedup();
                let mut ext = Dense::zeros(piece.ext.nrows(), support.len());
                for (a, &g) in piece.support.iter().enumerate() {
                    for &(w, weight) in &z[g] {
                        let col = support.partition_point(|&s| s < w);
                        for i in 0..piece.ext.nrows() {
                            ext[(i, col)] += piece.ext[(i, a)] * weight;
                        }
                    }
                }
                Piece { support, ext }
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

/// Which end of [0, 1].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum End {
    /// t = 0.
    Start,
    /// t = 1.
    Finish,
}

/// Bézier extraction of the span [t_n, t_{n+1}] of a local knot vector t_0..t_{2n+1}: the
/// Bernstein coefficients of the n + 1 B-splines acting there, as an (n+1) × (n+1) matrix.
///
/// Boehm insertion raises both span ends to multiplicity n on the identity; the rows of the
/// B-splines acting on the span are then the Bernstein coefficients.
fn local_extraction(local: &[f64], n: usize) -> Dense {
    let (a, b) = (local[n], local[n + 1]);
    let mut knots = local.to_vec();
    let mut coefs = Dense::identity(n + 1);
    for x in [a, b] {
        while knots.iter().filter(|&&u| u == x).count() < n {
            (knots, coefs) = insert_knot(&knots, &coefs, n, x);
        }
    }
    // The span [a, b] is now [knots[k], knots[k+1]] with k the last index of a.
    let k = knots.iter().rposition(|&u| u == a).unwrap_or(n);
    coefs.rows_range(k - n, n + 1)
}

/// Boehm's knot insertion of x, applied to the rows of a coefficient matrix (row i holds
/// the coefficients of B-spline i of `knots`).
fn insert_knot(knots: &[f64], coefs: &Dense, n: usize, x: f64) -> (Vec<f64>, Dense) {
    // k: last index with knots[k] ≤ x; s: multiplicity of x already present.
    let k = knots.iter().rposition(|&u| u <= x).unwrap_or(0);
    let s = knots.iter().filter(|&&u| u == x).count();
    let rows = coefs.nrows();
    let mut out = Dense::zeros(rows + 1, coefs.ncols());
    for i in 0..=rows {
        for c in 0..coefs.ncols() {
            out[(i, c)] = if i + n <= k {
                coefs[(i, c)]
            } else if i + s > k {
                coefs[(i - 1, c)]
            } else {
                let alpha = (x - knots[i]) / (knots[i + n] - knots[i]);
                alpha * coefs[(i, c)] + (1.0 - alpha) * coefs[(i - 1, c)]
            };
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
        let d0 = s.end_derivatives(End::Start, 4);
        let d1 = s.end_derivatives(End::Finish, 4);
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
