//! The B-spline form of a solution and its STEP export round trip.

#![allow(clippy::unwrap_used, reason = "test helpers unwrap known-good inputs")]

use bez_core::Vector3;
use pde_bezier::cases;
use pde_bezier::{
    BSplineSurface, Method, PdeError, read_iges, read_step, solve, write_iges, write_step,
};

/// The STEP text of `s` (written into a byte buffer).
fn step_string(s: &BSplineSurface, name: &str) -> Result<String, PdeError> {
    let mut out = Vec::new();
    write_step(s, name, &mut out)?;
    Ok(String::from_utf8(out).unwrap())
}

/// The IGES text of `s`.
fn iges_string(s: &BSplineSurface, name: &str) -> Result<String, PdeError> {
    let mut out = Vec::new();
    write_iges(s, name, &mut out)?;
    Ok(String::from_utf8(out).unwrap())
}

fn solutions() -> Vec<pde_bezier::Solution> {
    let mut cs = vec![cases::enneper(2, 3, 2).unwrap(), cases::vase(2, 4).unwrap()];
    cs.push(cases::cylinder_plane(2, 8).unwrap());
    // A non-square, non-symmetric net: bidegree (5, 4) on 3 x 2 patches.
    let mut c = cases::enneper(3, 3, 2).unwrap();
    c.disc.degree_v = 4;
    c.disc.smoothness_v = 1;
    cs.push(c);
    cs.iter()
        .map(|c| solve(&c.problem, &c.disc, Method::Galerkin).unwrap())
        .collect()
}

#[test]
fn spline_form_equals_patch_grid() {
    for sol in solutions() {
        for i in 0..=12 {
            for j in 0..=12 {
                let (u, v) = (i as f64 / 12.0, j as f64 / 12.0);
                let a = sol.spline.eval(u, v).unwrap();
                let b = sol.surface.eval(u, v).unwrap();
                assert!((a - b).norm() < 1e-11, "({u}, {v}): {a} vs {b}");
            }
        }
    }
}

#[test]
fn step_round_trips_exactly() {
    for sol in solutions() {
        let text = step_string(&sol.spline, "pde surface").unwrap();
        assert!(text.starts_with("ISO-10303-21;"));
        assert!(text.contains("B_SPLINE_SURFACE_WITH_KNOTS"));
        assert!(text.contains("SHAPE_DEFINITION_REPRESENTATION"));
        // Every real has a decimal point and an upper-case exponent.
        for line in text.lines().filter(|l| l.contains("CARTESIAN_POINT")) {
            assert!(
                !line.contains('e') && line.contains(".") && line.contains('E'),
                "{line}"
            );
        }
        let back = read_step(&text).unwrap();
        assert_eq!(back, std::slice::from_ref(&sol.spline));
        for (u, v) in [(0.1, 0.7), (0.55, 0.2), (1.0, 1.0)] {
            let d = back[0].eval(u, v).unwrap() - sol.surface.eval(u, v).unwrap();
            assert!(d.norm() < 1e-11);
        }
    }
}

#[test]
fn step_rejects_bad_input() {
    let s = BSplineSurface {
        degree_u: 1,
        degree_v: 1,
        knots_u: vec![0.0, 0.0, 1.0, 1.0],
        knots_v: vec![0.0, 0.0, 1.0, 1.0],
        points: vec![
            Vector3::zeros(),
            Vector3::zeros(),
            Vector3::zeros(),
            Vector3::new(f64::NAN, 0.0, 0.0),
        ],
    };
    assert!(matches!(
        step_string(&s, "x"),
        Err(PdeError::NonFinite { .. })
    ));
    let short = BSplineSurface {
        points: vec![Vector3::zeros(); 3],
        ..s.clone()
    };
    assert!(matches!(step_string(&short, "x"), Err(PdeError::Core(_))));
    let decreasing = BSplineSurface {
        knots_v: vec![0.0, 0.5, 0.2, 1.0],
        points: vec![Vector3::zeros(); 4],
        ..s.clone()
    };
    assert_eq!(
        step_string(&decreasing, "x"),
        Err(PdeError::DecreasingKnots {
            direction: "v",
            index: 2
        })
    );
    let good = BSplineSurface {
        points: vec![Vector3::zeros(); 4],
        ..s
    };
    let text = step_string(&good, "x").unwrap();
    read_step(&text).unwrap();
    // A real without a decimal point, a missing point entity, truncation.
    let broken = text.replacen("0.0000000000000000E0", "1E-7", 1);
    assert!(
        matches!(read_step(&broken), Err(PdeError::Step { .. })),
        "{broken}"
    );
    let missing = text.replace("#15=CARTESIAN_POINT", "#99=CARTESIAN_POINT");
    assert!(matches!(read_step(&missing), Err(PdeError::Step { .. })));
    assert!(matches!(
        read_step(&text[..text.len() / 2]),
        Err(PdeError::Step { .. })
    ));
    assert!(matches!(read_step("garbage"), Err(PdeError::Step { .. })));
    let reversed = "ISO-10303-21;\nENDSEC;\nEND-ISO-10303-21;\nDATA;\n";
    assert!(matches!(read_step(reversed), Err(PdeError::Step { .. })));
}

#[test]
fn iges_round_trips_exactly() {
    for sol in solutions() {
        let text = iges_string(&sol.spline, "pde surface").unwrap();
        for line in text.lines() {
            assert_eq!(line.len(), 80, "{line}");
        }
        assert!(text.lines().last().unwrap().starts_with("S      1G"));
        let back = read_iges(&text).unwrap();
        assert_eq!(back, std::slice::from_ref(&sol.spline));
    }
}

#[test]
fn iges_rejects_bad_input() {
    let sol = &solutions()[0];
    let text = iges_string(&sol.spline, "x").unwrap();
    assert!(matches!(
        read_iges("short line\n"),
        Err(PdeError::Iges { .. })
    ));
    let no_t: String = text
        .lines()
        .filter(|l| l.as_bytes()[72] != b'T')
        .map(|l| format!("{l}\n"))
        .collect();
    assert!(matches!(read_iges(&no_t), Err(PdeError::Iges { .. })));
    let truncated: String = text
        .lines()
        .enumerate()
        .filter(|(i, l)| l.as_bytes()[72] != b'P' || *i < 8)
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    assert!(matches!(read_iges(&truncated), Err(PdeError::Iges { .. })));
}

mod fuzz {
    use super::*;
    use proptest::prelude::*;

    fn sample_texts() -> (String, String) {
        let s = BSplineSurface {
            degree_u: 2,
            degree_v: 1,
            knots_u: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            knots_v: vec![0.0, 0.0, 1.0, 1.0],
            points: (0..6).map(|i| Vector3::new(i as f64, 0.5, -1.0)).collect(),
        };
        (step_string(&s, "f").unwrap(), iges_string(&s, "f").unwrap())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn readers_never_panic(junk in ".{0,200}", cut in 0usize..4000, byte in 0u8..128) {
            let _ = read_step(&junk);
            let _ = read_iges(&junk);
            let (step, iges) = sample_texts();
            for text in [step, iges] {
                let cut = cut.min(text.len());
                let _ = read_step(&text[..cut]);
                let _ = read_iges(&text[..cut]);
                let mut bytes = text.into_bytes();
                let at = cut.min(bytes.len() - 1);
                bytes[at] = byte;
                let mutated = String::from_utf8_lossy(&bytes).into_owned();
                let _ = read_step(&mutated);
                let _ = read_iges(&mutated);
            }
        }
    }
}
