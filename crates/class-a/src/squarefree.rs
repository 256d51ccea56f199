//! The odd part of a square-free decomposition, for numerators whose sign subdivision cannot
//! settle (a double root).
//!
//! N = c · Π fᵢⁱ with coprime square-free fᵢ (Yun's algorithm on exact integer polynomials, gcds
//! by the primitive polynomial remainder sequence). N changes sign exactly at the roots of the
//! odd part O = Π_{i odd} fᵢ, whose roots are simple, so exact subdivision of O ends: O of one
//! sign makes N of one sign (N ≥ 0 or ≤ 0, the sign read off at a dyadic point where N ≠ 0), and
//! a sign change of O is a sign change of N, confirmed by exact values of N.

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::exact::{ScaledBernstein, binomial_row};

/// A polynomial Σ cⱼ tʲ with integer coefficients, lowest degree first, no trailing zeros
/// (the zero polynomial is empty).
type Power = Vec<BigInt>;

fn trim(mut p: Power) -> Power {
    while p.last().is_some_and(Zero::is_zero) {
        p.pop();
    }
    p
}

/// Σ aₖ tᵏ(1 − t)ᴺ⁻ᵏ in the power basis: (1 − t)ᵐ = Σ C(m, j)(−t)ʲ.
pub(crate) fn to_power(f: &ScaledBernstein) -> Power {
    let a = f.coefficients();
    let n = f.degree();
    let mut c = vec![BigInt::zero(); n + 1];
    for (k, ak) in a.iter().enumerate() {
        if ak.is_zero() {
            continue;
        }
        for (j, b) in binomial_row(n - k).into_iter().enumerate() {
            let term = ak * b;
            if j % 2 == 0 {
                c[k + j] += term;
            } else {
                c[k + j] -= term;
            }
        }
    }
    trim(c)
}

/// The power form as a scaled Bernstein polynomial of its own degree: tʲ = tʲ((1 − t) + t)ᵐ⁻ʲ.
pub(crate) fn from_power(c: &[BigInt]) -> ScaledBernstein {
    let n = c.len().saturating_sub(1);
    let mut a = vec![BigInt::zero(); n + 1];
    for (j, cj) in c.iter().enumerate() {
        if cj.is_zero() {
            continue;
        }
        for (i, b) in binomial_row(n - j).into_iter().enumerate() {
            a[j + i] += cj * b;
        }
    }
    ScaledBernstein::new(a)
}

fn derivative(p: &[BigInt]) -> Power {
    trim(
        p.iter()
            .enumerate()
            .skip(1)
            .map(|(j, c)| c * BigInt::from(j))
            .collect(),
    )
}

/// The non-negative gcd of two integers (Euclid).
fn gcd_int(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut a, mut b) = (a.abs(), b.abs());
    while !b.is_zero() {
        let r = &a % &b;
        a = b;
        b = r;
    }
    a
}

/// p divided by the gcd of its coefficients, leading coefficient positive.
fn primitive(p: Power) -> Power {
    let p = trim(p);
    let Some(lead) = p.last() else {
        return p;
    };
    let content = p.iter().fold(BigInt::zero(), |g, c| gcd_int(&g, c));
    let content = if lead.is_negative() {
        -content
    } else {
        content
    };
    p.into_iter().map(|c| c / &content).collect()
}

/// The pseudo-remainder of a by b (b ≠ 0): lc(b)^(deg a − deg b + 1) a mod b.
fn pseudo_remainder(a: &[BigInt], b: &[BigInt]) -> Power {
    let mut r = a.to_vec();
    let db = b.len() - 1;
    let lb = &b[db];
    while r.len() > db && !r.is_empty() {
        let dr = r.len() - 1;
        let lr = r[dr].clone();
        for x in r.iter_mut() {
            *x *= lb;
        }
        for (i, bi) in b.iter().enumerate() {
            r[dr - db + i] -= &lr * bi;
        }
        r = trim(r);
    }
    r
}

