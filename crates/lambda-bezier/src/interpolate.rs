//! Shape-preserving G1 interpolation of functional data with cubic λ-curves (section 4.1).
//!
//! The paper shows the result (Fig. 5) but not the construction; this one is ours.
//! 1. Slopes: chord slopes sᵢ = Δyᵢ/Δxᵢ; at an interior point mᵢ = 0 if s_{i−1} sᵢ ≤ 0, else the
//!    harmonic mean 2 s_{i−1} sᵢ / (s_{i−1} + sᵢ) (it lies between them and is at most twice the
//!    smaller); at the ends the three-point value (3s − m_next)/2, set to 0 if its sign differs
//!    from s.
//! 2. Runs of collinear data (equal chord slopes and end slopes on them) become one straight
//!    λ-curve with the midpoint as middle control point.
//! 3. An interval whose chord slope lies between its end slopes gets one cubic λ-curve
//!    (n = 2) whose middle control point is the intersection of the two tangent lines.
//! 4. Otherwise the data has an inflection inside the interval: it gets two λ-curves through
//!    L = Dᵢ + (h/4)(1, mᵢ), Z = (L + R)/2, R = D_{i+1} − (h/4)(1, m_{i+1}).
//!
//! Every joint is G1 (the neighbouring legs are collinear and point the same way) for every
//! λ ∈ (−2, 1] (λ = −2 makes the tangent vanish). For monotone data every control polygon is
//! monotone, so the curves are too (their Bézier polygons are corner cuttings).

use bez_core::Vector2;

use crate::curve::LambdaBezierCurve;
use crate::error::LambdaError;

/// The control polygons (3 points each, n = 2) of the construction in the module docs.
///
/// # Errors
/// [`LambdaError::TooFewPoints`] below 2 points, [`LambdaError::NotIncreasing`] if the
/// abscissae do not increase strictly, `CoreError::NonFinite` or `CoordinateOutOfRange` for
/// data outside the coordinate contract, `CoreError::Overflow` when a slope overflows.
pub fn shape_preserving_polygons(data: &[Vector2]) -> Result<Vec<[Vector2; 3]>, LambdaError> {
    if data.len() < 2 {
        return Err(LambdaError::TooFewPoints {
            needed: 2,
            got: data.len(),
        });
    }
    if let Some(index) = data
        .iter()
        .position(|p| !(p.x().is_finite() && p.y().is_finite()))
    {
        return Err(bez_core::CoreError::NonFinite { index }.into());
    }
    if let Some((index, p)) = data
        .iter()
        .enumerate()
        .find(|(_, p)| p.amax() > bez_core::MAX_COORDINATE)
    {
        return Err(bez_core::CoreError::CoordinateOutOfRange {
            index,
            value: p.amax(),
            max: bez_core::MAX_COORDINATE,
        }
        .into());
    }
    if let Some(i) = (1..data.len()).find(|&i| data[i].x() <= data[i - 1].x()) {
        return Err(LambdaError::NotIncreasing {
            index: i,
            value: data[i].x(),
        });
    }
    let s: Vec<f64> = data
        .windows(2)
        .map(|w| (w[1].y() - w[0].y()) / (w[1].x() - w[0].x()))
        .collect();
    let last = s.len() - 1;
    let mut m = vec![0.0; data.len()];
    for i in 1..data.len() - 1 {
        let (a, b) = (s[i - 1], s[i]);
        m[i] = if a * b <= 0.0 {
            0.0
        } else {
            2.0 * a * b / (a + b)
        };
    }
    let end = |chord: f64, next: f64| {
        let v = (3.0 * chord - next) / 2.0;
        if v * chord <= 0.0 { 0.0 } else { v }
    };
    if data.len() == 2 {
        m[0] = s[0];
        m[1] = s[0];
    } else {
        m[0] = end(s[0], m[1]);
        m[last + 1] = end(s[last], m[last]);
    }
    let line = |i: usize| m[i] == s[i] && m[i + 1] == s[i];
    let mut out = Vec::new();
    let mut i = 0;
    while i <= last {
        let (p, q) = (data[i], data[i + 1]);
        if line(i) {
            let mut j = i;
            while j < last && line(j + 1) && s[j + 1] == s[i] {
                j += 1;
            }
            let r = data[j + 1];
            out.push([p, (p + r) / 2.0, r]);
            i = j + 1;
            continue;
        }
        let (mi, mj, si) = (m[i], m[i + 1], s[i]);
        if (mi - si) * (mj - si) < 0.0 {
            // Tangent lines y = p.y + mi (x − p.x) and y = q.y + mj (x − q.x) meet strictly inside.
            let x = (q.y() - p.y() + mi * p.x() - mj * q.x()) / (mi - mj);
            out.push([p, Vector2::new(x, p.y() + mi * (x - p.x())), q]);
        } else {
            let h = q.x() - p.x();
            let l = p + Vector2::new(h / 4.0, mi * h / 4.0);
            let r = q - Vector2::new(h / 4.0, mj * h / 4.0);
            let z = (l + r) / 2.0;
            out.push([p, l, z]);
            out.push([z, r, q]);
        }
        i += 1;
    }
    // Chord slopes of nearly vertical steps (Δx tiny against Δy) can overflow.
    if out.iter().flatten().all(Vector2::is_finite) {
        Ok(out)
    } else {
        Err(bez_core::CoreError::Overflow {
            operation: "shape-preserving slopes",
        }
        .into())
    }
}

