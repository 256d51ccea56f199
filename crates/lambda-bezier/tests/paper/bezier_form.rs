//! `LambdaBezierCurve` through the `BezierForm` trait against the λ-B basis of eq. (2).
#![allow(
    clippy::unwrap_used,
    reason = "test support functions outside #[test] fns unwrap known-good values"
)]

use bez_core::proptest_support::check_bezier_form;
use bez_core::{BezierCurve, BezierForm, Vector, Vector2, Vector3};
use lambda_bezier::{LambdaBasis, LambdaBezierCurve, LambdaRange};

/// C(t) = Σ Pᵢ b_{i,n+1}(t) with the basis values from the recurrence (2) itself, started from
/// Han & Liu's degree-3 basis (1): independent of the corner-cut Bézier form.
fn position<const D: usize>(points: &[Vector<D>], basis: &LambdaBasis, t: f64) -> Vector<D> {
    let b = basis.eval_by_recurrence(t).unwrap();
    points.iter().zip(b).map(|(p, w)| p * w).sum()
}

/// C'(t) = Σ Pᵢ b'_{i,n+1}(t), each basis function differentiated on its own Bernstein
/// coefficients (not the hodograph of the curve's Bézier form).
fn velocity<const D: usize>(points: &[Vector<D>], basis: &LambdaBasis, t: f64) -> Vector<D> {
    points
        .iter()
        .enumerate()
        .map(|(k, p)| p * basis.derivative(k, t, 1).unwrap())
        .sum()
}

fn check<const D: usize>(points: Vec<Vector<D>>, lambda: f64) {
    let n = points.len() - 1;
    let basis = LambdaBasis::new(n, lambda).unwrap();
    let curve = LambdaBezierCurve::new(points.clone(), lambda).unwrap();
    assert_eq!(BezierForm::degree(&curve), n + 1);
    let r = check_bezier_form(
        &curve,
        |t| position(&points, &basis, t),
        |t| velocity(&points, &basis, t),
        1e-12,
    );
    assert_eq!(r, Ok(()), "n = {n}, λ = {lambda}");
}

#[test]
fn lambda_curves_match_the_basis_through_the_trait() {
    let planar = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 2.0),
        Vector2::new(3.0, 2.5),
        Vector2::new(4.0, 0.0),
    ];
    for lambda in [-3.0, -1.0, 0.0, 0.56, 1.0] {
        check(planar.clone(), lambda);
    }
    // A spatial quintic λ-curve (n = 5) at both ends of its valid interval.
    let spatial: Vec<Vector3> = (0..6)
        .map(|i| {
            let a = f64::from(i) * 0.9;
            Vector3::new(a.cos(), a.sin(), 0.3 * f64::from(i))
        })
        .collect();
    let range = LambdaRange::new(5).unwrap();
    for lambda in [range.min(), 0.2, range.max()] {
        check(spatial.clone(), lambda);
    }
}

#[test]
fn as_bezier_is_the_corner_cut_form_and_trait_calls_are_bitwise_its_own() {
    let p = vec![
        Vector2::new(-1.0, 0.0),
        Vector2::new(-1.0, 1.2),
        Vector2::new(1.0, 1.2),
        Vector2::new(1.0, 0.0),
    ];
    let c = LambdaBezierCurve::new(p, 0.56).unwrap();
    let b: &BezierCurve<2> = c.as_bezier();
    assert_eq!(b, &c.clone().into_bezier());
    for t in [0.0, 0.3, 0.5, 1.0] {
        assert_eq!(c.eval(t).unwrap(), b.eval(t).unwrap());
        assert_eq!(c.signed_curvature(t), b.signed_curvature(t));
    }
    assert_eq!(c.split(0.3).unwrap(), b.split(0.3).unwrap());
    assert_eq!(c.derivative().unwrap(), b.derivative().unwrap());
    assert_eq!(c.arc_length(1e-9).unwrap(), b.arc_length(1e-9).unwrap());
    // The trait keeps bez-core's typed errors; `?` turns them into LambdaError.
    assert!(c.eval(1.5).is_err());
    let e: lambda_bezier::LambdaError = c.subsegment(0.5, 0.2).unwrap_err().into();
    assert!(e.to_string().contains("[0.5, 0.2]"), "{e}");
}
