//! The basis stays finite and a partition of unity at degrees where C(n, k) overflows `f64`
//! (n ≥ 1030), inside the accepted range of n.
#![allow(clippy::unwrap_used, reason = "tests fail loudly on unexpected errors")]

use lambda_bezier::LambdaBasis;

#[test]
fn basis_row_and_values_are_finite_at_high_degree() {
    for n in [1020, 1500, 4000] {
        for lambda in [-2.0, 0.0, 0.7, 1.0] {
            let basis = LambdaBasis::new(n, lambda).unwrap();
            let mut row = vec![0.0; n + 1];
            for t in [0.0, 1e-3, 0.3, 0.5, 0.97, 1.0] {
                basis.row(t, &mut row).unwrap();
                assert!(
                    row.iter().all(|v| v.is_finite()),
                    "n = {n}, λ = {lambda}, t = {t}"
                );
                let sum: f64 = row.iter().sum();
                assert!(
                    (sum - 1.0).abs() < 1e-9,
                    "n = {n}, λ = {lambda}, t = {t}: Σ = {sum}"
                );
                // Single values agree with the row.
                for k in [0, n / 3, n / 2, n] {
                    let v = basis.eval(k, t).unwrap();
                    assert!((v - row[k]).abs() <= 1e-12 + 1e-9 * row[k].abs(), "k = {k}");
                }
            }
        }
    }
}