/// The cubic λ-curves (n = 2) on [`shape_preserving_polygons`], λ cycling through `lambdas`
/// (one value for all, or one per curve).
///
/// # Errors
/// As [`shape_preserving_polygons`]; [`LambdaError::LambdaCount`] if `lambdas` is empty;
/// λ outside [−2, 1].
pub fn shape_preserving_curves(
    data: &[Vector2],
    lambdas: &[f64],
) -> Result<Vec<LambdaBezierCurve<2>>, LambdaError> {
    let polygons = shape_preserving_polygons(data)?;
    if lambdas.is_empty() {
        return Err(LambdaError::LambdaCount {
            expected: polygons.len(),
            got: 0,
        });
    }
    polygons
        .iter()
        .zip(lambdas.iter().cycle())
        .map(|(p, &l)| LambdaBezierCurve::new(p.to_vec(), l))
        .collect()
}

#[cfg(all(test, feature = "paper"))]
mod tests {
    use super::*;
    use crate::cases::akima_data;
    use crate::join::{Continuity, continuity};
    use bez_core::BezierForm;

    #[test]
    fn akima_interpolant_is_g1_monotone_and_interpolating() {
        let data = akima_data();
        for lambdas in [
            vec![-1.0],
            vec![0.0],
            vec![1.0],
            vec![0.0, 1.0, -1.0, 0.0, 1.0],
        ] {
            let curves = shape_preserving_curves(&data, &lambdas).unwrap();
            // One straight piece for the flat run, then curved pieces.
            assert_eq!(curves[0].points()[0], data[0]);
            assert_eq!(curves[0].points()[2], data[5]);
            for w in curves.windows(2) {
                let c = continuity(&w[0], &w[1], 1e-12);
                assert!(c >= Continuity::G1, "{c:?}");
            }
            // Every data point is an end point of some curve or lies on the straight piece.
            let line = curves[0].points();
            for d in &data[1..5] {
                let cross = (line[2] - line[0]).perp(&(d - line[0]));
                assert!(cross == 0.0 && d.x() > line[0].x() && d.x() < line[2].x());
            }
            for d in data.iter().filter(|d| !(1.0..9.0).contains(&d.x())) {
                assert!(
                    curves
                        .iter()
                        .any(|c| c.points()[0] == *d || c.points()[2] == *d)
                );
            }
            // Monotone Bézier polygons (x and y non-decreasing) ⇒ monotone curve.
            for c in &curves {
                let q = c.as_bezier().points();
                for w in q.windows(2) {
                    assert!(
                        w[1].x() >= w[0].x() && w[1].y() >= w[0].y() - 1e-12,
                        "{q:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn errors() {
        let d = akima_data();
        assert!(matches!(
            shape_preserving_polygons(&d[..1]),
            Err(LambdaError::TooFewPoints { .. })
        ));
        let mut bad = d.clone();
        bad[3][0] = bad[2].x();
        assert!(matches!(
            shape_preserving_polygons(&bad),
            Err(LambdaError::NotIncreasing { index: 3, .. })
        ));
        bad[3][0] = f64::NAN;
        assert!(shape_preserving_polygons(&bad).is_err());
        assert!(matches!(
            shape_preserving_curves(&d, &[]),
            Err(LambdaError::LambdaCount { .. })
        ));
        assert!(shape_preserving_curves(&d, &[-2.5]).is_err());
        let two = shape_preserving_polygons(&d[5..7]).unwrap();
        assert_eq!(two.len(), 1);
    }
}
