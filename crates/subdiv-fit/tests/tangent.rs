//! Tangent vertices (a double knot): refinement against exact evaluation, an independent de Boor
//! evaluation against the Bézier output, tangent continuity with a curvature jump, serde.

use proptest::prelude::*;
use subdiv_fit::{Closure, SubdivCurve, SubdivFitError, Vector2, VertexKind};

/// The knot of every vertex: `k_0 = 0`, `k_{i+1} = k_i` after a tangent vertex, else `k_i + 1`.
fn vertex_knots(kinds: &[VertexKind]) -> Vec<f64> {
    let mut k = Vec::with_capacity(kinds.len());
    let mut at = 0.0;
    for kind in kinds {
        k.push(at);
        if *kind != VertexKind::Tangent {
            at += 1.0;
        }
    }
    k
}

/// Textbook de Boor evaluation (in the usual indexing: control point `c_i` on the knots
/// `t_i … t_{i+4}`) of a closed cubic B-spline with regular and tangent vertices only, written
/// independently of the crate: vertex `i` has the middle knot `k_i`, so `t_i = k_{i−2}`, and the
/// periodic knot vector is unrolled.
fn de_boor_closed(points: &[Vector2], kinds: &[VertexKind], x: f64) -> Vector2 {
    let n = points.len() as isize;
    let k = vertex_knots(kinds);
    let period = k[k.len() - 1]
        + if kinds[k.len() - 1] == VertexKind::Tangent {
            0.0
        } else {
            1.0
        };
    let t = |i: isize| {
        let m = i - 2;
        k[m.rem_euclid(n) as usize] + period * m.div_euclid(n) as f64
    };
    let c = |i: isize| points[i.rem_euclid(n) as usize];
    let mut span = 0isize;
    while t(span + 1) <= x {
        span += 1;
    }
    while t(span) > x {
        span -= 1;
    }
    let p = 3isize;
    let mut d: Vec<Vector2> = (0..=p).map(|j| c(j + span - p)).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let (lo, hi) = (t(j + span - p), t(j + 1 + span - r));
            let alpha = (x - lo) / (hi - lo);
            d[j as usize] = (1.0 - alpha) * d[j as usize - 1] + alpha * d[j as usize];
        }
    }
    d[p as usize]
}

fn wavy(n: usize) -> Vec<Vector2> {
    (0..n)
        .map(|i| {
            let t = i as f64 / n as f64 * std::f64::consts::TAU;
            let r = 1.0 + 0.3 * (3.0 * t).sin() + 0.1 * (i % 3) as f64;
            Vector2::new(r * t.cos(), r * t.sin())
        })
        .collect()
}

fn with_kinds(n: usize, tangent: &[usize], sharp: &[usize]) -> Vec<VertexKind> {
    let mut kinds = vec![VertexKind::Regular; n];
    for &i in tangent {
        kinds[i] = VertexKind::Tangent;
    }
    for &i in sharp {
        kinds[i] = VertexKind::Sharp;
    }
    kinds
}

/// Test curves: closed with two tangent vertices (one of them two apart from another double
/// knot's partner), closed with a sharp vertex too, open with sharp ends.
#[allow(clippy::unwrap_used, reason = "test helper")]
fn test_curves() -> Vec<SubdivCurve<2>> {
    vec![
        SubdivCurve::new(wavy(10), with_kinds(10, &[2, 5], &[]), Closure::Closed).unwrap(),
        SubdivCurve::new(wavy(14), with_kinds(14, &[3, 8], &[12]), Closure::Closed).unwrap(),
        SubdivCurve::new(wavy(12), with_kinds(12, &[4, 7], &[]), Closure::Open).unwrap(),
    ]
}

fn params(c: &SubdivCurve<2>, per: usize) -> Vec<f64> {
    let m = c.segment_count() * per;
    (0..=m).map(|j| j as f64 / per as f64).collect()
}

