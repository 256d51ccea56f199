//! Certificates of monotone curvature and torsion from the curve itself (Bernstein form).

use bez_core::{
    BezierCurve, SVector, bernstein_derivative_coeffs, bernstein_product, eval_bernstein_poly,
    roots_in_unit_interval,
};

use crate::ClassAError;

/// Largest degree of the curvature certificate (numerator degree 6n − 9 ≤ 120, exact binomials).
pub const MAX_CURVATURE_DEGREE: usize = 21;
/// Largest degree of the torsion certificate (numerator degree 7n − 13 ≤ 120).
pub const MAX_TORSION_DEGREE: usize = 19;
/// Coefficients within this fraction of the largest |coefficient| count as zero (rounding).
pub const ROUNDING_ALLOWANCE: f64 = 1e-12;

/// The verdict of a monotonicity certificate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Monotonicity {
    /// Non-decreasing on [0, 1].
    Increasing,
    /// Non-increasing on [0, 1].
    Decreasing,
    /// Constant (numerator identically zero up to rounding).
    Constant,
    /// The derivative changes sign at the given interior parameter: an interior extremum.
    NotMonotone {
        /// Parameter of the extremum.
        extremum: f64,
    },
}

/// A monotonicity certificate: the Bernstein coefficients of the numerator N(t) of the
/// derivative (the denominator is positive), and the verdict.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Certificate {
    /// The verdict.
    pub verdict: Monotonicity,
    /// Bernstein coefficients of N(t).
    pub numerator: Vec<f64>,
    /// The verdict follows from the signs of the coefficients alone (convex-hull property),
    /// rather than from root isolation.
    pub by_coefficient_signs: bool,
}

impl Certificate {
    /// The quantity is monotone (increasing, decreasing or constant).
    #[must_use]
    pub fn is_monotone(&self) -> bool {
        !matches!(self.verdict, Monotonicity::NotMonotone { .. })
    }
}

fn components<const D: usize>(points: &[SVector<f64, D>], k: usize) -> Vec<f64> {
    points.iter().map(|p| p[k]).collect()
}

fn add(a: &[f64], b: &[f64], sb: f64) -> Vec<f64> {
    a.iter().zip(b).map(|(x, y)| x + sb * y).collect()
}

