//! Curvature and torsion with their arc-length derivatives, and the logarithmic curvature and
//! torsion graphs (LCG, LTG; eqs. (20)–(24)).

use crate::square::Matrix3;
use bez_core::BezierCurve;

use crate::ClassAError;

/// Curvature κ and dκ/ds at t, for any dimension.
///
/// With P = |x'|², G = P|x''|² − (x'·x'')² = |x' × x''|²: κ = √G / P^{3/2} and
/// dκ/dt = G'/(2√G P^{3/2}) − (3/2)√G P'/P^{5/2}, G' = 2P(x''·x''') − 2(x'·x'')(x'·x'''),
/// P' = 2x'·x''; dκ/ds = (dκ/dt)/√P.
///
/// # Errors
/// [`ClassAError::Core`] for t ∉ [0, 1] or a zero tangent.
pub fn curvature_with_derivative<const D: usize>(
    curve: &BezierCurve<D>,
    t: f64,
) -> Result<(f64, f64), ClassAError> {
    let d = curve.eval_derivatives(t, 3)?;
    let (d1, d2, d3) = (d[1], d[2], d[3]);
    let p = d1.norm_squared();
    if p == 0.0 {
        return Err(bez_core::CoreError::ZeroTangent { t }.into());
    }
    let g = (p * d2.norm_squared() - d1.dot(&d2).powi(2)).max(0.0);
    let gp = 2.0 * p * d2.dot(&d3) - 2.0 * d1.dot(&d2) * d1.dot(&d3);
    let pp = 2.0 * d1.dot(&d2);
    let sg = g.sqrt();
    let k = sg / p.powf(1.5);
    let kt = if sg > 0.0 {
        gp / (2.0 * sg * p.powf(1.5))
    } else {
        0.0
    } - 1.5 * sg * pp / p.powf(2.5);
    Ok((k, kt / p.sqrt()))
}

/// Torsion τ and dτ/ds at t: τ = Δ/G, Δ = det(x', x'', x'''), dτ/dt = det(x', x'', x'''')/G − ΔG'/G².
///
/// # Errors
/// [`ClassAError::Core`] for t ∉ [0, 1], a zero tangent, or zero curvature (G = 0).
pub fn torsion_with_derivative(curve: &BezierCurve<3>, t: f64) -> Result<(f64, f64), ClassAError> {
    let d = curve.eval_derivatives(t, 4)?;
    let (d1, d2, d3, d4) = (d[1], d[2], d[3], d[4]);
    let p = d1.norm_squared();
    if p == 0.0 {
        return Err(bez_core::CoreError::ZeroTangent { t }.into());
    }
    let c = d1.cross(&d2);
    let g = c.norm_squared();
    if g == 0.0 {
        return Err(bez_core::CoreError::ZeroCurvature { t }.into());
    }
    let det = Matrix3::from_columns(&[d1, d2, d3]).determinant();
    let det4 = Matrix3::from_columns(&[d1, d2, d4]).determinant();
    let gp = 2.0 * c.dot(&d1.cross(&d3));
    let tau = det / g;
    let tt = det4 / g - det * gp / (g * g);
    Ok((tau, tt / p.sqrt()))
}

/// A logarithmic curvature (or torsion) graph with its least-squares line y = αx + c (eq. (20)).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct LogGraph {
    /// Points (x, y) = (log ρ, log(ρ |ds/dρ|)), ρ = 1/|κ| (or μ = 1/|τ|).
    pub points: Vec<(f64, f64)>,
    /// Fitted slope α.
    pub slope: f64,
    /// Fitted intercept c.
    pub intercept: f64,
    /// Straightness: largest |residual| of the fit divided by the y-range of the points
    /// (0 for a straight graph; the y-range is replaced by 1 when it is 0).
    pub straightness: f64,
}

/// The graph from samples (κ, dκ/ds) (or (τ, dτ/ds)): x = log ρ = −log|κ| and, since
/// dρ/ds = −κ_s/κ² (eq. (22)), y = log(ρ|ds/dρ|) = log(|κ| / |κ_s|).
/// Samples with κ = 0, κ_s = 0 or non-finite values are skipped.
///
/// # Errors
/// [`ClassAError::TooFewSamples`] with fewer than 2 usable samples.
pub fn log_graph(samples: &[(f64, f64)]) -> Result<LogGraph, ClassAError> {
    let points: Vec<(f64, f64)> = samples
        .iter()
        .filter(|(k, ks)| k.is_finite() && ks.is_finite() && *k != 0.0 && *ks != 0.0)
        .map(|(k, ks)| (-k.abs().ln(), (k.abs() / ks.abs()).ln()))
        .collect();
    log_graph_from_points(points)
}

