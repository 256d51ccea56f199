//! Discrete curvature and the initial fitting points (Sec. 4.2).

use bez_core::Vector;

/// A data point chosen as an initial fitting point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct FeaturePoint {
    /// Index into the data.
    pub index: usize,
    /// Discrete curvature there (infinite at the ends of open data).
    pub curvature: f64,
    /// Whether the point is classified sharp.
    pub sharp: bool,
}

/// Angle between the unit vectors `a/|a|` and `b/|b|`, accurate for small and large angles
/// (`2 atan2(|â − b̂|, |â + b̂|)`); 0 when either is zero, NaN when either is not finite. Each is
/// scaled by its largest coordinate before its length is taken, whose square would underflow
/// below about 10⁻¹⁵⁴ (and then made a tiny direction look like none) or overflow above 10¹⁵⁴.
pub(crate) fn angle_between<const D: usize>(a: &Vector<D>, b: &Vector<D>) -> f64 {
    let unit = |v: &Vector<D>| {
        let scaled = *v / v.amax();
        scaled / scaled.norm()
    };
    let (ma, mb) = (a.amax(), b.amax());
    if !(ma.is_finite() && mb.is_finite()) {
        return f64::NAN;
    }
    if ma == 0.0 || mb == 0.0 {
        return 0.0;
    }
    let (ua, ub) = (unit(a), unit(b));
    2.0 * (ua - ub).norm().atan2((ua + ub).norm())
}

fn neighbours(n: usize, i: usize, closed: bool) -> Option<(usize, usize)> {
    if closed {
        Some(((i + n - 1) % n, (i + 1) % n))
    } else if i == 0 || i + 1 == n {
        None
    } else {
        Some((i - 1, i + 1))
    }
}

/// The turning angle `φ_i ∈ [0, π]` between `v_{i−1}v_i` and `v_i v_{i+1}` at every data point
/// (`π` at the ends of open data). The angle between the two edges *at* the point, which the
/// paper thresholds (Sec. 4.1), is `π − φ_i`.
#[must_use]
pub fn turning_angle<const D: usize>(data: &[Vector<D>], closed: bool) -> Vec<f64> {
    let n = data.len();
    (0..n)
        .map(|i| match neighbours(n, i, closed) {
            Some((a, b)) => angle_between(&(data[i] - data[a]), &(data[b] - data[i])),
            None => std::f64::consts::PI,
        })
        .collect()
}

/// Discrete curvature (Sec. 4.2): `K(v_i) = 2 sin φ_i / d_i`, the inverse radius of the circle
/// through `v_{i−1}, v_i, v_{i+1}`, with `φ_i` the turning angle and `d_i = |v_{i+1} − v_{i−1}|`.
/// Infinite at the ends of open data ("a large curvature value", Sec. 4.2).
#[must_use]
pub fn discrete_curvature<const D: usize>(data: &[Vector<D>], closed: bool) -> Vec<f64> {
    let n = data.len();
    let phi = turning_angle(data, closed);
    (0..n)
        .map(|i| match neighbours(n, i, closed) {
            Some((a, b)) => {
                let d = (data[b] - data[a]).norm();
                if d == 0.0 {
                    f64::INFINITY
                } else {
                    2.0 * phi[i].sin() / d
                }
            }
            None => f64::INFINITY,
        })
        .collect()
}

/// Initial fitting points (Sec. 4.2): local curvature maxima plus every sharp point.
///
/// * A point is sharp when the angle between its two edges, `π − φ_i`, is below `sharp_angle`
///   (radians); the ends of open data are sharp.
/// * A local maximum must satisfy `K_i > (1 + prominence) K_{i−1}` and `K_i ≥ K_{i+1}` (the
///   prominence factor keeps rounding noise on arcs of constant curvature from creating maxima, and
///   the asymmetric test picks one point of an exact plateau), and `K_i · L > curvature_floor`, with
///   `L` the diagonal of the data's bounding box (so straight runs, whose discrete curvature is
///   rounding noise, yield none).
#[must_use]
pub fn feature_points<const D: usize>(
    data: &[Vector<D>],
    closed: bool,
    sharp_angle: f64,
    curvature_floor: f64,
    prominence: f64,
) -> Vec<FeaturePoint> {
    let n = data.len();
    if n == 0 {
        return Vec::new();
    }
    let k = discrete_curvature(data, closed);
    let phi = turning_angle(data, closed);
    let diag = diagonal(data);
    let mut out = Vec::new();
    for i in 0..n {
        let sharp = std::f64::consts::PI - phi[i] < sharp_angle;
        let is_max = match neighbours(n, i, closed) {
            Some((a, b)) => {
                k[i] > (1.0 + prominence) * k[a] && k[i] >= k[b] && k[i] * diag > curvature_floor
            }
            None => true,
        };
        if sharp || is_max {
            out.push(FeaturePoint {
                index: i,
                curvature: k[i],
                sharp: sharp || neighbours(n, i, closed).is_none(),
            });
        }
    }
    out
}

/// Diagonal of the axis-aligned bounding box.
pub(crate) fn diagonal<const D: usize>(data: &[Vector<D>]) -> f64 {
    let Some(first) = data.first() else {
        return 0.0;
    };
    let (mut lo, mut hi) = (*first, *first);
    for p in data {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    (hi - lo).norm()
}

#[cfg(test)]
mod tests {
    use bez_core::Vector2;

    use super::angle_between;

    /// The angle between two directions whatever their lengths: tiny vectors, whose squared
    /// lengths underflow, and huge ones, whose squared lengths overflow, against the angle of the
    /// same directions at unit scale.
    #[test]
    fn angles_of_tiny_and_huge_directions() {
        let (a, b) = (Vector2::new(1.0, 0.0), Vector2::new(-0.6, 0.8));
        let exact = 0.8f64.atan2(-0.6);
        assert!((angle_between(&a, &b) - exact).abs() < 1e-15);
        for (sa, sb) in [
            (1e-200, 1.0),
            (1e-300, 1e-305),
            (1e200, 1e-200),
            (1e300, 1e300),
        ] {
            let angle = angle_between(&(a * sa), &(b * sb));
            assert!((angle - exact).abs() < 1e-15, "{sa:e}, {sb:e}: {angle}");
        }
        // Subnormal coordinates carry fewer bits.
        let angle = angle_between(&a, &(b * 1e-310));
        assert!((angle - exact).abs() < 1e-12, "{angle}");
        assert_eq!(angle_between(&Vector2::new(0.0, 0.0), &b), 0.0);
        assert!(angle_between(&Vector2::new(f64::INFINITY, 0.0), &b).is_nan());
        assert!(angle_between(&a, &Vector2::new(f64::NAN, 1.0)).is_nan());
    }
}
