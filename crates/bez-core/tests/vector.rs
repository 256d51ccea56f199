//! Property tests of `Vector`: every operation gives the same bits as the naive formula and as
//! nalgebra's fixed-size vectors (the type bez-core used before), plus algebraic identities.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    reason = "tests fail loudly on unexpected errors"
)]

use bez_core::{Vector, Vector2, Vector3};
use proptest::prelude::*;

fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![-1e3..1e3f64, -1.0..1.0f64, -1e-8..1e-8f64]
}

fn v3() -> impl Strategy<Value = [f64; 3]> {
    proptest::array::uniform3(coord())
}

fn v2() -> impl Strategy<Value = [f64; 2]> {
    proptest::array::uniform2(coord())
}

proptest! {
    #[test]
    fn ops_match_nalgebra_bit_for_bit(a in v3(), b in v3(), s in coord()) {
        let (va, vb) = (Vector3::from(a), Vector3::from(b));
        let (na, nb) = (nalgebra::Vector3::from(a), nalgebra::Vector3::from(b));
        let same = |v: Vector3, n: nalgebra::Vector3<f64>| {
            (0..3).all(|i| v[i].to_bits() == n[i].to_bits())
        };
        prop_assert!(same(va + vb, na + nb));
        prop_assert!(same(va - vb, na - nb));
        prop_assert!(same(-va, -na));
        prop_assert!(same(va * s, na * s));
        prop_assert!(same(s * va, s * na));
        prop_assert!(same(va.cross(&vb), na.cross(&nb)));
        prop_assert!(same(va.abs(), na.abs()));
        prop_assert!(same(va.inf(&vb), na.inf(&nb)));
        prop_assert!(same(va.sup(&vb), na.sup(&nb)));
        prop_assert_eq!(va.dot(&vb).to_bits(), na.dot(&nb).to_bits());
        prop_assert_eq!(va.norm_squared().to_bits(), na.norm_squared().to_bits());
        prop_assert_eq!(va.norm().to_bits(), na.norm().to_bits());
        prop_assert_eq!(va.amax().to_bits(), na.amax().to_bits());
        prop_assert_eq!(va.max().to_bits(), na.max().to_bits());
        prop_assert_eq!(va.min().to_bits(), na.min().to_bits());
        if s != 0.0 {
            prop_assert!(same(va / s, na / s));
        }
        if na.norm() > 0.0 {
            prop_assert!(same(va.normalize(), na.normalize()));
        }
        let list = [va, vb, va * s];
        let nlist = [na, nb, na * s];
        prop_assert!(same(list.iter().sum(), nlist.iter().sum()));
    }

    #[test]
    fn planar_ops_match_nalgebra_bit_for_bit(a in v2(), b in v2()) {
        let (va, vb) = (Vector2::from(a), Vector2::from(b));
        let (na, nb) = (nalgebra::Vector2::from(a), nalgebra::Vector2::from(b));
        prop_assert_eq!(va.perp(&vb).to_bits(), na.perp(&nb).to_bits());
        prop_assert_eq!(va.dot(&vb).to_bits(), na.dot(&nb).to_bits());
        prop_assert_eq!(va.norm().to_bits(), na.norm().to_bits());
        prop_assert_eq!(nalgebra::Vector2::from(va), na);
    }

    #[test]
    fn ops_match_the_naive_formulas(a in v3(), b in v3()) {
        let (va, vb) = (Vector3::from(a), Vector3::from(b));
        let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        prop_assert_eq!(va.dot(&vb).to_bits(), dot.to_bits());
        let nsq = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        prop_assert_eq!(va.norm().to_bits(), nsq.sqrt().to_bits());
        // Symmetry is exact; the Lagrange identity |a × b|² + (a·b)² = |a|²|b|² up to rounding.
        prop_assert_eq!(va.dot(&vb).to_bits(), vb.dot(&va).to_bits());
        let lhs = va.cross(&vb).norm_squared() + dot * dot;
        let rhs = va.norm_squared() * vb.norm_squared();
        prop_assert!((lhs - rhs).abs() <= 1e-12 * rhs.max(f64::MIN_POSITIVE));
        prop_assert_eq!(va.cross(&vb), -vb.cross(&va));
    }

    #[test]
    fn json_matches_the_plain_array(a in v3(), d in proptest::array::uniform5(coord())) {
        // serde_json's default float parser is not always correctly rounded, so the oracle is
        // the same text parsed as a plain array.
        let v = Vector3::from(a);
        let json = serde_json::to_string(&v).unwrap();
        prop_assert_eq!(&json, &serde_json::to_string(&a).unwrap());
        let parsed: [f64; 3] = serde_json::from_str(&json).unwrap();
        prop_assert_eq!(serde_json::from_str::<Vector3>(&json).unwrap(), Vector3::from(parsed));
        let w = Vector::from(d);
        let json = serde_json::to_string(&w).unwrap();
        let parsed: [f64; 5] = serde_json::from_str(&json).unwrap();
        prop_assert_eq!(serde_json::from_str::<Vector<5>>(&json).unwrap(), Vector::from(parsed));
    }
}