/// Σ_k a_k b_k of vector-valued Bernstein polynomials given by components.
fn dot(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<f64> {
    let mut acc: Vec<f64> = Vec::new();
    for (x, y) in a.iter().zip(b) {
        let p = bernstein_product(x, y);
        acc = if acc.is_empty() {
            p
        } else {
            add(&acc, &p, 1.0)
        };
    }
    acc
}

/// Hodographs of order 1..=k of a normalized copy (translation and scale do not change signs).
fn derivative_components<const D: usize>(curve: &BezierCurve<D>, k: usize) -> Vec<Vec<Vec<f64>>> {
    let pts = curve.points();
    let scale = pts
        .windows(2)
        .map(|w| (w[1] - w[0]).amax())
        .fold(0.0_f64, f64::max);
    let scale = if scale > 0.0 { scale } else { 1.0 };
    let mut cur: Vec<Vec<f64>> = (0..D)
        .map(|d| components(pts, d).iter().map(|x| x / scale).collect())
        .collect();
    let mut out = Vec::with_capacity(k);
    for _ in 0..k {
        cur = cur.iter().map(|c| bernstein_derivative_coeffs(c)).collect();
        out.push(cur.clone());
    }
    out
}

fn decide(numerator: Vec<f64>) -> Certificate {
    let scale = numerator.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    let tol = ROUNDING_ALLOWANCE * scale;
    if scale == 0.0 || numerator.iter().all(|c| c.abs() <= tol) {
        return Certificate {
            verdict: Monotonicity::Constant,
            numerator,
            by_coefficient_signs: true,
        };
    }
    if numerator.iter().all(|&c| c >= -tol) {
        return Certificate {
            verdict: Monotonicity::Increasing,
            numerator,
            by_coefficient_signs: true,
        };
    }
    if numerator.iter().all(|&c| c <= tol) {
        return Certificate {
            verdict: Monotonicity::Decreasing,
            numerator,
            by_coefficient_signs: true,
        };
    }
    // Mixed signs: isolate the roots and look for a sign change of N.
    let roots = roots_in_unit_interval(&numerator);
    let mut cuts = vec![0.0];
    cuts.extend(roots.iter().copied().filter(|r| *r > 0.0 && *r < 1.0));
    cuts.push(1.0);
    let mut signs = Vec::with_capacity(cuts.len());
    for w in cuts.windows(2) {
        let v = eval_bernstein_poly(&numerator, 0.5 * (w[0] + w[1]));
        signs.push(if v > tol {
            1
        } else if v < -tol {
            -1
        } else {
            0
        });
    }
    let mut last = 0;
    for (i, &sg) in signs.iter().enumerate() {
        if sg != 0 {
            if last != 0 && sg != last {
                return Certificate {
                    verdict: Monotonicity::NotMonotone { extremum: cuts[i] },
                    numerator,
                    by_coefficient_signs: false,
                };
            }
            last = sg;
        }
    }
    let verdict = match last {
        1 => Monotonicity::Increasing,
        -1 => Monotonicity::Decreasing,
        _ => Monotonicity::Constant,
    };
    Certificate {
        verdict,
        numerator,
        by_coefficient_signs: false,
    }
}

/// Certificate of monotone curvature of a planar or spatial curve (any D).
///
/// κ² = G / P³ with P = |x'|² and G = |x'|²|x''|² − (x'·x'')² = |x' × x''|² (Lagrange), so
/// d(κ²)/dt = N / P⁴ with N = G'P − 3GP', a polynomial of degree ≤ 6n − 9 computed exactly in
/// Bernstein form (products of hodograph coefficients). All coefficients of one sign prove
/// monotonicity (convex hull); otherwise the roots of N are isolated and a sign change reports
/// an interior extremum. Coefficients within [`ROUNDING_ALLOWANCE`] of the largest count as zero.
/// Points where x' = 0 (P = 0) are not excluded: the certificate assumes a regular curve.
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 2, [`ClassAError::DegreeTooHigh`] for n > [`MAX_CURVATURE_DEGREE`].
pub fn curvature_certificate<const D: usize>(
    curve: &BezierCurve<D>,
) -> Result<Certificate, ClassAError> {
    let n = curve.degree();
    if n < 2 {
        return Err(ClassAError::DegreeTooLow {
            degree: n,
            needed: 2,
        });
    }
    if n > MAX_CURVATURE_DEGREE {
        return Err(ClassAError::DegreeTooHigh {
            degree: n,
            max: MAX_CURVATURE_DEGREE,
        });
    }
    let d = derivative_components(curve, 2);
    let (d1, d2) = (&d[0], &d[1]);
    let p = dot(d1, d1);
    let g = add(
        &bernstein_product(&p, &dot(d2, d2)),
        &{
            let q = dot(d1, d2);
            bernstein_product(&q, &q)
        },
        -1.0,
    );
    let n_poly = add(
        &bernstein_product(&bernstein_derivative_coeffs(&g), &p),
        &bernstein_product(&g, &bernstein_derivative_coeffs(&p)),
        -3.0,
    );
    Ok(decide(n_poly))
}

fn det3(a: &[Vec<f64>], b: &[Vec<f64>], c: &[Vec<f64>]) -> Vec<f64> {
    let cross = |i: usize, j: usize| {
        add(
            &bernstein_product(&b[i], &c[j]),
            &bernstein_product(&b[j], &c[i]),
            -1.0,
        )
    };
    let t0 = bernstein_product(&a[0], &cross(1, 2));
    let t1 = bernstein_product(&a[1], &cross(2, 0));
    let t2 = bernstein_product(&a[2], &cross(0, 1));
    add(&add(&t0, &t1, 1.0), &t2, 1.0)
}

/// Certificate of monotone torsion of a spatial curve.
///
/// τ = Δ / G with Δ = det(x', x'', x''') and G = |x' × x''|², so dτ/dt = (Δ'G − ΔG') / G²:
/// the numerator (degree ≤ 7n − 13) is decided as in [`curvature_certificate`].
/// Where G = 0 (inflections) torsion is undefined; the certificate assumes G > 0.
///
/// # Errors
/// [`ClassAError::DegreeTooLow`] for n < 3, [`ClassAError::DegreeTooHigh`] for n > [`MAX_TORSION_DEGREE`].
pub fn torsion_certificate(curve: &BezierCurve<3>) -> Result<Certificate, ClassAError> {
    let n = curve.degree();
    if n < 3 {
        return Err(ClassAError::DegreeTooLow {
            degree: n,
            needed: 3,
        });
    }
    if n > MAX_TORSION_DEGREE {
        return Err(ClassAError::DegreeTooHigh {
            degree: n,
            max: MAX_TORSION_DEGREE,
        });
    }
    let d = derivative_components(curve, 3);
    let (d1, d2, d3) = (&d[0], &d[1], &d[2]);
    let cr: Vec<Vec<f64>> = (0..3)
        .map(|k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            add(
                &bernstein_product(&d1[i], &d2[j]),
                &bernstein_product(&d1[j], &d2[i]),
                -1.0,
            )
        })
        .collect();
    let g = dot(&cr, &cr);
    let delta = det3(d1, d2, d3);
    let n_poly = add(
        &bernstein_product(&bernstein_derivative_coeffs(&delta), &g),
        &bernstein_product(&delta, &bernstein_derivative_coeffs(&g)),
        -1.0,
    );
    Ok(decide(n_poly))
}