/// One refinement is exact knot insertion: the refined curve at `2 s` is the curve at `s`; after
/// `L` levels vertex `m`'s limit is the curve at `k_m / 2^L`, and the raw vertices converge to
/// the curve (their distance shrinks about 4x per level, as for a cubic B-spline).
#[test]
fn refinement_converges_to_the_exact_curve() {
    for c in test_curves() {
        let r = c.refine();
        assert_eq!(r.segment_count(), 2 * c.segment_count());
        for s in params(&c, 7) {
            let (a, b) = (c.eval(s).unwrap(), r.eval(2.0 * s).unwrap());
            assert!((a - b).norm() < 1e-12, "s = {s}: {a:?} vs {b:?}");
        }
        let mut raw = Vec::new();
        for levels in [2, 4, 6] {
            let r = c.refine_levels(levels).unwrap();
            let scale = f64::from(1u32 << levels);
            let knots = vertex_knots(r.kinds());
            let mut worst = 0.0_f64;
            let count = knots.len();
            for (m, &k) in knots.iter().enumerate() {
                let exact = c.eval(k / scale).unwrap();
                let mask = r.limit_position(m).unwrap();
                assert!((mask - exact).norm() < 1e-12, "level {levels}, vertex {m}");
                // A control point sits next to the curve at its Greville abscissa (the mean of
                // its three middle knots; a sharp vertex at its own knot), O(h²) away.
                let greville = if r.is_sharp(m) {
                    k
                } else {
                    let before = knots[(m + count - 1) % count];
                    let after = knots[(m + 1) % count];
                    let period = r.segment_count() as f64;
                    let before = if before > k { before - period } else { before };
                    let after = if after < k { after + period } else { after };
                    (before + k + after) / 3.0
                };
                let near = c.eval(greville / scale).unwrap();
                worst = worst.max((r.points()[m] - near).norm());
            }
            raw.push(worst);
        }
        assert!(raw[1] < raw[0] / 10.0 && raw[2] < raw[1] / 10.0, "{raw:?}");
        assert!(raw[2] < 1e-3, "{raw:?}");
    }
}

/// The Bézier output and the exact evaluation agree with an independent de Boor evaluation.
#[test]
fn de_boor_agrees_with_the_bezier_output() {
    for (n, tangent) in [(10, vec![2, 5]), (9, vec![0, 4]), (7, vec![6])] {
        let points = wavy(n);
        let kinds = with_kinds(n, &tangent, &[]);
        let c = SubdivCurve::new(points.clone(), kinds.clone(), Closure::Closed).unwrap();
        assert_eq!(c.segment_count(), n - tangent.len());
        let beziers = c.to_beziers().unwrap();
        for (i, b) in beziers.iter().enumerate() {
            for j in 0..=16 {
                let u = f64::from(j) / 16.0;
                let s = i as f64 + u;
                let want = de_boor_closed(&points, &kinds, s.min(c.segment_count() as f64 - 1e-12));
                let got = b.eval(u).unwrap();
                assert!((got - want).norm() < 1e-9, "n {n}, segment {i}, u {u}");
                assert!((c.eval(s).unwrap() - want).norm() < 1e-9);
            }
        }
    }
}

/// At the double knot the curve is C1 (equal first derivatives, so the tangents agree in
/// direction) and passes through the midpoint of the tangent edge; the second derivatives differ.
#[test]
fn tangent_joint_is_c1_with_a_curvature_jump() {
    for c in test_curves() {
        let k = vertex_knots(c.kinds());
        let p = c.points();
        for (v, kind) in c.kinds().iter().enumerate() {
            if *kind != VertexKind::Tangent {
                continue;
            }
            let s = k[v];
            let seg = s as usize;
            let left = c.eval_segment_derivatives(seg - 1, 1.0).unwrap();
            let right = c.eval_segment_derivatives(seg, 0.0).unwrap();
            assert!((left.position - right.position).norm() < 1e-12);
            assert!((left.position - (p[v] + p[v + 1]) / 2.0).norm() < 1e-12);
            assert!((left.first - right.first).norm() < 1e-12);
            let edge = p[v + 1] - p[v];
            assert!(edge.perp(&right.first).abs() < 1e-12 * edge.norm() * right.first.norm());
            assert!((left.second - right.second).norm() > 1e-3);
        }
    }
}