/// As [`log_graph`] from ready (x, y) points (e.g. [`crate::TypicalPlanar::log_curvature_point`]).
///
/// # Errors
/// [`ClassAError::TooFewSamples`] with fewer than 2 finite points or all x equal;
/// [`ClassAError::InvalidParameter`] when the fitted line is not representable.
pub fn log_graph_from_points(points: Vec<(f64, f64)>) -> Result<LogGraph, ClassAError> {
    let points: Vec<(f64, f64)> = points
        .into_iter()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let n = points.len() as f64;
    if points.len() < 2 {
        return Err(ClassAError::TooFewSamples {
            count: points.len(),
        });
    }
    // Means of x/n (no overflow for any finite input), then the fit on deviations scaled to
    // at most 1, so that no square overflows: α = (Σ x̂ŷ / Σ x̂²) · (s_y / s_x).
    let mx = points.iter().map(|p| p.0 / n).sum::<f64>();
    let my = points.iter().map(|p| p.1 / n).sum::<f64>();
    let spread = |f: &dyn Fn(&(f64, f64)) -> f64| points.iter().map(f).fold(0.0_f64, f64::max);
    let (sx, sy) = (
        spread(&|p| (p.0 - mx).abs()),
        spread(&|p| (p.1 - my).abs()).max(f64::MIN_POSITIVE),
    );
    if sx == 0.0 || !sx.is_finite() || !sy.is_finite() {
        return Err(ClassAError::TooFewSamples { count: 1 });
    }
    let sxx: f64 = points.iter().map(|p| ((p.0 - mx) / sx).powi(2)).sum();
    let sxy: f64 = points
        .iter()
        .map(|p| (p.0 - mx) / sx * ((p.1 - my) / sy))
        .sum();
    let slope = sxy / sxx * (sy / sx);
    let intercept = my - slope * mx;
    if !(slope.is_finite() && intercept.is_finite()) {
        return Err(ClassAError::InvalidParameter {
            name: "log graph slope",
            value: slope,
            expected: "a finite line through the points",
        });
    }
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
    let range = if hi > lo { hi - lo } else { 1.0 };
    let worst = points
        .iter()
        .map(|p| (p.1 - slope * p.0 - intercept).abs())
        .fold(0.0, f64::max);
    Ok(LogGraph {
        points,
        slope,
        intercept,
        straightness: worst / range,
    })
}

/// Curvature samples (κ, dκ/ds) at `count` uniform parameters (at least 2; parameters where
/// the curvature is undefined are skipped).
///
/// # Errors
/// `CoreError::TooLarge` when `count` exceeds [`bez_core::MAX_SAMPLES`] (checked first).
pub fn curvature_samples<const D: usize>(
    curve: &BezierCurve<D>,
    count: usize,
) -> Result<Vec<(f64, f64)>, ClassAError> {
    let count = checked_count(count)?;
    Ok((0..count)
        .filter_map(|i| curvature_with_derivative(curve, i as f64 / (count - 1) as f64).ok())
        .collect())
}

/// Torsion samples (τ, dτ/ds) at `count` uniform parameters, as [`curvature_samples`].
///
/// # Errors
/// As [`curvature_samples`].
pub fn torsion_samples(
    curve: &BezierCurve<3>,
    count: usize,
) -> Result<Vec<(f64, f64)>, ClassAError> {
    let count = checked_count(count)?;
    Ok((0..count)
        .filter_map(|i| torsion_with_derivative(curve, i as f64 / (count - 1) as f64).ok())
        .collect())
}

/// `count` raised to 2, or `TooLarge` above [`bez_core::MAX_SAMPLES`].
fn checked_count(count: usize) -> Result<usize, ClassAError> {
    if count > bez_core::MAX_SAMPLES {
        return Err(bez_core::CoreError::TooLarge {
            requested: count,
            max: bez_core::MAX_SAMPLES,
        }
        .into());
    }
    Ok(count.max(2))
}
