//! The fitting loop: recovery, tolerance, corners, the two-sided measure, errors.

use subdiv_fit::cases::{closed_petals, open_wave, rippled_petals};
use subdiv_fit::{
    ErrorMeasure, FitMode, FitOptions, Insertion, Reduction, SubdivCurve, SubdivFitError, Vector2,
    Vector3, discrete_curvature, feature_points, fit, point_polyline_distance, scaled_corners,
};

fn all_within(data: &[Vector2], fitted: &subdiv_fit::Fit<2>, tol: f64) {
    curve_within(data, &fitted.curve, tol);
}

#[allow(clippy::unwrap_used, reason = "test helper")]
fn curve_within(data: &[Vector2], c: &SubdivCurve<2>, tol: f64) {
    // Independent check: every data point against dense samples of the whole curve.
    let mut samples = Vec::new();
    let count = c.segment_count() * 400;
    let params: Vec<f64> = (0..=count)
        .map(|k| k as f64 * c.segment_count() as f64 / count as f64)
        .collect();
    c.eval_many(&params, &mut samples).unwrap();
    for (i, v) in data.iter().enumerate() {
        let d = samples
            .iter()
            .map(|s| (s - v).norm())
            .fold(f64::INFINITY, f64::min);
        assert!(d <= tol * 1.01, "data point {i} at distance {d}");
    }
}

#[test]
fn recovers_data_sampled_from_a_subdivision_curve() {
    let ctrl = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(3.0, 0.5),
        Vector2::new(4.0, 3.0),
        Vector2::new(2.0, 4.0),
        Vector2::new(-1.0, 3.0),
        Vector2::new(-2.0, 1.0),
    ];
    let truth = SubdivCurve::with_sharp(ctrl, &[2], subdiv_fit::Closure::Closed).unwrap();
    let per = 24;
    let count = truth.segment_count() * per;
    let data: Vec<Vector2> = (0..count)
        .map(|k| truth.eval(k as f64 / per as f64).unwrap())
        .collect();
    let tol = 1e-3;
    let f = fit(&data, subdiv_fit::Closure::Closed, &FitOptions::new(tol)).unwrap();
    let last = f.last().unwrap();
    assert!(last.max_data_to_curve <= tol && last.max_curve_to_data <= tol);
    all_within(&data, &f, tol);
    // The corner of the truth (vertex 2, data index 2 * per) is a sharp fitting point.
    let pos = f.fitting.iter().position(|&i| i == 2 * per).unwrap();
    assert!(f.curve.is_sharp(pos));
    assert_eq!(f.curve.kinds().iter().filter(|k| k.is_sharp()).count(), 1);
    // Recovery: samples of the truth (between the data points too) are close to the fitted curve.
    let mut dense = Vec::new();
    let params: Vec<f64> = (0..=8000)
        .map(|m| m as f64 * f.curve.segment_count() as f64 / 8000.0)
        .collect();
    f.curve.eval_many(&params, &mut dense).unwrap();
    for k in 0..count * 3 {
        let p = truth.eval(k as f64 / (3 * per) as f64).unwrap();
        let d = point_polyline_distance(&p, &dense);
        assert!(d < 2.0 * tol, "{d}");
    }
}

#[test]
fn test_shapes_converge_with_corners_sharp() {
    for (data, closed) in [(closed_petals(1), true), (open_wave(1), false)] {
        for mode in [FitMode::Interpolate, FitMode::LeastSquares] {
            let opts = FitOptions::new(0.01).with_mode(mode);
            let f = fit(&data, subdiv_fit::Closure::from_closed(closed), &opts).unwrap();
            all_within(&data, &f, 0.01);
            let r = f.last().unwrap();
            assert!(r.max_data_to_curve <= 0.01 && r.max_curve_to_data <= 0.01);
            assert_eq!(r.control_points, f.curve.points().len());
            // Sharp control points sit exactly on sharp data points (corners, ends).
            for (j, &i) in f.fitting.iter().enumerate() {
                if f.curve.is_sharp(j) {
                    assert_eq!(f.curve.points()[j], data[i]);
                }
            }
        }
    }
    // The corners of the closed shape are at θ = kπ/2: data indices 0, 16, 32, 48.
    let f = fit(
        &closed_petals(1),
        subdiv_fit::Closure::Closed,
        &FitOptions::new(0.01),
    )
    .unwrap();
    for corner in [0, 16, 32, 48] {
        let j = f.fitting.iter().position(|&i| i == corner).unwrap();
        assert!(f.curve.is_sharp(j), "corner {corner}");
    }
    // The open shape's kinks at data indices 22 and 44, and its ends.
    let f = fit(
        &open_wave(1),
        subdiv_fit::Closure::Open,
        &FitOptions::new(0.01),
    )
    .unwrap();
    for corner in [0, 22, 44, 65] {
        let j = f.fitting.iter().position(|&i| i == corner).unwrap();
        assert!(f.curve.is_sharp(j), "corner {corner}");
    }
}

