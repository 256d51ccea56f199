//! Exact sign of an integer polynomial on [0, 1] by de Casteljau subdivision at 1/2.
//!
//! Bernstein coefficients of one sign on a piece prove that sign there (convex-hull property);
//! the first and last coefficients are the exact values at the piece's dyadic end points. Pieces
//! with mixed signs are halved; halving keeps integers when every level is scaled by 2ᴺ.

use num_bigint::BigInt;
use num_traits::{ToPrimitive, Zero};

use crate::exact::{ScaledBernstein, sign};

/// Deepest subdivision level (pieces of width 2⁻⁹⁶) before a piece is reported undecided.
pub const MAX_SUBDIVISION_DEPTH: u32 = 96;
/// Most pieces examined before the remaining ones are reported undecided.
pub const MAX_PIECES: usize = 20_000;
/// Exact bisection of a proven sign change stops at this width (2⁻⁴⁰ ≈ 9.1e-13).
const LOCATE_LEVEL: u32 = 40;

/// A dyadic point m / 2ʲ of [0, 1].
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Dyadic {
    m: BigInt,
    j: u32,
}

impl Dyadic {
    fn new(m: BigInt, j: u32) -> Self {
        Self { m, j }
    }

    /// The point rounded to f64.
    pub(crate) fn to_f64(&self) -> f64 {
        let m = self.m.to_f64().unwrap_or(f64::NAN);
        m * 2f64.powi(-i32::try_from(self.j).unwrap_or(i32::MAX))
    }

    /// The numerator at level j ≥ self.j.
    fn at_level(&self, j: u32) -> BigInt {
        &self.m << (j - self.j)
    }
}

/// What the subdivision proved about the sign of f on [0, 1].
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum SignProfile {
    /// f ≡ 0.
    Zero,
    /// f ≥ 0 and not identically zero.
    NonNegative,
    /// f ≤ 0 and not identically zero.
    NonPositive,
    /// f(positive) > 0 and f(negative) < 0, so f changes sign between them.
    Changes {
        /// A point where f > 0.
        positive: Dyadic,
        /// A point where f < 0.
        negative: Dyadic,
    },
    /// No piece proved a sign change, but the piece [lo, hi] still had mixed signs at the cap.
    Undecided {
        /// Start of the first unresolved piece.
        lo: f64,
        /// End of the first unresolved piece.
        hi: f64,
    },
}

/// A piece [m/2ʲ, (m + 1)/2ʲ] with its Bernstein coefficients times a positive constant.
struct Piece {
    b: Vec<BigInt>,
    m: BigInt,
    j: u32,
}

impl Piece {
    /// The two halves [2m/2ʲ⁺¹, (2m + 1)/2ʲ⁺¹] and [(2m + 1)/2ʲ⁺¹, (2m + 2)/2ʲ⁺¹], right half
    /// first (pushed on a stack, the left half is taken next).
    fn halves(&self) -> [Self; 2] {
        let (left, right) = halve_coefficients(&self.b);
        let m2 = &self.m << 1;
        [
            Self {
                b: right,
                m: &m2 + 1,
                j: self.j + 1,
            },
            Self {
                b: left,
                m: m2,
                j: self.j + 1,
            },
        ]
    }
}

/// Divides all coefficients by their common power of two (keeps integers small).
fn strip_twos(b: &mut [BigInt]) {
    let tz = b.iter().filter_map(BigInt::trailing_zeros).min();
    if let Some(tz) = tz.filter(|&t| t > 0) {
        for x in b.iter_mut() {
            *x >>= tz;
        }
    }
}

/// de Casteljau at 1/2 in integers: level r sums give 2ʳ × the true values, rescaled by 2ᴺ⁻ʳ.
fn halve_coefficients(b: &[BigInt]) -> (Vec<BigInt>, Vec<BigInt>) {
    let n = b.len() - 1;
    let mut c = b.to_vec();
    let mut left = Vec::with_capacity(n + 1);
    let mut right = vec![BigInt::zero(); n + 1];
    for r in 0..=n {
        if r > 0 {
            for i in 0..=n - r {
                let next = c[i + 1].clone();
                c[i] += next;
            }
        }
        left.push(&c[0] << (n - r));
        right[n - r] = &c[n - r] << (n - r);
    }
    strip_twos(&mut left);
    strip_twos(&mut right);
    (left, right)
}

