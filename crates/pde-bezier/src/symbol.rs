//! Ellipticity from the principal symbol of the operator.

use crate::error::PdeError;
use crate::problem::Operator;

impl Operator {
    /// The principal symbol σ(ξ, η) = Σ_{du+dv = k} c ξ^du η^dv (the terms of top order k).
    #[must_use]
    pub fn principal_symbol(&self, xi: f64, eta: f64) -> f64 {
        let k = self.order();
        self.terms()
            .iter()
            .filter(|t| t.du + t.dv == k)
            .map(|t| t.coeff * xi.powi(t.du as i32) * eta.powi(t.dv as i32))
            .sum()
    }

    /// Checks that the operator is elliptic: σ(cos θ, sin θ) ≠ 0 for every θ, that is,
    /// σ keeps one sign on the unit circle and its smallest magnitude there is above
    /// 10⁻⁹ of its largest. Every local minimum of |σ| on a 720-point sampling of [0, π)
    /// is refined by golden-section search, so double roots (no sign change) are found.
    ///
    /// # Errors
    /// [`PdeError::NotElliptic`] with a direction where σ vanishes (or nearly).
    pub fn check_elliptic(&self) -> Result<(), PdeError> {
        let scale = self
            .terms()
            .iter()
            .map(|t| t.coeff.abs())
            .fold(0.0, f64::max);
        let k = self.order();
        // σ/scale, summed term by term so that huge coefficients cannot overflow.
        let sigma = |theta: f64| -> f64 {
            if scale > 0.0 {
                let (xi, eta) = (theta.cos(), theta.sin());
                self.terms()
                    .iter()
                    .filter(|t| t.du + t.dv == k)
                    .map(|t| t.coeff / scale * xi.powi(t.du as i32) * eta.powi(t.dv as i32))
                    .sum()
            } else {
                0.0
            }
        };
        const STEPS: usize = 720;
        let h = std::f64::consts::PI / STEPS as f64;
        let values: Vec<f64> = (0..=STEPS).map(|i| sigma(i as f64 * h)).collect();
        let fail = |theta: f64| PdeError::NotElliptic {
            order: k,
            xi: theta.cos(),
            eta: theta.sin(),
        };
        let mut worst = (f64::INFINITY, 0.0);
        for i in 0..=STEPS {
            let v = values[i];
            if i > 0 && values[i - 1].signum() != v.signum() {
                // Bisection on the sign change.
                let (mut a, mut b) = ((i as f64 - 1.0) * h, i as f64 * h);
                let sa = values[i - 1].signum();
                for _ in 0..80 {
                    let c = 0.5 * (a + b);
                    if sigma(c).signum() == sa {
                        a = c;
                    } else {
                        b = c;
                    }
                }
                return Err(fail(0.5 * (a + b)));
            }
            let left = if i == 0 {
                f64::INFINITY
            } else {
                values[i - 1].abs()
            };
            let right = values.get(i + 1).map_or(f64::INFINITY, |x| x.abs());
            if v.abs() <= left && v.abs() <= right {
                // Golden-section search for the minimum of |σ| on [θ − h, θ + h].
                let (mut a, mut b) = ((i as f64 - 1.0) * h, (i as f64 + 1.0) * h);
                let g = 0.5 * (5f64.sqrt() - 1.0);
                for _ in 0..80 {
                    let c = b - g * (b - a);
                    let d = a + g * (b - a);
                    if sigma(c).abs() < sigma(d).abs() {
                        b = d;
                    } else {
                        a = c;
                    }
                }
                let theta = 0.5 * (a + b);
                let m = sigma(theta).abs();
                if m < worst.0 {
                    worst = (m, theta);
                }
            }
        }
        let largest = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // Written so that a NaN minimum fails too.
        if worst.0.partial_cmp(&(1e-9 * largest)) != Some(std::cmp::Ordering::Greater) {
            return Err(fail(worst.1));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::error::PdeError;
    use crate::problem::{Operator, Term};

    fn op(terms: &[(f64, usize, usize)]) -> Operator {
        Operator::new(
            terms
                .iter()
                .map(|&(coeff, du, dv)| Term { coeff, du, dv })
                .collect(),
        )
        .unwrap()
    }

    #[test]
    fn elliptic_operators_pass() {
        assert!(
            Operator::second_order(1.0, 1.0)
                .unwrap()
                .check_elliptic()
                .is_ok()
        );
        assert!(
            Operator::second_order(-5.0, -1e-3)
                .unwrap()
                .check_elliptic()
                .is_ok()
        );
        assert!(
            Operator::bloor_wilson(0.3)
                .unwrap()
                .check_elliptic()
                .is_ok()
        );
        // ξ² + ξη + η² > 0; lower-order terms do not count.
        assert!(
            op(&[(1.0, 2, 0), (1.0, 1, 1), (1.0, 0, 2)])
                .check_elliptic()
                .is_ok()
        );
        assert!(
            op(&[(1.0, 6, 0), (1.0, 0, 6), (-100.0, 2, 0)])
                .check_elliptic()
                .is_ok()
        );
    }

    #[test]
    fn non_elliptic_operators_fail_at_a_root_of_the_symbol() {
        for (o, roots) in [
            // Wave operator: ξ² − η², roots at θ = π/4, 3π/4.
            (Operator::second_order(1.0, -1.0).unwrap(), vec![0.25, 0.75]),
            // ∂u∂v: ξη, roots at 0 and π/2.
            (op(&[(1.0, 1, 1)]), vec![0.0, 0.5, 1.0]),
            // (ξ² − 2η²)²: double roots, no sign change.
            (op(&[(1.0, 4, 0), (-4.0, 2, 2), (4.0, 0, 4)]), vec![]),
            // ∂⁴/∂u⁴ alone: ξ⁴ vanishes at ξ = 0.
            (op(&[(1.0, 4, 0)]), vec![0.5]),
        ] {
            match o.check_elliptic() {
                Err(PdeError::NotElliptic { xi, eta, .. }) => {
                    assert!(
                        o.principal_symbol(xi, eta).abs() < 1e-6,
                        "{o:?}: ({xi}, {eta})"
                    );
                    if !roots.is_empty() {
                        let theta =
                            eta.atan2(xi).rem_euclid(std::f64::consts::PI) / std::f64::consts::PI;
                        assert!(
                            roots.iter().any(|r| (theta - r).abs() < 1e-2),
                            "{o:?}: {theta}"
                        );
                    }
                }
                other => panic!("{o:?}: {other:?}"),
            }
        }
    }
}