#[test]
fn discrete_curvature_is_inverse_circumradius() {
    // Three points on a circle of radius 2.
    let r = 2.0;
    let pts: Vec<Vector2> = [0.3_f64, 1.0, 2.2]
        .iter()
        .map(|t| Vector2::new(r * t.cos(), r * t.sin()))
        .collect();
    let k = discrete_curvature(&pts, true);
    for ki in k {
        assert!((ki - 0.5).abs() < 1e-14, "{ki}");
    }
    let open = discrete_curvature(&pts, false);
    assert!(open[0].is_infinite() && open[2].is_infinite());
}

#[test]
fn float_noise_on_straight_runs_and_arcs_makes_no_maxima() {
    // A straight run with rounding-level noise and a circle: no interior features.
    let line: Vec<Vector2> = (0..50)
        .map(|i| Vector2::new(0.1 * i as f64, 0.1 * i as f64 * (1.0 / 3.0)))
        .collect();
    let f = feature_points(&line, false, 140f64.to_radians(), 1e-6, 1e-9);
    assert_eq!(f.iter().map(|p| p.index).collect::<Vec<_>>(), vec![0, 49]);
    let circle: Vec<Vector2> = (0..40)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 40.0 + 0.1;
            Vector2::new(t.cos(), t.sin())
        })
        .collect();
    let f = feature_points(&circle, true, 140f64.to_radians(), 1e-6, 1e-9);
    assert!(f.is_empty(), "{f:?}");
    // Without the prominence test, rounding noise creates maxima on the circle.
    let noisy = feature_points(&circle, true, 140f64.to_radians(), 0.0, 0.0);
    assert!(!noisy.is_empty());
}

/// A square whose top side is given only by its two end points; corners are not taken for sharp
/// (sharp angle 0), so the curve rounds them and bulges above the top side, where no data point
/// lies: the paper's measure passes, the curve-to-data measure does not.
#[test]
fn one_sided_measure_misses_a_bulge_that_two_sided_catches() {
    let mut data = Vec::new();
    for i in 0..=20 {
        data.push(Vector2::new(0.0, 1.0 - i as f64 / 20.0)); // left side, down
    }
    for i in 1..=20 {
        data.push(Vector2::new(i as f64 / 20.0, 0.0)); // bottom
    }
    for i in 1..=20 {
        data.push(Vector2::new(1.0, i as f64 / 20.0)); // right side, up; then back to (0, 1)
    }
    let tol = 0.02;
    let paper = FitOptions::paper(tol).with_sharp_angle(0.0);
    let f = fit(&data, subdiv_fit::Closure::Closed, &paper).unwrap();
    let r = f.last().unwrap();
    assert!(r.max_data_to_curve <= tol);
    assert!(r.max_curve_to_data > 2.0 * tol, "{r:?}");
    let ours = paper.with_measure(ErrorMeasure::TwoSided);
    assert!(matches!(
        fit(&data, subdiv_fit::Closure::Closed, &ours),
        Err(SubdivFitError::NoConvergence { .. })
    ));
}

#[test]
fn bad_input_gives_typed_errors() {
    let ok = closed_petals(1);
    let o = FitOptions::new(0.01);
    assert!(matches!(
        fit(&ok[..2], subdiv_fit::Closure::Open, &o),
        Err(SubdivFitError::TooFewPoints { got: 2, .. })
    ));
    let mut nan = ok.clone();
    nan[5][0] = f64::NAN;
    assert!(matches!(
        fit(&nan, subdiv_fit::Closure::Closed, &o),
        Err(SubdivFitError::NonFinite { index: 5 })
    ));
    let mut dup = ok.clone();
    dup[7] = dup[6];
    assert!(matches!(
        fit(&dup, subdiv_fit::Closure::Closed, &o),
        Err(SubdivFitError::DuplicatePoint { index: 6, next: 7 })
    ));
    let mut wrap = ok.clone();
    wrap.push(wrap[0]);
    assert!(matches!(
        fit(&wrap, subdiv_fit::Closure::Closed, &o),
        Err(SubdivFitError::DuplicatePoint { next: 0, .. })
    ));
    for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            fit(&ok, subdiv_fit::Closure::Closed, &FitOptions::new(t)),
            Err(SubdivFitError::InvalidTolerance { .. })
        ));
    }
    let bad = o.with_sharp_angle(4.0);
    assert!(matches!(
        fit(&ok, subdiv_fit::Closure::Closed, &bad),
        Err(SubdivFitError::InvalidOption {
            name: "sharp_angle",
            ..
        })
    ));
    let capped = o.with_max_rounds(0);
    assert!(matches!(
        fit(&ok, subdiv_fit::Closure::Closed, &capped),
        Err(SubdivFitError::NoConvergence { rounds: 0, .. })
    ));
}

