//! One frame of an interactive edit: the solution for the moved points, its curve, the proven
//! monotonicity certificate and the slope of the logarithmic curvature or torsion graph.

use bez_core::{BezierCurve, Vector2, Vector3};

use crate::{
    Certificate, ClassAError, TypicalPlanar, TypicalSpatial, curvature_certificate, log_graph,
    log_graph_from_points, torsion_certificate, torsion_samples,
};

/// Samples (uniform in t, ends included) of the LCG / LTG behind [`EditFrame::slope`].
pub const FRAME_SAMPLES: usize = 17;

/// What an editor shows after each move: the solution, its control points, the certificate of
/// the quantity its graph plots (curvature for planar curves, torsion for spatial ones) and
/// the graph's least-squares slope.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct EditFrame<T, const D: usize> {
    /// The solved curve's parameters.
    pub solution: T,
    /// Its control points.
    pub curve: BezierCurve<D>,
    /// The proven monotonicity of curvature (planar) or torsion (spatial), or why it could not
    /// be stated (e.g. [`ClassAError::Singular`]).
    pub certificate: Result<Certificate, ClassAError>,
    /// The LCG (planar) or LTG (spatial) slope α from [`FRAME_SAMPLES`] samples; `None` when
    /// the graph has fewer than two usable points.
    pub slope: Option<f64>,
}

impl TypicalPlanar {
    /// One editing frame: [`TypicalPlanar::from_points`] (a planar solve needs no previous
    /// state), its curve, the curvature certificate ([`curvature_certificate`]) and the LCG
    /// slope from the closed-form points ([`TypicalPlanar::log_curvature_point`]).
    ///
    /// ```
    /// use bez_core::Vector2;
    /// use class_a::TypicalPlanar;
    /// let (a0, a1) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
    /// let f = TypicalPlanar::edit(&a0, &a1, &Vector2::new(1.6, 1.0), 7)?;
    /// assert!(f.certificate?.is_monotone());
    /// assert!(f.slope.is_some_and(f64::is_finite));
    /// # Ok::<(), class_a::ClassAError>(())
    /// ```
    ///
    /// # Errors
    /// As [`TypicalPlanar::from_points`].
    pub fn edit(
        a0: &Vector2,
        a1: &Vector2,
        a2: &Vector2,
        degree: usize,
    ) -> Result<EditFrame<Self, 2>, ClassAError> {
        let solution = Self::from_points(a0, a1, a2, degree)?;
        let curve = solution.curve()?;
        let certificate = curvature_certificate(&curve);
        let points = (0..FRAME_SAMPLES)
            .filter_map(|i| solution.log_curvature_point(i as f64 / (FRAME_SAMPLES - 1) as f64))
            .collect();
        let slope = log_graph_from_points(points).ok().map(|g| g.slope);
        Ok(EditFrame {
            solution,
            curve,
            certificate,
            slope,
        })
    }
}

impl TypicalSpatial {
    /// One editing frame continued from `self` (the previous frame's solution) for the moved
    /// points α₀..α₃: the solution, its curve, the torsion certificate ([`torsion_certificate`])
    /// and the LTG slope ([`torsion_samples`], [`log_graph`]). This is the editing API.
    ///
    /// The solution follows `self`'s branch: damped Newton from `self`'s (φ, log s) on its
    /// branch k = round(((n − 1)θ − ψ)/2π), without the grid; if that does not converge to a
    /// Class A curve passing the checks of [`TypicalSpatial::solve`], the full
    /// [`TypicalSpatial::from_points`] is run. Following the branch keeps the curve continuous
    /// during a drag (it need not be the least-turning solution `from_points` would pick).
    ///
    /// ```
    /// use bez_core::Vector3;
    /// use class_a::TypicalSpatial;
    /// let mut a = [
    ///     Vector3::new(0.0, 0.0, 0.0),
    ///     Vector3::new(1.0, 0.0, 0.2),
    ///     Vector3::new(6.21, 6.54, 1.79),
    ///     Vector3::new(6.12, 9.44, 2.73),
    /// ];
    /// let mut t = TypicalSpatial::from_points(&a, 7)?;
    /// for _ in 0..10 {
    ///     a[3] += Vector3::new(0.02, 0.01, 0.0);
    ///     let f = t.edit(&a)?;
    ///     assert!(f.certificate.is_ok() && f.slope.is_some());
    ///     assert!((f.curve.end() - a[3]).norm() < 1e-9);
    ///     t = f.solution;
    /// }
    /// assert!(t.class_a_margin() >= 0.0);
    /// # Ok::<(), class_a::ClassAError>(())
    /// ```
    ///
    /// # Errors
    /// As [`TypicalSpatial::from_points`].
    pub fn edit(&self, a: &[Vector3; 4]) -> Result<EditFrame<Self, 3>, ClassAError> {
        let solution = self.update(a)?;
        let curve = solution.curve()?;
        let certificate = torsion_certificate(&curve);
        let slope = torsion_samples(&curve, FRAME_SAMPLES)
            .ok()
            .and_then(|s| log_graph(&s).ok())
            .map(|g| g.slope);
        Ok(EditFrame {
            solution,
            curve,
            certificate,
            slope,
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, reason = "tests fail loudly")]
    use super::*;
    use crate::curvature_samples;

    #[test]
    fn planar_frames_agree_with_the_separate_calls() {
        let (a0, a1) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
        for (a2, n) in [(Vector2::new(1.6, 1.0), 7), (Vector2::new(2.0, 0.4), 12)] {
            let f = TypicalPlanar::edit(&a0, &a1, &a2, n).unwrap();
            let t = TypicalPlanar::from_points(&a0, &a1, &a2, n).unwrap();
            assert_eq!(f.curve, t.curve().unwrap());
            assert_eq!(f.certificate, curvature_certificate(&f.curve));
            // Condition (4) is exact for typical planar curves: the certificate agrees.
            assert_eq!(f.certificate.unwrap().is_monotone(), t.margin() >= 0.0);
            // The closed-form LCG against one from control-point derivatives.
            let samples = curvature_samples(&f.curve, FRAME_SAMPLES).unwrap();
            let slope = log_graph(&samples).unwrap().slope;
            assert!(
                (f.slope.unwrap() - slope).abs() < 1e-8,
                "{:?} {slope}",
                f.slope
            );
        }
    }

    #[test]
    fn spatial_frames_continue_the_drag() {
        let mut a = [
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0, 0.0, 0.2),
            Vector3::new(6.21, 6.54, 1.79),
            Vector3::new(6.12, 9.44, 2.73),
        ];
        let mut t = TypicalSpatial::from_points(&a, 7).unwrap();
        for _ in 0..5 {
            a[3] += Vector3::new(0.03, -0.02, 0.01);
            let f = t.edit(&a).unwrap();
            let next = t.update(&a).unwrap();
            assert_eq!(f.curve, next.curve().unwrap());
            assert_eq!(f.certificate, torsion_certificate(&f.curve));
            let samples = torsion_samples(&f.curve, FRAME_SAMPLES).unwrap();
            assert_eq!(f.slope, Some(log_graph(&samples).unwrap().slope));
            t = f.solution;
        }
    }
}
