//! Exact-arithmetic checks of the λ-B basis: the recurrence (2) against the paper's printed
//! bases, the closed Bernstein form, the valid λ interval and linear independence.
//!
//! Polynomials in t have coefficients linear in λ: `Lin { a, b }` stands for a + bλ.
#![allow(
    clippy::unwrap_used,
    reason = "test support functions outside #[test] fns unwrap known-good values"
)]

use lambda_bezier::{LambdaBasis, LambdaRange};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

#[derive(Clone, Debug, PartialEq)]
struct Lin {
    a: Q,
    b: Q,
}

impl Lin {
    fn new(a: i64, b: i64) -> Self {
        Self {
            a: q(a, 1),
            b: q(b, 1),
        }
    }
    fn at(&self, l: &Q) -> Q {
        &self.a + &self.b * l
    }
    fn add(&self, o: &Self) -> Self {
        Self {
            a: &self.a + &o.a,
            b: &self.b + &o.b,
        }
    }
    fn scale(&self, s: &Q) -> Self {
        Self {
            a: &self.a * s,
            b: &self.b * s,
        }
    }
}

/// Monomial coefficients (index = power of t), each linear in λ.
type Poly = Vec<Lin>;

fn trim(mut p: Poly) -> Poly {
    while p.len() > 1 && p.last().is_some_and(|c| c.a.is_zero() && c.b.is_zero()) {
        p.pop();
    }
    p
}

fn add(p: &Poly, r: &Poly) -> Poly {
    let len = p.len().max(r.len());
    let z = Lin::new(0, 0);
    trim(
        (0..len)
            .map(|i| p.get(i).unwrap_or(&z).add(r.get(i).unwrap_or(&z)))
            .collect(),
    )
}

/// p · (c0 + c1 t) with plain rational c0, c1.
fn mul_lin(p: &Poly, c0: &Q, c1: &Q) -> Poly {
    let mut out = vec![Lin::new(0, 0); p.len() + 1];
    for (i, c) in p.iter().enumerate() {
        out[i] = out[i].add(&c.scale(c0));
        out[i + 1] = out[i + 1].add(&c.scale(c1));
    }
    trim(out)
}

/// p · (λ-linear polynomial in t).
fn mul(p: &Poly, r: &Poly) -> Poly {
    // Only products where one side is λ-free are needed here: r is λ-free or p is.
    let mut out = vec![Lin::new(0, 0); p.len() + r.len() - 1];
    for (i, x) in p.iter().enumerate() {
        for (j, y) in r.iter().enumerate() {
            assert!(
                x.b.is_zero() || y.b.is_zero(),
                "product would be quadratic in λ"
            );
            let prod = Lin {
                a: &x.a * &y.a,
                b: &x.a * &y.b + &x.b * &y.a,
            };
            out[i + j] = out[i + j].add(&prod);
        }
    }
    trim(out)
}

fn pow(p: &Poly, k: usize) -> Poly {
    (0..k).fold(vec![Lin::new(1, 0)], |acc, _| mul(&acc, p))
}

fn t() -> Poly {
    vec![Lin::new(0, 0), Lin::new(1, 0)]
}
fn one_minus_t() -> Poly {
    vec![Lin::new(1, 0), Lin::new(-1, 0)]
}
fn lin(a: i64, b_lambda: i64, c: i64, d_lambda: i64) -> Poly {
    // (a + bλ) + (c + dλ) t
    vec![Lin::new(a, b_lambda), Lin::new(c, d_lambda)]
}

/// The λ-B basis of degree n + 1 by the recurrence (2) from (1), exactly.
fn recurrence(n: usize) -> Vec<Poly> {
    let s = one_minus_t();
    let mut b = vec![
        mul(&lin(1, 0, 0, -1), &pow(&s, 2)),
        mul(&lin(2, 1, 0, 0), &mul(&s, &t())),
        mul(&lin(1, -1, 0, 1), &pow(&t(), 2)),
    ];
    for _ in 3..=n {
        let mut next = Vec::new();
        for k in 0..=b.len() {
            let own = b.get(k).map(|p| mul_lin(p, &q(1, 1), &q(-1, 1)));
            let left = k
                .checked_sub(1)
                .and_then(|i| b.get(i))
                .map(|p| mul_lin(p, &q(0, 1), &q(1, 1)));
            next.push(match (own, left) {
                (Some(x), Some(y)) => add(&x, &y),
                (Some(x), None) | (None, Some(x)) => x,
                (None, None) => unreachable!(),
            });
        }
        b = next;
    }
    b
}

fn binom(n: usize, k: usize) -> Q {
    let mut r = Q::one();
    for i in 0..k {
        r *= q((n - i) as i64, (i + 1) as i64);
    }
    r
}

/// Bernstein B_{i,m} in monomial form.
fn bernstein(m: usize, i: usize) -> Poly {
    let p = mul(&pow(&t(), i), &pow(&one_minus_t(), m - i));
    p.iter().map(|c| c.scale(&binom(m, i))).collect()
}

