//! Gauss–Legendre quadrature on [0, 1].

/// The `count`-point Gauss–Legendre rule on [0, 1]: (nodes, weights), exact for polynomials
/// of degree ≤ 2·count − 1. Nodes are the roots of P_count found by Newton's method from
/// the asymptotic guesses cos(π(i − 1/4)/(count + 1/2)).
pub(crate) fn gauss_legendre(count: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = Vec::with_capacity(count);
    let mut weights = Vec::with_capacity(count);
    for i in 1..=count {
        let mut x = (std::f64::consts::PI * (i as f64 - 0.25) / (count as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            // Three-term recurrence for P_count(x) and its derivative.
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=count {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            dp = count as f64 * (x * p1 - p0) / (x * x - 1.0);
            let step = p1 / dp;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        nodes.push(0.5 * (1.0 - x));
        weights.push(0.5 * w);
    }
    (nodes, weights)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rule_integrates_monomials_exactly() {
        for count in [1usize, 2, 5, 12, 41] {
            let (x, w) = gauss_legendre(count);
            for d in 0..2 * count {
                let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(d as i32)).sum();
                let exact = 1.0 / (d as f64 + 1.0);
                assert!((s - exact).abs() < 1e-13, "count {count} degree {d}: {s}");
            }
        }
    }
}