/// A line meeting an arc tangentially: the polygon is straight up to the tangent vertex's
/// partner and bends after it. The curve is exactly straight before the joint (zero curvature),
/// has a clearly positive curvature right after it, and is tangent-continuous.
#[test]
fn a_line_meets_an_arc() {
    let mut points: Vec<Vector2> = (0..6).map(|i| Vector2::new(f64::from(i), 0.0)).collect();
    // Then around a circle of radius 2 centred at (5, 2), from its bottom point.
    for j in 1..6 {
        let a = f64::from(j) * 0.5 - std::f64::consts::FRAC_PI_2;
        points.push(Vector2::new(5.0 + 2.0 * a.cos(), 2.0 + 2.0 * a.sin()));
    }
    let n = points.len();
    let mut kinds = vec![VertexKind::Regular; n];
    kinds[4] = VertexKind::Tangent;
    let c = SubdivCurve::new(points.clone(), kinds.clone(), Closure::Open).unwrap();
    let curvature = |d: subdiv_fit::CurvePoint<2>| d.first.perp(&d.second) / d.first.norm().powi(3);
    // Segments 0..=3 end at the joint, knot 4 (vertex 4 and 5 share it).
    for j in 0..=8 {
        let u = f64::from(j) / 8.0;
        let d = c.eval_segment_derivatives(3, u).unwrap();
        assert!(
            d.position[1].abs() < 1e-14 && curvature(d).abs() < 1e-14,
            "{u}"
        );
    }
    let left = c.eval_segment_derivatives(3, 1.0).unwrap();
    let right = c.eval_segment_derivatives(4, 0.0).unwrap();
    assert!((left.first - right.first).norm() < 1e-12);
    assert!((right.position - Vector2::new(4.5, 0.0)).norm() < 1e-12);
    assert!(curvature(right) > 0.05, "{}", curvature(right));
    // The same polygon with a regular vertex there is C2: its curvature is continuous, so it
    // cannot be straight up to the joint and bend right after it.
    let smooth = SubdivCurve::smooth(points, Closure::Open).unwrap();
    let (l, r) = (
        smooth.eval_segment_derivatives(4, 1.0).unwrap(),
        smooth.eval_segment_derivatives(5, 0.0).unwrap(),
    );
    assert!((curvature(l) - curvature(r)).abs() < 1e-12);
}

#[test]
fn tangent_vertices_without_room_are_refused() {
    let bad = |n: usize, t: &[usize], s: &[usize], closure| {
        matches!(
            SubdivCurve::new(wavy(n), with_kinds(n, t, s), closure),
            Err(SubdivFitError::InvalidTangent { .. })
        )
    };
    assert!(bad(5, &[1], &[], Closure::Closed));
    assert!(bad(10, &[2, 3], &[], Closure::Closed));
    assert!(bad(10, &[2], &[0], Closure::Closed));
    assert!(bad(10, &[2], &[5], Closure::Closed));
    assert!(bad(10, &[2], &[], Closure::Open));
    assert!(bad(10, &[6], &[], Closure::Open));
    assert!(!bad(10, &[2], &[6], Closure::Closed));
    assert!(!bad(10, &[3, 5], &[], Closure::Open));
}

#[cfg(feature = "serde")]
#[test]
fn serde_round_trip_and_rejection() {
    for c in test_curves() {
        let json = serde_json::to_string(&c).unwrap();
        assert!(json.contains("\"Tangent\""));
        let back: SubdivCurve<2> = serde_json::from_str(&json).unwrap();
        assert_eq!(back.kinds(), c.kinds());
        assert_eq!(back.segment_count(), c.segment_count());
        for (a, b) in back.points().iter().zip(c.points()) {
            assert!((a - b).norm() < 1e-15);
        }
    }
    let bad = r#"{"points":[[0,0],[1,0],[2,1],[1,2],[0,1]],"kinds":["Regular","Tangent","Regular","Regular","Regular"],"closed":true}"#;
    assert!(serde_json::from_str::<SubdivCurve<2>>(bad).is_err());
    let bad = r#"{"points":[[0,0],[1,0],[2,1],[2,2],[1,3],[0,2]],"kinds":["Sharp","Tangent","Regular","Regular","Regular","Regular"],"closed":true}"#;
    assert!(serde_json::from_str::<SubdivCurve<2>>(bad).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random closed polygons with a tangent vertex: C1 at the joint, and one refinement is exact.
    #[test]
    fn random_tangent_joints_are_c1_and_refine_exactly(
        pts in prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), 6..12),
        v in 0usize..12,
    ) {
        let points: Vec<Vector2> = pts.iter().map(|&(x, y)| Vector2::new(x, y)).collect();
        let n = points.len();
        let v = v % n;
        let c = SubdivCurve::new(points, with_kinds(n, &[v], &[]), Closure::Closed).unwrap();
        let s = vertex_knots(c.kinds())[v] as usize;
        let segs = c.segment_count();
        let left = c.eval_segment_derivatives((s + segs - 1) % segs, 1.0).unwrap();
        let right = c.eval_segment_derivatives(s % segs, 0.0).unwrap();
        let scale = 1.0 + left.first.norm();
        prop_assert!((left.position - right.position).norm() < 1e-12 * scale * 10.0);
        prop_assert!((left.first - right.first).norm() < 1e-12 * scale * 10.0);
        let r = c.refine();
        for j in 0..=4 * segs {
            let s = j as f64 / 4.0;
            prop_assert!((c.eval(s).unwrap() - r.eval(2.0 * s).unwrap()).norm() < 1e-11);
        }
    }
}