/// A point of the piece where f has the strict sign `want`, knowing f has that sign or is zero
/// on the piece and is not identically zero: an end point if its coefficient has the sign, else
/// one of 2ᵏ − 1 > N interior dyadic points (f has at most N zeros).
fn witness(f: &ScaledBernstein, p: &Piece, want: i8) -> Option<Dyadic> {
    let n = p.b.len() - 1;
    if sign(&p.b[0]) == want {
        return Some(Dyadic::new(p.m.clone(), p.j));
    }
    if sign(&p.b[n]) == want {
        return Some(Dyadic::new(&p.m + 1, p.j));
    }
    let k = usize::BITS - (n + 1).leading_zeros() + 1; // 2ᵏ > N + 1
    let base = &p.m << k;
    (1..(1u64 << k))
        .map(|i| Dyadic::new(&base + i, p.j + k))
        .find(|d| f.sign_at(&d.m, d.j) == want)
}

/// Decides the sign of f on [0, 1] exactly (see [`SignProfile`]).
pub(crate) fn sign_profile(f: &ScaledBernstein) -> SignProfile {
    if f.is_zero() {
        return SignProfile::Zero;
    }
    let mut b = f.bernstein_times_factorial();
    strip_twos(&mut b);
    let mut stack = vec![Piece {
        b,
        m: BigInt::zero(),
        j: 0,
    }];
    let (mut pos, mut neg): (Option<Dyadic>, Option<Dyadic>) = (None, None);
    let mut undecided: Option<(f64, f64)> = None;
    let mut pieces = 0usize;
    while let Some(p) = stack.pop() {
        pieces += 1;
        let has_pos = p.b.iter().any(|x| sign(x) > 0);
        let has_neg = p.b.iter().any(|x| sign(x) < 0);
        if has_pos && pos.is_none() {
            pos = witness_if_one_signed(f, &p, 1, has_neg);
        }
        if has_neg && neg.is_none() {
            neg = witness_if_one_signed(f, &p, -1, has_pos);
        }
        let one_signed_without_witness =
            (has_pos && !has_neg && pos.is_none()) || (has_neg && !has_pos && neg.is_none());
        if one_signed_without_witness {
            // Impossible for a non-zero f (at most N zeros); kept as an honest fallback.
            undecided.get_or_insert((
                Dyadic::new(p.m.clone(), p.j).to_f64(),
                Dyadic::new(&p.m + 1, p.j).to_f64(),
            ));
        }
        if let (Some(positive), Some(negative)) = (&pos, &neg) {
            return SignProfile::Changes {
                positive: positive.clone(),
                negative: negative.clone(),
            };
        }
        if has_pos && has_neg {
            if p.j >= MAX_SUBDIVISION_DEPTH || pieces >= MAX_PIECES {
                let lo = Dyadic::new(p.m.clone(), p.j).to_f64();
                let hi = Dyadic::new(&p.m + 1, p.j).to_f64();
                undecided.get_or_insert((lo, hi));
                continue;
            }
            stack.extend(p.halves());
        }
    }
    match (undecided, pos.is_some(), neg.is_some()) {
        (Some((lo, hi)), _, _) => SignProfile::Undecided { lo, hi },
        (None, true, false) => SignProfile::NonNegative,
        (None, false, true) => SignProfile::NonPositive,
        // Unreachable for a non-zero f; never claim a sign without proof.
        _ => SignProfile::Undecided { lo: 0.0, hi: 1.0 },
    }
}

/// On a one-signed piece, a witness of that sign; on a mixed piece, an end point with the
/// sign if there is one (exact values), else nothing yet.
fn witness_if_one_signed(f: &ScaledBernstein, p: &Piece, want: i8, mixed: bool) -> Option<Dyadic> {
    if !mixed {
        return witness(f, p, want);
    }
    let n = p.b.len() - 1;
    if sign(&p.b[0]) == want {
        Some(Dyadic::new(p.m.clone(), p.j))
    } else if sign(&p.b[n]) == want {
        Some(Dyadic::new(&p.m + 1, p.j))
    } else {
        None
    }
}