/// The primitive gcd (leading coefficient positive); gcd(p, 0) = primitive(p).
fn gcd(a: &[BigInt], b: &[BigInt]) -> Power {
    let (mut a, mut b) = (primitive(a.to_vec()), primitive(b.to_vec()));
    while !b.is_empty() {
        let r = primitive(pseudo_remainder(&a, &b));
        a = b;
        b = r;
    }
    a
}

/// a / b for a primitive b dividing a (the quotient is then an integer polynomial), or
/// `None` if the division is not exact.
fn divide(a: &[BigInt], b: &[BigInt]) -> Option<Power> {
    let mut r = a.to_vec();
    let db = b.len().checked_sub(1)?;
    if r.len() < b.len() {
        return r.is_empty().then(Vec::new);
    }
    let mut q = vec![BigInt::zero(); r.len() - db];
    for k in (0..q.len()).rev() {
        let qk = &r[k + db] / &b[db];
        if &qk * &b[db] != r[k + db] {
            return None;
        }
        for (i, bi) in b.iter().enumerate() {
            r[k + i] -= &qk * bi;
        }
        q[k] = qk;
    }
    trim(r).is_empty().then(|| trim(q))
}

fn sub(a: &[BigInt], b: &[BigInt]) -> Power {
    let n = a.len().max(b.len());
    let zero = BigInt::zero();
    trim(
        (0..n)
            .map(|i| a.get(i).unwrap_or(&zero) - b.get(i).unwrap_or(&zero))
            .collect(),
    )
}

fn mul(a: &[BigInt], b: &[BigInt]) -> Power {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            c[i + j] += x * y;
        }
    }
    c
}

/// The odd part O = Π_{i odd} fᵢ of N = c Π fᵢⁱ (Yun's algorithm), as a scaled Bernstein
/// polynomial; `None` for the zero polynomial or if an exact division unexpectedly fails.
pub(crate) fn odd_part(f: &ScaledBernstein) -> Option<ScaledBernstein> {
    let p = primitive(to_power(f));
    if p.is_empty() {
        return None;
    }
    let dp = derivative(&p);
    let a0 = gcd(&p, &dp);
    let mut b = divide(&p, &a0)?;
    let c = divide(&dp, &a0)?;
    let mut d = sub(&c, &derivative(&b));
    let mut odd: Power = vec![BigInt::one()];
    let mut i = 1usize;
    while b.len() > 1 && i <= p.len() {
        let a = gcd(&b, &d);
        let next_b = divide(&b, &a)?;
        let c = divide(&d, &a)?;
        d = sub(&c, &derivative(&next_b));
        if i % 2 == 1 {
            odd = mul(&odd, &a);
        }
        b = next_b;
        i += 1;
    }
    Some(from_power(&odd))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(v: &[i64]) -> Power {
        trim(v.iter().map(|&x| BigInt::from(x)).collect())
    }

    #[test]
    fn conversions_round_trip_and_yun_finds_the_odd_part() {
        // (3t − 1)²(5t − 2)³(t + 2): odd part ∝ (5t − 2)(t + 2).
        let lin1 = p(&[-1, 3]);
        let lin2 = p(&[-2, 5]);
        let lin3 = p(&[2, 1]);
        let f = mul(
            &mul(&mul(&lin1, &lin1), &mul(&mul(&lin2, &lin2), &lin2)),
            &lin3,
        );
        let sb = from_power(&f);
        assert_eq!(to_power(&sb), f);
        let odd = odd_part(&sb).unwrap();
        assert_eq!(primitive(to_power(&odd)), mul(&lin2, &lin3));
        // Square-free input: its own odd part.
        let g = mul(&lin1, &lin2);
        assert_eq!(
            primitive(to_power(&odd_part(&from_power(&g)).unwrap())),
            primitive(g.clone())
        );
        // A perfect square: constant odd part.
        let sq = mul(&g, &g);
        assert_eq!(
            primitive(to_power(&odd_part(&from_power(&sq)).unwrap())),
            p(&[1])
        );
        assert_eq!(divide(&p(&[1, 0, 1]), &lin3), None);
    }
}
