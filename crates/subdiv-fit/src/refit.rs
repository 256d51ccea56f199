//! Least-squares refit of a window of control points, the others fixed (the project's addition,
//! for [`Reduction::Refit`](crate::Reduction::Refit)).
//!
//! A data point of segment `s` touches the control points `s − 1..=s + 2` (a sharp end replaces
//! its outer neighbour by the phantom point `2 p_i − p_{i±1}`), so freeing a few control points
//! changes only the segments they shape: the normal equations of those segments' data in the free
//! points are a band of half-width 3 ([`CyclicBand`]), solved in O(window) time, and every other
//! segment stays bit for bit what it was. Each iteration takes the foot-point parameters of the
//! data on the current curve (Newton on eq. (6), each sample starting from a step along the tangent
//! from the previous sample's foot point) and solves for the
//! free points (Gauss–Newton on the foot-point distances with the parameters fixed per step).

use bez_core::Vector;

use crate::SubdivCurve;
use crate::banded::CyclicBand;
use crate::bspline::bspline_basis;
use crate::corner_angles::Ray;
use crate::distance::PowerCubic;
use crate::fit::segment_controls_weights;
use crate::insertion::segment_range;
use crate::on_rays::{RayColumn, solve_on_rays};

/// Data points per segment that the refit uses at most (evenly strided, both ends included): the
/// least-squares control points of a few dozen points of a segment are those of all of them to
/// well within the tolerance, and the result is measured on all data anyway.
pub(crate) const SAMPLES_PER_SEGMENT: usize = 16;

/// Data points per segment of the iterations before the last, which only give it its foot points:
/// the last iteration sets the result (on the glyph set at 10⁻³ em 1,794 control points instead of
/// 1,795 with 16 in both, 7 % fewer instructions in all). With a cone (one iteration more) the
/// first takes half as many: its solve only places the cone's rays (with the curved kind and the
/// corner bound 1,784 control points instead of 1,788, 3.6 % fewer instructions).
pub(crate) const FIRST_SAMPLES: usize = 8;

/// The rays for the corner sides of a refitted curve that leave their share of the corner bound
/// ([`cone_rays`](crate::corner_angles::cone_rays)).
pub(crate) type Cone<'a, const D: usize> = &'a dyn Fn(&SubdivCurve<D>) -> Vec<Ray<D>>;

/// Iterations of foot points and solve per refit.
pub(crate) const ITERATIONS: usize = 2;

/// A test of a trial's curve after the first of several iterations: `true` gives the trial up
/// (the refit returns `None`) before the later iterations are computed.
pub(crate) type Abandon<'a, const D: usize> = &'a dyn Fn(&SubdivCurve<D>) -> bool;

/// The distance, in tolerances, beyond which a subsampled data point of a trial's first solve
/// gives the trial up ([`Abandon`]): the later iterations move the foot points and the curve by
/// much less than that. On the glyph set of the standing comparison at 10⁻³ em no trial that
/// would have been accepted was given up at 1.5 (every `Refit` row the same control points,
/// 0.68–0.8 of the time); at 1.2 the first ones were (1,792 control points instead of 1,786 with
/// curved corners and the bound), at 1.1 more (1,807).
pub(crate) const ABANDON_AT: f64 = 1.5;

/// The segments of `curve` that a control point in `free` (vertex indices) shapes, increasing.
pub(crate) fn shaped_segments<const D: usize>(
    curve: &SubdivCurve<D>,
    free: &[usize],
) -> Vec<usize> {
    let k = curve.points().len();
    let sharp = curve.kinds();
    let mut is_free = vec![false; k];
    for &v in free {
        is_free[v] = true;
    }
    (0..curve.segment_count())
        .filter(|&s| {
            let e = (s + 1) % k;
            is_free[s]
                || is_free[e]
                || (!sharp[s].is_sharp() && is_free[(s + k - 1) % k])
                || (!sharp[e].is_sharp() && is_free[(e + 1) % k])
        })
        .collect()
}

