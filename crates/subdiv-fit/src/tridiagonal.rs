//! The interpolation system of eq. (4) is (cyclic) tridiagonal: a banded O(k) solver.

/// Solves the (cyclic, if `closed`) tridiagonal system
/// `lower[i] x[i−1] + diag[i] x[i] + upper[i] x[i+1] = rhs[i]` for `D` right-hand sides at once,
/// indices modulo `k` when `closed` (`lower[0]` and `upper[k−1]` are the corner entries;
/// ignored when open).
/// Thomas's algorithm, with the Sherman–Morrison correction for the corners.
/// Returns `None` on a zero pivot or a non-finite result.
/// Stable without pivoting for the diagonally dominant matrix of eq. (4).
pub(crate) fn solve_tridiagonal<const D: usize>(
    lower: &[f64],
    diag: &[f64],
    upper: &[f64],
    rhs: &[[f64; D]],
    closed: bool,
) -> Option<Vec<[f64; D]>> {
    let k = diag.len();
    if k == 0 || lower.len() != k || upper.len() != k || rhs.len() != k {
        return None;
    }
    let corner = closed && k > 2 && (lower[0] != 0.0 || upper[k - 1] != 0.0);
    if !corner {
        let (mut lo, mut up) = (lower.to_vec(), upper.to_vec());
        if closed && k <= 2 {
            // Two unknowns: the wrapped neighbours are the same unknown.
            if k == 2 {
                up[0] += lower[0];
                lo[1] += upper[1];
            } else {
                let d = diag[0] + lower[0] + upper[0];
                return (d != 0.0).then(|| vec![rhs[0].map(|r| r / d)]);
            }
        }
        lo[0] = 0.0;
        up[k - 1] = 0.0;
        return thomas(&lo, diag, &up, rhs);
    }
    // Sherman–Morrison: A = T + u vᵀ with u = (γ, 0, …, 0, c), v = (1, 0, …, 0, a/γ).
    let gamma = -diag[0];
    let (a, c) = (lower[0], upper[k - 1]);
    let mut d2 = diag.to_vec();
    d2[0] -= gamma;
    d2[k - 1] -= c * a / gamma;
    let (mut lo, mut up) = (lower.to_vec(), upper.to_vec());
    lo[0] = 0.0;
    up[k - 1] = 0.0;
    let y = thomas(&lo, &d2, &up, rhs)?;
    let mut u = vec![[0.0; 1]; k];
    u[0] = [gamma];
    u[k - 1] = [c];
    let z = thomas(&lo, &d2, &up, &u)?;
    let vz = z[0][0] + a / gamma * z[k - 1][0];
    let denom = 1.0 + vz;
    if denom == 0.0 {
        return None;
    }
    let mut out = y.clone();
    for col in 0..D {
        let vy = y[0][col] + a / gamma * y[k - 1][col];
        let f = vy / denom;
        for i in 0..k {
            out[i][col] = y[i][col] - f * z[i][0];
        }
    }
    out.iter()
        .all(|r| r.iter().all(|v| v.is_finite()))
        .then_some(out)
}

fn thomas<const D: usize>(
    lower: &[f64],
    diag: &[f64],
    upper: &[f64],
    rhs: &[[f64; D]],
) -> Option<Vec<[f64; D]>> {
    let k = diag.len();
    let mut c = vec![0.0; k];
    let mut d = vec![[0.0; D]; k];
    let mut denom = diag[0];
    if denom == 0.0 {
        return None;
    }
    c[0] = upper[0] / denom;
    d[0] = rhs[0].map(|r| r / denom);
    for i in 1..k {
        denom = diag[i] - lower[i] * c[i - 1];
        if denom == 0.0 || !denom.is_finite() {
            return None;
        }
        c[i] = upper[i] / denom;
        for col in 0..D {
            d[i][col] = (rhs[i][col] - lower[i] * d[i - 1][col]) / denom;
        }
    }
    for i in (0..k - 1).rev() {
        let next = d[i + 1];
        for (v, n) in d[i].iter_mut().zip(next) {
            *v -= c[i] * n;
        }
    }
    Some(d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;
    use proptest::prelude::*;

    fn dense(lower: &[f64], diag: &[f64], upper: &[f64], closed: bool) -> DMatrix<f64> {
        let k = diag.len();
        let mut m = DMatrix::zeros(k, k);
        for i in 0..k {
            m[(i, i)] += diag[i];
            if i > 0 {
                m[(i, i - 1)] += lower[i];
            } else if closed {
                m[(0, k - 1)] += lower[0];
            }
            if i + 1 < k {
                m[(i, i + 1)] += upper[i];
            } else if closed {
                m[(k - 1, 0)] += upper[k - 1];
            }
        }
        m
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn matches_dense_lu(
            rows in prop::collection::vec((any::<bool>(), -1.0..1.0f64, -1.0..1.0f64), 1..12),
            closed in any::<bool>(),
        ) {
            // Eq. (4) rows: sharp (identity) or regular (1/6, 4/6, 1/6).
            let k = rows.len();
            let mut lo = vec![0.0; k];
            let mut di = vec![0.0; k];
            let mut up = vec![0.0; k];
            let mut rhs = vec![[0.0; 2]; k];
            for (i, (sharp, x, y)) in rows.iter().enumerate() {
                let end = !closed && (i == 0 || i + 1 == k);
                if *sharp || end {
                    di[i] = 1.0;
                } else {
                    lo[i] = 1.0 / 6.0;
                    di[i] = 4.0 / 6.0;
                    up[i] = 1.0 / 6.0;
                }
                rhs[i] = [*x, *y];
            }
            let x = solve_tridiagonal(&lo, &di, &up, &rhs, closed).unwrap();
            let m = dense(&lo, &di, &up, closed);
            for col in 0..2 {
                let b = nalgebra::DVector::from_iterator(k, rhs.iter().map(|r| r[col]));
                let xd = m.clone().lu().solve(&b).unwrap();
                for i in 0..k {
                    prop_assert!((x[i][col] - xd[i]).abs() < 1e-12, "{} vs {}", x[i][col], xd[i]);
                }
            }
        }
    }

    #[test]
    fn zero_pivot_is_reported() {
        assert!(
            solve_tridiagonal(
                &[0.0, 1.0],
                &[0.0, 1.0],
                &[1.0, 0.0],
                &[[1.0], [1.0]],
                false
            )
            .is_none()
        );
    }
}