/// The literal rule (insert the worst data point) spaces the fitting points unevenly; bisection
/// reaches the tolerance in fewer rounds with fewer points on the denser open shape (the distance
/// alone: corners' turns unchecked).
#[test]
fn bisection_beats_max_error_insertion() {
    let data = open_wave(10);
    let bisect = FitOptions::new(0.01)
        .with_reduction(Reduction::Off)
        .with_corner_tolerance(None);
    let literal = bisect.with_insertion(Insertion::MaxError);
    let m = fit(&data, subdiv_fit::Closure::Open, &literal).unwrap();
    let b = fit(&data, subdiv_fit::Closure::Open, &bisect).unwrap();
    all_within(&data, &m, 0.01);
    all_within(&data, &b, 0.01);
    assert!(b.rounds() < m.rounds(), "{} vs {}", b.rounds(), m.rounds());
    assert!(b.curve.points().len() < m.curve.points().len());
}

/// Both measures within tolerance, the independent dense check, corners sharp, and well inside the
/// round cap (bisection needs about log2 of the longest failing segment).
#[allow(clippy::unwrap_used, reason = "test helper")]
fn converges_cleanly(data: &[Vector2], mode: FitMode, max_rounds: usize) {
    let tol = 0.01;
    let opts = FitOptions::new(tol).with_mode(mode);
    let f = fit(data, subdiv_fit::Closure::Closed, &opts).unwrap();
    let r = f.last().unwrap();
    assert!(
        r.max_data_to_curve <= tol && r.max_curve_to_data <= tol,
        "{r:?}"
    );
    assert!(f.rounds() <= max_rounds, "{} rounds", f.rounds());
    all_within(data, &f, tol);
    // Inserted points are regular: the sharp vertices are exactly the initial sharp ones.
    let sharp_now: Vec<usize> = (0..f.fitting.len())
        .filter(|&j| f.curve.is_sharp(j))
        .map(|j| f.fitting[j])
        .collect();
    let sharp_initial = scaled_corners(data, subdiv_fit::Closure::Closed, &opts).unwrap();
    assert_eq!(sharp_now, sharp_initial);
}

/// The shape on which the loop used to stall (no convergence within 100 rounds at 10x and 100x
/// density): a failing segment without interior data now bisects its neighbours instead of
/// creeping outward one data point per round.
#[test]
fn many_close_curvature_maxima_converge() {
    for density in [1, 10, 100] {
        let data = rippled_petals(density, 0.08, 9.0, 0.0);
        converges_cleanly(&data, FitMode::Interpolate, 12);
        if density < 100 {
            converges_cleanly(&data, FitMode::LeastSquares, 12);
        }
    }
}

/// A small seeded family of rippled shapes at two densities.
#[test]
fn rippled_family_converges() {
    let mut state: u64 = 0x5eed;
    let mut uniform = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..6 {
        let a = 0.04 + 0.08 * uniform();
        let k = (7.0 + 8.0 * uniform()).floor();
        let phase = std::f64::consts::TAU * uniform();
        for density in [1, 10] {
            converges_cleanly(
                &rippled_petals(density, a, k, phase),
                FitMode::Interpolate,
                12,
            );
        }
    }
}

#[test]
fn fits_space_curves() {
    // The closed test shape lifted onto a wavy band in 3D: corners stay corners.
    let data: Vec<Vector3> = closed_petals(1)
        .iter()
        .enumerate()
        .map(|(i, p)| {
            Vector3::new(
                p.x(),
                p.y(),
                0.2 * (std::f64::consts::TAU * i as f64 / 64.0).sin(),
            )
        })
        .collect();
    let f = fit(&data, subdiv_fit::Closure::Closed, &FitOptions::new(0.01)).unwrap();
    let r = f.last().unwrap();
    assert!(r.max_data_to_curve <= 0.01 && r.max_curve_to_data <= 0.01);
    for corner in [0, 16, 32, 48] {
        let j = f.fitting.iter().position(|&i| i == corner).unwrap();
        assert!(f.curve.is_sharp(j));
        assert_eq!(f.curve.points()[j], data[corner]);
    }
}

/// A fit stopped by the round cap returns, with `NoConvergence`, the curve of its best round and
/// that round's error: for caps 0 to 3 the best error is the smallest of the rounds' errors
/// (each cap's `max_error` is the error of its last round), never above the last round's, and the
/// curve is within that error of every data point (an independent check against dense samples).
#[test]
fn no_convergence_returns_the_best_curve_with_its_error() {
    let data = rippled_petals(10, 0.08, 9.0, 0.0);
    let tol = 1e-4;
    let mut smallest = f64::INFINITY;
    for cap in 0..4 {
        let opts = FitOptions::new(tol).with_max_rounds(cap);
        let Err(SubdivFitError::NoConvergence {
            rounds,
            max_error,
            best,
            ..
        }) = fit(&data, subdiv_fit::Closure::Closed, &opts)
        else {
            panic!("cap {cap}: expected NoConvergence");
        };
        assert_eq!(rounds, cap);
        smallest = smallest.min(max_error);
        assert_eq!(best.max_error(), smallest, "cap {cap}");
        assert!(best.max_error() <= max_error && best.max_error() > tol);
        let curve = best.curve::<2>().expect("the data's dimension");
        assert_eq!(curve.points().len(), curve.kinds().len());
        if cap == 3 {
            curve_within(&data, &curve, best.max_error());
        }
    }
}