/// `guess` with its control points `free` (regular vertices, in polygon order, consecutive ones at
/// most 3 apart or wrapping round a closed polygon) refitted by least squares to the data of the
/// segments they shape (`iterations` times), the other control points fixed. With `cone`, each
/// solve without rays is followed by `cone`'s rays for its result, if any: the same normal
/// equations are then solved with them, and the iterations after it keep them. `None` when the
/// system is singular (a free point without data) or the result not finite. The free control
/// points of `rays` are constrained to them (one unknown each along its ray, solved with the
/// others: [`solve_on_rays`]); `None` also when a ray's vertex is not free, and when `abandon`
/// gives the trial up after the first of several iterations.
#[expect(
    clippy::too_many_arguments,
    reason = "the data, the trial with its free points and rays, and how it iterates"
)]
pub(crate) fn refit<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    guess: SubdivCurve<D>,
    free: &[usize],
    rays: &[Ray<D>],
    iterations: usize,
    cone: Option<Cone<'_, D>>,
    abandon: Option<Abandon<'_, D>>,
) -> Option<SubdivCurve<D>> {
    let n = data.len();
    let k = guess.points().len();
    let mut column = vec![None; k];
    for (col, &v) in free.iter().enumerate() {
        if guess.is_sharp(v) {
            return None;
        }
        column[v] = Some(col);
    }
    let u = free.len();
    if u == 0 {
        return Some(guess);
    }
    let segments = shaped_segments(&guess, free);
    let closed = guess.is_closed();
    let mut curve = guess;
    let mut active = rays.to_vec();
    for iteration in 0..iterations {
        let sharp = curve.kinds();
        let mut ata = CyclicBand::zeros(u);
        let mut atb = vec![[0.0; D]; u];
        for &s in &segments {
            let (a, b) = segment_range(fitting, s, n);
            let ctrl = curve.segment_controls(s).ok()?;
            let cubic = PowerCubic::new(&ctrl);
            let last = b - a;
            let samples = if iteration + 1 == iterations {
                SAMPLES_PER_SEGMENT
            } else if iteration == 0 && cone.is_some() {
                FIRST_SAMPLES / 2
            } else {
                FIRST_SAMPLES
            };
            let stride = last.div_ceil(samples).max(1);
            // The segment's Gram matrix G = Σ B(t) B(t)ᵀ of the B-spline basis (its upper
            // triangle) and the moments Σ B(t) vᵀ, then mapped once onto the vertices its four
            // control points are made of.
            let mut gram = [[0.0; 4]; 4];
            let mut moment = [[0.0; D]; 4];
            // The samples at offsets 0, stride, 2 stride, …, and the last. Newton's start: 0 for
            // the first (the segment's fitting point), then a step along the tangent from the
            // previous sample's foot point (`PowerCubic::start_after`; the data follow the
            // segment).
            let (mut off, mut t, mut previous) = (0, 0.0, data[a]);
            loop {
                // a < n and b < 2n (`segment_range`).
                let i = a + off;
                let v = data[if i < n { i } else { i - n }];
                let t0 = if off == 0 {
                    0.0
                } else {
                    cubic.start_after(t, &previous, &v)
                };
                (t, _) = cubic.foot(&v, t0);
                previous = v;
                let w = bspline_basis(t);
                let v = <[f64; D]>::from(v);
                for r in 0..4 {
                    for c in r..4 {
                        gram[r][c] += w[r] * w[c];
                    }
                    for d in 0..D {
                        moment[r][d] += w[r] * v[d];
                    }
                }
                if off == last {
                    break;
                }
                off = (off + stride).min(last);
            }
            for (r, c) in [(1, 0), (2, 0), (2, 1), (3, 0), (3, 1), (3, 2)] {
                gram[r][c] = gram[c][r];
            }
            // Control point r = Σ coefficient · vertex (phantom points at sharp ends): its free
            // part by column, its fixed part as a point.
            // At most three vertices each (module `curved_corner`).
            let mut parts = [[(0, 0.0); 3]; 4];
            let mut counts = [0; 4];
            let mut fixed = [[0.0; D]; 4];
            for (r, control) in segment_controls_weights(sharp, closed, s)
                .iter()
                .enumerate()
            {
                for &(idx, coef) in control {
                    if coef == 0.0 {
                        continue;
                    }
                    match column[idx] {
                        Some(col) => {
                            parts[r][counts[r]] = (col, coef);
                            counts[r] += 1;
                        }
                        None => {
                            let p = <[f64; D]>::from(curve.points()[idx]);
                            for d in 0..D {
                                fixed[r][d] += coef * p[d];
                            }
                        }
                    }
                }
            }
            for r in 0..4 {
                // The right-hand side of control r: its moment less what the fixed parts give.
                let mut rhs = moment[r];
                for c in 0..4 {
                    for d in 0..D {
                        rhs[d] -= gram[r][c] * fixed[c][d];
                    }
                }
                for &(c1, w1) in &parts[r][..counts[r]] {
                    for d in 0..D {
                        atb[c1][d] += w1 * rhs[d];
                    }
                    for c in 0..4 {
                        for &(c2, w2) in &parts[c][..counts[c]] {
                            if c1 >= c2 && !ata.add_lower(c1, c2, w1 * gram[r][c] * w2) {
                                return None;
                            }
                        }
                    }
                }
            }
        }
        // One factorization for the solves of this iteration (without rays, with the cone's).
        let factor = ata.factor()?;
        let solve = |rays: &[Ray<D>]| -> Option<SubdivCurve<D>> {
            // A partner that is not free is part of the anchor.
            let on_rays: Vec<RayColumn<D>> = rays
                .iter()
                .map(|r| {
                    let (partner, anchor) = match r.partner {
                        Some((w, k)) => match column[w] {
                            Some(col) => (Some((col, k)), r.anchor),
                            None => (None, r.anchor + curve.points()[w] * k),
                        },
                        None => (None, r.anchor),
                    };
                    Some(RayColumn {
                        column: column[r.vertex]?,
                        partner,
                        anchor: anchor.into(),
                        direction: r.direction.into(),
                    })
                })
                .collect::<Option<_>>()?;
            let (sol, _) = solve_on_rays(&factor, &atb, &on_rays)?;
            let mut points = curve.points().to_vec();
            for (&v, p) in free.iter().zip(&sol) {
                points[v] = Vector::<D>::from(*p);
            }
            SubdivCurve::new(points, sharp.to_vec(), curve.closure()).ok()
        };
        let mut next = solve(&active)?;
        if iteration == 0
            && iterations > 1
            && let Some(abandon) = abandon
            && abandon(&next)
        {
            return None;
        }
        if active.is_empty()
            && let Some(cone) = cone
        {
            // The cone's rays from this solve, on the same normal equations, and kept for the
            // iterations after it.
            let late = cone(&next);
            if !late.is_empty() {
                next = solve(&late)?;
                active = late;
            }
        }
        curve = next;
    }
    Some(curve)
}