/// Narrows a proven sign change: returns (lo, hi), lo < hi, dyadic end points (level ≤ 48,
/// exact in f64), with f of opposite strict signs at the two exact end points, of width 2⁻⁴¹
/// when the f64 guess is confirmed ([`confirmed_guess`]), else by exact bisection of width at
/// most 2⁻³⁹ unless a midpoint is a zero of f (then the neighbouring dyadics are tried).
pub(crate) fn locate_sign_change(
    f: &ScaledBernstein,
    positive: &Dyadic,
    negative: &Dyadic,
) -> (f64, f64) {
    confirmed_guess(f, positive, negative).unwrap_or_else(|| bisect(f, positive, negative))
}

/// [`locate_sign_change`] by exact bisection only.
fn bisect(f: &ScaledBernstein, positive: &Dyadic, negative: &Dyadic) -> (f64, f64) {
    let mut j = positive.j.max(negative.j);
    let (mut a, mut b) = (positive.at_level(j), negative.at_level(j)); // f(a) > 0 > f(b)
    while j < LOCATE_LEVEL + 8 {
        let width = (&b - &a).magnitude().clone();
        if j >= LOCATE_LEVEL && width.bits() <= u64::from(j - LOCATE_LEVEL) + 1 {
            break;
        }
        a <<= 1;
        b <<= 1;
        j += 1;
        let mid: BigInt = (&a + &b) >> 1u32;
        let step = if a < b {
            BigInt::from(1)
        } else {
            BigInt::from(-1)
        };
        for c in [mid.clone(), &mid - &step, &mid + &step] {
            if c == a || c == b {
                continue;
            }
            match f.sign_at(&c, j) {
                1 => {
                    a = c;
                    break;
                }
                -1 => {
                    b = c;
                    break;
                }
                _ => {}
            }
        }
    }
    let (x, y) = (Dyadic::new(a, j).to_f64(), Dyadic::new(b, j).to_f64());
    (x.min(y), x.max(y))
}

/// Level of the dyadic points of a guessed bracket (three steps of 2⁻⁴² wide, under 2⁻⁴⁰).
const GUESS_LEVEL: u32 = 42;

/// The fast path of [`locate_sign_change`]: a root between the two points found by f64
/// bisection (de Casteljau evaluation of the rounded coefficients), then bracketed by the
/// dyadic points r ∓ 2⁻⁴¹ (level 42) whose signs are checked exactly; `None` when f64 cannot
/// follow the sign or a check fails (the exact bisection then decides).
fn confirmed_guess(
    f: &ScaledBernstein,
    positive: &Dyadic,
    negative: &Dyadic,
) -> Option<(f64, f64)> {
    let b = rounded_bernstein(f)?;
    let (mut lo, mut hi) = (positive.to_f64(), negative.to_f64()); // f(lo) > 0 > f(hi)
    let mut scratch = b.clone();
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        let v = de_casteljau(&b, mid, &mut scratch);
        if v > 0.0 {
            lo = mid;
        } else if v < 0.0 {
            hi = mid;
        } else {
            break;
        }
    }
    let scale = f64::from(1u32 << 21) * f64::from(1u32 << 21); // 2⁴²
    let r = (0.5 * (lo + hi) * scale).round();
    let (left, right) = (r - 1.0, r + 1.0);
    if left < 0.0 || right > scale {
        return None;
    }
    let (pos, neg) = if positive.to_f64() < negative.to_f64() {
        (left, right)
    } else {
        (right, left)
    };
    // Exact integers below 2⁵³, so the conversions are exact.
    let (pm, nm) = (BigInt::from(pos as u64), BigInt::from(neg as u64));
    (f.sign_at(&pm, GUESS_LEVEL) > 0 && f.sign_at(&nm, GUESS_LEVEL) < 0)
        .then_some((left / scale, right / scale))
}