#[test]
fn recurrence_gives_the_papers_degree_4_and_5_bases() {
    let s = one_minus_t;
    let printed4 = [
        mul(&lin(1, 0, 0, -1), &pow(&s(), 3)),
        mul(&lin(3, 1, 0, -1), &mul(&pow(&s(), 2), &t())),
        mul(&lin(3, 0, 0, 1), &mul(&s(), &pow(&t(), 2))),
        mul(&lin(1, -1, 0, 1), &pow(&t(), 3)),
    ];
    assert_eq!(recurrence(3), printed4.to_vec());
    let printed5 = [
        mul(&lin(1, 0, 0, -1), &pow(&s(), 4)),
        mul(&lin(4, 1, 0, -2), &mul(&pow(&s(), 3), &t())),
        mul(&lin(6, 1, 0, 0), &mul(&pow(&s(), 2), &pow(&t(), 2))),
        mul(&lin(4, -1, 0, 2), &mul(&s(), &pow(&t(), 3))),
        mul(&lin(1, -1, 0, 1), &pow(&t(), 4)),
    ];
    assert_eq!(recurrence(4), printed5.to_vec());
}

/// αⱼ as an exact linear function of λ, written independently of the crate's f64 formula.
fn alpha(n: usize, j: usize) -> Lin {
    let (n, j) = (n as i64, j as i64);
    let base = q(n + 1 - j, n + 1);
    Lin {
        b: &base * q(j * (n + 1 - 2 * j), n * (n - 1)),
        a: base,
    }
}

#[test]
fn closed_bernstein_form_equals_the_recurrence() {
    for n in 2..=15 {
        let rec = recurrence(n);
        let m = n + 1;
        for (k, bk) in rec.iter().enumerate() {
            let a = alpha(n, k);
            let one_minus_next = Lin::new(1, 0).add(&alpha(n, k + 1).scale(&q(-1, 1)));
            let closed = add(
                &mul(&bernstein(m, k), &vec![a]),
                &mul(&bernstein(m, k + 1), &vec![one_minus_next]),
            );
            assert_eq!(&closed, bk, "n = {n}, k = {k}");
        }
    }
}

#[test]
fn f64_ratios_equal_the_exact_ones() {
    use num_traits::ToPrimitive;
    for n in 2..=15 {
        for l in [q(-8, 1), q(-3, 2), q(0, 1), q(7, 10), q(1, 1)] {
            let lf = l.to_f64().unwrap();
            for j in 0..=n + 1 {
                let exact = alpha(n, j).at(&l).to_f64().unwrap();
                let float = lambda_bezier::corner_cut_ratio(n, j, lf);
                assert!((exact - float).abs() <= 4.0 * f64::EPSILON, "n={n} j={j}");
            }
        }
    }
}

/// Exact division of p by (1 − t); panics on a non-zero remainder.
fn div_one_minus_t(p: &Poly) -> Poly {
    // p = (1 − t) r  ⇔  p_i = r_i − r_{i−1}: r_i = p_i + r_{i−1}, and p_deg = −r_{deg−1}.
    let deg = p.len() - 1;
    let mut r: Poly = Vec::with_capacity(deg);
    for i in 0..deg {
        let prev = if i == 0 {
            Lin::new(0, 0)
        } else {
            r[i - 1].clone()
        };
        r.push(p[i].add(&prev));
    }
    assert_eq!(&mul(&r, &one_minus_t()), p, "not divisible by 1 − t");
    r
}

/// The λ interval where every basis function is ≥ 0, computed from the recurrence alone:
/// b_k = t^k (1 − t)^{n−k} q_k(t) with q_k linear in t, found by exact division.
fn interval_from_recurrence(n: usize) -> (Q, Q) {
    let mut lo: Option<Q> = None;
    let mut hi: Option<Q> = None;
    for (k, bk) in recurrence(n).iter().enumerate() {
        assert!(bk[..k].iter().all(|c| c.a.is_zero() && c.b.is_zero()));
        let mut r: Poly = bk[k..].to_vec();
        for _ in 0..n - k {
            r = div_one_minus_t(&r);
        }
        assert!(r.len() <= 2, "quotient is linear");
        let r0 = r[0].clone();
        let r1 = r0.add(r.get(1).unwrap_or(&Lin::new(0, 0)));
        for c in [r0, r1] {
            // a + bλ ≥ 0
            if c.b.is_positive() {
                let bound = -(&c.a / &c.b);
                lo = Some(lo.map_or(bound.clone(), |x| x.max(bound)));
            } else if c.b.is_negative() {
                let bound = -(&c.a / &c.b);
                hi = Some(hi.map_or(bound.clone(), |x| x.min(bound)));
            } else {
                assert!(!c.a.is_negative());
            }
        }
    }
    (lo.unwrap(), hi.unwrap())
}