#[cfg(test)]
mod tests {
    use super::{ITERATIONS, refit, shaped_segments};
    use crate::{Closure, SubdivCurve, Vector2};

    /// An open polygon with a sharp vertex in the middle, its limit curve sampled at 40 points
    /// per segment (the fitting points at the segment ends).
    fn truth() -> (SubdivCurve<2>, Vec<Vector2>, Vec<(usize, bool)>) {
        let points: Vec<Vector2> = [
            (0.0, 0.0),
            (1.0, 0.8),
            (2.0, 1.1),
            (3.0, 0.2),
            (4.0, -0.6),
            (5.0, 0.3),
            (6.0, 1.4),
            (7.0, 0.9),
            (8.0, 0.0),
        ]
        .iter()
        .map(|&(x, y)| Vector2::new(x, y))
        .collect();
        let curve = SubdivCurve::with_sharp(points, &[0, 4, 8], Closure::Open).unwrap();
        let per = 40;
        let mut data = Vec::new();
        for s in 0..curve.segment_count() {
            for m in 0..per {
                data.push(curve.eval_segment(s, m as f64 / per as f64).unwrap());
            }
        }
        data.push(*curve.points().last().unwrap());
        let fitting = (0..curve.points().len())
            .map(|j| (j * per, curve.is_sharp(j)))
            .collect();
        (curve, data, fitting)
    }

    /// Largest distance from the data to the curve (each point to its own segment, by Newton from
    /// many starts).
    fn max_distance(curve: &SubdivCurve<2>, data: &[Vector2], fitting: &[(usize, bool)]) -> f64 {
        let mut worst = 0.0_f64;
        for s in 0..curve.segment_count() {
            let cubic = crate::distance::PowerCubic::new(&curve.segment_controls(s).unwrap());
            for v in &data[fitting[s].0..=fitting[s + 1].0] {
                let d = (0..=8)
                    .map(|m| cubic.foot(v, m as f64 / 8.0).1)
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(d);
            }
        }
        worst
    }