/// The Bernstein coefficients of f rounded to f64 (after one common power-of-two scaling),
/// `None` when they do not fit.
fn rounded_bernstein(f: &ScaledBernstein) -> Option<Vec<f64>> {
    let a = f.coefficients();
    let n = a.len() - 1;
    let bits = a.iter().map(BigInt::bits).max()?;
    let shift = bits.saturating_sub(960);
    let mut c = 1.0f64; // C(n, k), rounded
    let mut out = Vec::with_capacity(n + 1);
    for (k, x) in a.iter().enumerate() {
        let v = (x >> shift).to_f64()? / c;
        out.push(v);
        c = c * (n - k) as f64 / (k + 1) as f64;
    }
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// The value Σ bₖ Bₖᴺ(t) by de Casteljau's algorithm (`scratch` of the same length).
fn de_casteljau(b: &[f64], t: f64, scratch: &mut [f64]) -> f64 {
    scratch.copy_from_slice(b);
    let n = b.len();
    for r in 1..n {
        for i in 0..n - r {
            scratch[i] = (1.0 - t) * scratch[i] + t * scratch[i + 1];
        }
    }
    scratch[0]
}

/// What the subdivision proved about strict positivity of f on [0, 1] (regularity checks).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Positivity {
    /// f > 0 on [0, 1].
    Positive,
    /// f ≤ 0 at this exact dyadic point.
    FailsAt(Dyadic),
    /// A piece [lo, hi] still had a coefficient ≤ 0 at the cap.
    Undecided {
        /// Start of the unresolved piece.
        lo: f64,
        /// End of the unresolved piece.
        hi: f64,
    },
}