fn eval_poly(p: &Poly, l: &Q, t: &Q) -> Q {
    p.iter().rev().fold(Q::zero(), |acc, c| acc * t + c.at(l))
}

#[test]
fn valid_interval_equals_an_independent_exact_computation() {
    for n in 2..=24 {
        let (lo, hi) = interval_from_recurrence(n);
        let r = LambdaRange::new(n).unwrap();
        let (num, den) = r.min_fraction();
        assert_eq!(lo, q(-(num as i64), den as i64), "n = {n}");
        assert_eq!(hi, q(1, 1), "n = {n}");
        // Just outside, some basis function is negative at some t (exact evaluation).
        let basis = recurrence(n);
        // The negative region shrinks to an end of [0, 1] as λ → the bound: probe near both.
        let mut probes: Vec<Q> = (1..200).map(|i| q(i, 200)).collect();
        for k in 1..=12 {
            let eps = q(1, 10i64.pow(k));
            probes.push(Q::one() - &eps);
            probes.push(eps);
        }
        for outside in [&lo - q(1, 1000), &hi + q(1, 1000)] {
            let negative = basis.iter().any(|b| {
                probes
                    .iter()
                    .any(|t| eval_poly(b, &outside, t).is_negative())
            });
            assert!(negative, "n = {n}, λ = {outside}");
        }
        // And the float constructor agrees at the ends.
        assert!(LambdaBasis::new(n, r.min()).is_ok());
        assert!(LambdaBasis::new(n, r.min() - 1e-9).is_err());
    }
}

/// Rank of the (n+1) × (n+2) Bernstein coefficient matrix at an exact λ.
fn rank(n: usize, l: &Q) -> usize {
    let mut m: Vec<Vec<Q>> = (0..=n)
        .map(|k| {
            let mut row = vec![Q::zero(); n + 2];
            row[k] = alpha(n, k).at(l);
            row[k + 1] = Q::one() - alpha(n, k + 1).at(l);
            row
        })
        .collect();
    let mut rank = 0;
    for col in 0..n + 2 {
        let Some(p) = (rank..m.len()).find(|&r| !m[r][col].is_zero()) else {
            continue;
        };
        m.swap(rank, p);
        for r in 0..m.len() {
            if r != rank && !m[r][col].is_zero() {
                let f = &m[r][col] / &m[rank][col];
                let pivot = m[rank].clone();
                for (x, p) in m[r].iter_mut().zip(&pivot) {
                    *x -= p * &f;
                }
            }
        }
        rank += 1;
    }
    rank
}

#[test]
fn linear_independence_holds_except_at_the_lower_end() {
    for n in 2..=15 {
        let (num, den) = LambdaRange::new(n).unwrap().min_fraction();
        let lo = q(-(num as i64), den as i64);
        for l in [&lo + q(1, 1000), q(-1, 1), q(0, 1), q(1, 2), q(1, 1)] {
            assert_eq!(rank(n, &l), n + 1, "n = {n}, λ = {l}");
        }
        // Erratum: at λ = min the functions are linearly dependent (n = 2: b_{1,3} ≡ 0;
        // n = 3: b_{1,4} = b_{2,4} = 3t²(1 − t)²).
        assert_eq!(rank(n, &lo), n, "n = {n}");
    }
}

#[test]
fn unimodality_in_the_index_fails_for_negative_lambda() {
    // Eq. (5) of the paper is false: n = 2, λ = −1, t = 39/100 gives b₀ > b₁ < b₂.
    let b = recurrence(2);
    let (l, t) = (q(-1, 1), q(39, 100));
    let v: Vec<Q> = b.iter().map(|p| eval_poly(p, &l, &t)).collect();
    assert!(v[0] > v[1] && v[1] < v[2], "{v:?}");
    assert!(!is_unimodal(&v));
    // The threshold −2/3 is sharp for n = 2: at t = 1/2, b₁ < b₀ = b₂ exactly when λ < −2/3.
    let b = recurrence(2);
    let half = q(1, 2);
    let at = |l: Q| -> Vec<Q> { b.iter().map(|p| eval_poly(p, &l, &half)).collect() };
    assert!(!is_unimodal(&at(q(-2, 3) - q(1, 1000))));
    assert!(is_unimodal(&at(q(-2, 3))));
    // n = 3, λ = −3, t = 2/5.
    let b = recurrence(3);
    let (l, t) = (q(-3, 1), q(2, 5));
    let v: Vec<Q> = b.iter().map(|p| eval_poly(p, &l, &t)).collect();
    assert!(!is_unimodal(&v), "{v:?}");
}

/// Non-decreasing then non-increasing.
fn is_unimodal(v: &[Q]) -> bool {
    let mut falling = false;
    for w in v.windows(2) {
        if w[1] < w[0] {
            falling = true;
        } else if w[1] > w[0] && falling {
            return false;
        }
    }
    true
}