    /// Data on a subdivision curve: the true control points are a fixed point of the refit (the
    /// normal equations, phantom points at the sharp vertex included, are those of the curve);
    /// perturbed free control points (one next to the sharp vertex, where the phantom point
    /// enters) are pulled back (the largest distance to the data shrinks; by about 30 % here: the
    /// foot-point iteration converges linearly, slowly along the tangent), and the segments they
    /// do not shape are left bit for bit.
    /// The refit of `free` without rays, cone or give-up, in [`ITERATIONS`] iterations.
    fn plain(
        data: &[Vector2],
        fitting: &[(usize, bool)],
        guess: SubdivCurve<2>,
        free: &[usize],
    ) -> Option<SubdivCurve<2>> {
        refit(data, fitting, guess, free, &[], ITERATIONS, None, None)
    }

    #[test]
    fn refit_recovers_the_control_points_of_exact_data() {
        let (curve, data, fitting) = truth();
        let free = [2, 3, 5];
        let same = plain(&data, &fitting, curve.clone(), &free).unwrap();
        for v in 0..curve.points().len() {
            assert!((same.points()[v] - curve.points()[v]).norm() < 1e-9, "{v}");
        }
        let mut points = curve.points().to_vec();
        for (m, &v) in free.iter().enumerate() {
            points[v] += Vector2::new(0.01 * (m as f64 + 1.0), -0.008);
        }
        let guess = SubdivCurve::new(points, curve.kinds().to_vec(), Closure::Open).unwrap();
        let shaped = shaped_segments(&guess, &free);
        assert_eq!(shaped, [0, 1, 2, 3, 4, 5, 6]);
        let fitted = plain(&data, &fitting, guess.clone(), &free).unwrap();
        let (before, after) = (
            max_distance(&guess, &data, &fitting),
            max_distance(&fitted, &data, &fitting),
        );
        assert!(after < 0.75 * before, "{before} -> {after}");
        for v in (0..curve.points().len()).filter(|v| !free.contains(v)) {
            assert_eq!(fitted.points()[v], guess.points()[v]);
        }
        assert_eq!(
            fitted.segment_controls(7).unwrap(),
            guess.segment_controls(7).unwrap()
        );
    }

    /// A sharp vertex cannot be freed, and no free point is a no-op.
    #[test]
    fn abandon_gives_up_after_the_first_of_several_iterations() {
        let (curve, data, fitting) = truth();
        let free = [2, 3, 5];
        let mut points = curve.points().to_vec();
        points[3] += Vector2::new(0.05, -0.04);
        let guess = SubdivCurve::new(points, curve.kinds().to_vec(), Closure::Open).unwrap();
        // The first solve is asked about once, with the curve it found; its answer decides.
        let asked = std::cell::Cell::new(0);
        let first = std::cell::RefCell::new(None);
        let give_up = |c: &SubdivCurve<2>| {
            asked.set(asked.get() + 1);
            *first.borrow_mut() = Some(c.clone());
            true
        };
        let run = |iterations, abandon: Option<super::Abandon<'_, 2>>| {
            refit(
                &data,
                &fitting,
                guess.clone(),
                &free,
                &[],
                iterations,
                None,
                abandon,
            )
        };
        assert!(run(ITERATIONS, Some(&give_up)).is_none());
        assert_eq!(asked.get(), 1);
        // The curve it saw is the first solve's (on fewer samples than a refit of one
        // iteration takes), already nearer the data than the guess.
        let seen = first.borrow().clone().unwrap();
        let (before, after) = (
            max_distance(&guess, &data, &fitting),
            max_distance(&seen, &data, &fitting),
        );
        assert!(after < before, "{before} -> {after}");
        assert!(free.iter().any(|&v| seen.points()[v] != guess.points()[v]));
        // Kept, the trial goes on as without the test; with one iteration it is never asked.
        assert_eq!(run(ITERATIONS, Some(&|_| false)), run(ITERATIONS, None));
        assert!(run(1, Some(&give_up)).is_some());
        assert_eq!(asked.get(), 1);
    }

    #[test]
    fn refit_rejects_sharp_points_and_keeps_the_guess_without_free_points() {
        let (curve, data, fitting) = truth();
        assert!(plain(&data, &fitting, curve.clone(), &[4]).is_none());
        assert_eq!(plain(&data, &fitting, curve.clone(), &[]).unwrap(), curve);
    }
}