/// Decides f > 0 on [0, 1]: all coefficients of every piece positive proves it; an end point
/// coefficient ≤ 0 is an exact value ≤ 0 there.
pub(crate) fn positivity(f: &ScaledBernstein) -> Positivity {
    let mut b = f.bernstein_times_factorial();
    strip_twos(&mut b);
    let mut stack = vec![Piece {
        b,
        m: BigInt::zero(),
        j: 0,
    }];
    let mut pieces = 0usize;
    while let Some(p) = stack.pop() {
        pieces += 1;
        let n = p.b.len() - 1;
        if sign(&p.b[0]) <= 0 {
            return Positivity::FailsAt(Dyadic::new(p.m, p.j));
        }
        if sign(&p.b[n]) <= 0 {
            return Positivity::FailsAt(Dyadic::new(p.m + 1, p.j));
        }
        if p.b.iter().all(|x| sign(x) > 0) {
            continue;
        }
        if p.j >= MAX_SUBDIVISION_DEPTH || pieces >= MAX_PIECES {
            return Positivity::Undecided {
                lo: Dyadic::new(p.m.clone(), p.j).to_f64(),
                hi: Dyadic::new(&p.m + 1, p.j).to_f64(),
            };
        }
        stack.extend(p.halves());
    }
    Positivity::Positive
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[i64]) -> ScaledBernstein {
        ScaledBernstein::new(v.iter().map(|&x| BigInt::from(x)).collect())
    }

    #[test]
    fn halving_matches_exact_values() {
        // (1 − 2t)² = [1, −2, 1] scaled... Bernstein [1, −1, 1]: values 1, 0, 1 at 0, 1/2, 1.
        let f = ScaledBernstein::from_bernstein(vec![1.into(), (-1).into(), 1.into()]);
        let (l, r) = halve_coefficients(&f.bernstein_times_factorial());
        assert_eq!(sign(&l[0]), 1);
        assert_eq!(sign(&l[2]), 0);
        assert_eq!(sign(&r[0]), 0);
        // A double root at 1/2: non-negative, not strictly positive.
        assert_eq!(sign_profile(&f), SignProfile::NonNegative);
        assert_eq!(
            positivity(&f),
            Positivity::FailsAt(Dyadic::new(1.into(), 1))
        );
    }

    #[test]
    fn profiles_of_simple_polynomials() {
        assert_eq!(sign_profile(&poly(&[0, 0, 0])), SignProfile::Zero);
        assert_eq!(sign_profile(&poly(&[3, -1, 3])), SignProfile::NonNegative); // 3 − 7t + 7t²
        assert_eq!(positivity(&poly(&[3, -1, 3])), Positivity::Positive);
        assert_eq!(sign_profile(&poly(&[-1, 0, -2])), SignProfile::NonPositive);
        // (1 − 3t) changes sign at 1/3, not a dyadic point.
        let f = poly(&[1, -2]);
        match sign_profile(&f) {
            SignProfile::Changes { positive, negative } => {
                let (lo, hi) = locate_sign_change(&f, &positive, &negative);
                assert!(
                    lo < 1.0 / 3.0 && 1.0 / 3.0 < hi && hi - lo < 1e-12,
                    "{lo} {hi}"
                );
            }
            p => panic!("{p:?}"),
        }
        // 1 + t(1−t)·(−8) dips below zero around 1/2 without sign change at the ends.
        let g = poly(&[1, -6, 1]);
        assert!(matches!(sign_profile(&g), SignProfile::Changes { .. }));
    }

    /// Exact signs (at the dyadic end points, level ≤ 48) of a bracket: opposite and strict,
    /// and the width at most 2⁻³⁹ (the exact bisection stops between 2⁻⁴¹ and 2⁻³⁹).
    fn opposite_exact_signs(f: &ScaledBernstein, (lo, hi): (f64, f64)) -> bool {
        let at = |x: f64| f.sign_at(&BigInt::from((x * 2f64.powi(48)) as u64), 48);
        hi - lo <= 2f64.powi(-39) && at(lo) * at(hi) == -1
    }

    #[test]
    fn guessed_and_bisected_brackets_are_both_proven() {
        // (1 − 3t)(2 − 7t)(5 + t²)-like products: roots 1/3 and 2/7, not dyadic.
        let lin = |a: i64, b: i64| poly(&[a, a - b]); // a(1 − t) + (a − b)t = a − bt
        let f = lin(1, 3).mul(&lin(2, 7)).mul(&poly(&[5, 5, 6]));
        for (p, n) in [
            (Dyadic::new(0.into(), 0), Dyadic::new(5.into(), 4)),
            (Dyadic::new(1.into(), 0), Dyadic::new(5.into(), 4)),
        ] {
            let fast = confirmed_guess(&f, &p, &n).unwrap();
            let slow = bisect(&f, &p, &n);
            assert!(opposite_exact_signs(&f, fast), "{fast:?}");
            assert!(opposite_exact_signs(&f, slow), "{slow:?}");
            let root = if p.j == 0 && p.m == BigInt::from(0) {
                2.0 / 7.0
            } else {
                1.0 / 3.0
            };
            for (lo, hi) in [fast, slow] {
                assert!(lo < root && root < hi, "{lo} {hi}");
            }
        }
        // Coefficients beyond f64 (2¹²⁰⁰): the guess declines, bisection decides.
        let big = BigInt::from(1) << 1200u32;
        let g = ScaledBernstein::new(vec![big.clone(), -big * 2]);
        let (p, n) = (Dyadic::new(0.into(), 0), Dyadic::new(1.into(), 0));
        assert!(opposite_exact_signs(&g, locate_sign_change(&g, &p, &n)));
    }

    #[test]
    fn a_root_too_close_to_an_end_is_undecided_not_guessed() {
        // f = (t − ε)² with ε = 2⁻²⁰⁰: non-negative, but the pieces near 0 stay mixed
        // beyond the depth cap; the profile must not claim a sign.
        let e = BigInt::from(1) << 200u32;
        // Power form (t − 1/e)² · e² = e²t² − 2et + 1 → scaled basis (1−t)², t(1−t), t².
        let f = ScaledBernstein::new(vec![
            BigInt::from(1),
            BigInt::from(2) - 2 * &e,
            &e * &e - 2 * &e + 1,
        ]);
        assert!(matches!(sign_profile(&f), SignProfile::Undecided { .. }));
        assert!(matches!(positivity(&f), Positivity::Undecided { .. }));
    }
}
