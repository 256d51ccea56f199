//! Per-segment errors of a round (Sec. 5, eqs. 5–6, and the two-sided measure).

use std::borrow::Cow;

use bez_core::Vector;

use crate::SubdivCurve;
use crate::bspline::bspline_basis;
use crate::curve::combine;
use crate::distance::{PowerCubic, curve_to_polyline};
use crate::fit::{ErrorMeasure, FitOptions, Reduction};
use crate::insertion::{Verdict, segment_range};

/// Chord-length parameters of data a..=b (indices mod n), the paper's Newton start (Sec. 5).
pub(crate) fn chord_params<const D: usize>(data: &[Vector<D>], a: usize, b: usize) -> Vec<f64> {
    polyline_params(&segment_polyline(data, a, b))
}

/// Data a..=b (indices mod n): borrowed unless the range wraps round.
pub(crate) fn segment_polyline<const D: usize>(
    data: &[Vector<D>],
    a: usize,
    b: usize,
) -> Cow<'_, [Vector<D>]> {
    let n = data.len();
    if b < n {
        Cow::Borrowed(&data[a..=b])
    } else {
        Cow::Owned((a..=b).map(|i| data[i % n]).collect())
    }
}

/// Chord-length parameters of the points of a polyline, from 0 to 1.
fn polyline_params<const D: usize>(poly: &[Vector<D>]) -> Vec<f64> {
    let mut acc = Vec::with_capacity(poly.len());
    let mut s = 0.0;
    acc.push(0.0);
    for w in poly.windows(2) {
        s += (w[1] - w[0]).norm();
        acc.push(s);
    }
    if s > 0.0 {
        for x in &mut acc {
            *x = (*x / s).clamp(0.0, 1.0);
        }
    }
    acc
}

/// The errors of a whole curve.
pub(crate) struct Assessment {
    pub(crate) max_d2c: f64,
    pub(crate) rms_d2c: f64,
    pub(crate) max_c2d: f64,
    pub(crate) verdicts: Vec<Verdict>,
    /// Per segment, the error the loop drives below the tolerance (the larger of the two
    /// measures with [`ErrorMeasure::TwoSided`]).
    pub(crate) driven: Vec<f64>,
}

/// The errors of one segment.
#[derive(Clone)]
pub(crate) struct SegmentErrors {
    pub(crate) d2c: f64,
    sum2: f64,
    count: usize,
    pub(crate) c2d: f64,
    pub(crate) verdict: Verdict,
}

impl SegmentErrors {
    /// The error the loop drives below the tolerance.
    pub(crate) fn driven(&self, measure: ErrorMeasure) -> f64 {
        match measure {
            ErrorMeasure::DataToCurve => self.d2c,
            ErrorMeasure::TwoSided => self.d2c.max(self.c2d),
        }
    }
}

/// Errors of segment `j`: each data point of the segment against it by Newton on eq. (6) from
/// its chord-length parameter (with [`Reduction::Refit`] from the previous point's foot point,
/// which needs fewer steps; any start gives the distance to a point of the segment, never below
/// the distance to the segment), and dense curve samples against the segment's data polyline.
///
/// The measurement stops as soon as the driven error exceeds `cap` (the errors are then lower
/// bounds, enough to reject the segment); with `cap` = ∞ every error is exact.
pub(crate) fn assess_segment<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
    j: usize,
    cap: f64,
) -> SegmentErrors {
    let n = data.len();
    let tol = options.tolerance;
    let segs = curve.segment_count();
    let (a, b) = segment_range(fitting, j, n);
    let Ok(ctrl) = curve.segment_controls(j) else {
        return SegmentErrors {
            d2c: 0.0,
            sum2: 0.0,
            count: 0,
            c2d: 0.0,
            verdict: Verdict {
                fails: false,
                worst_point: None,
            },
        };
    };
    let poly = segment_polyline(data, a, b);
    // Newton's start: the paper's chord-length parameter, or with `Reduction::Refit` 0 for the
    // segment's first data point (its fitting point) and then a step along the tangent from the
    // previous point's foot point (`PowerCubic::start_after`).
    let chord = (options.reduction != Reduction::Refit).then(|| polyline_params(&poly));
    let cubic = PowerCubic::new(&ctrl);
    let (mut seg_max, mut seg_arg, mut sum2, mut count) = (0.0_f64, None, 0.0, 0);
    let mut t = 0.0;
    for (off, v) in poly.iter().enumerate() {
        // The segment's end data points are counted once, by the segment that starts there
        // (for open data the last point also by the last segment).
        let last_of_open = !closed && j + 1 == segs && off + 1 == poly.len();
        if off + 1 == poly.len() && !last_of_open {
            continue;
        }
        let t0 = match &chord {
            Some(chord) => chord[off],
            None if off == 0 => 0.0,
            None => cubic.start_after(t, &poly[off - 1], v),
        };
        let d;
        (t, d) = cubic.foot(v, t0);
        sum2 += d * d;
        count += 1;
        if d > seg_max {
            seg_max = d;
            if off > 0 && a + off < b {
                seg_arg = Some((a + off) % n);
            }
            if seg_max > cap {
                break;
            }
        }
    }
    let mut verdict = Verdict {
        fails: seg_max > tol,
        worst_point: seg_arg.filter(|_| seg_max > tol),
    };
    let mut c2d = 0.0_f64;
    let needed = match options.measure {
        ErrorMeasure::TwoSided => seg_max <= cap,
        // Reported only, never driven: not needed when the measurement may stop early.
        ErrorMeasure::DataToCurve => !verdict.fails && cap == f64::INFINITY,
    };
    if needed {
        let worst_u;
        (c2d, worst_u) = curve_to_polyline(&ctrl, &poly, options.samples_per_segment, cap);
        if options.measure == ErrorMeasure::TwoSided && !verdict.fails && c2d > tol {
            let p = combine(&ctrl, bspline_basis(worst_u));
            verdict = Verdict {
                fails: true,
                worst_point: (a + 1..b)
                    .map(|i| (i % n, (data[i % n] - p).norm()))
                    .min_by(|x, y| x.1.total_cmp(&y.1))
                    .map(|x| x.0),
            };
        }
    }
    SegmentErrors {
        d2c: seg_max,
        sum2,
        count,
        c2d,
        verdict,
    }
}

/// Data points between two of [`subsample_exceeds`]'s samples.
pub(crate) const COARSE_STRIDE: usize = 8;

/// Whether one of every [`COARSE_STRIDE`]-th data point of segment `j` (from its first, the end
/// point left to the next segment) is farther than `tol` from the segment (Newton on eq. (6), each
/// from a step along the tangent after the previous one, as [`assess_segment`] with
/// [`Reduction::Refit`]): a first look at a trial before it is measured in full, which rejects
/// most failing trials at an eighth of the cost. Distances of points of the segment, as those of
/// [`assess_segment`], so it rejects what the full measurement would reject from the same points.
pub(crate) fn subsample_exceeds<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    j: usize,
    tol: f64,
) -> bool {
    let n = data.len();
    let (a, b) = segment_range(fitting, j, n);
    let Ok(ctrl) = curve.segment_controls(j) else {
        return false;
    };
    let cubic = PowerCubic::new(&ctrl);
    let at = |off: usize| data[if a + off < n { a + off } else { a + off - n }];
    let (mut t, mut previous) = (0.0, at(0));
    for off in (0..b - a).step_by(COARSE_STRIDE) {
        let v = at(off);
        let t0 = if off == 0 {
            0.0
        } else {
            cubic.start_after(t, &previous, &v)
        };
        let d;
        (t, d) = cubic.foot(&v, t0);
        if d > tol {
            return true;
        }
        previous = v;
    }
    false
}

/// One segment's errors with what they were measured on: its data range and its four control
/// points. A segment of a later round with the same range and bit for bit the same control points
/// has the same errors, so they are not measured again.
#[derive(Clone)]
pub(crate) struct Measured<const D: usize> {
    range: (usize, usize),
    ctrl: [Vector<D>; 4],
    errors: SegmentErrors,
}

impl<const D: usize> Measured<D> {
    /// The errors of the segment on the data range `range` with the control points `ctrl`.
    pub(crate) fn new(range: (usize, usize), ctrl: [Vector<D>; 4], errors: SegmentErrors) -> Self {
        Self {
            range,
            ctrl,
            errors,
        }
    }

    /// The segment's first data index, by which [`assess_reusing`] finds it.
    pub(crate) fn first(&self) -> usize {
        self.range.0
    }
}

/// Errors of every segment of `curve`.
pub(crate) fn assess<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
) -> Assessment {
    assess_reusing(data, fitting, curve, closed, options, &mut Vec::new())
}

/// [`assess`], taking the errors of every segment that `previous` (the segments of the last
/// round, by their first data index) measured on the same data range with the same control points,
/// and leaving this round's segments in `previous`.
///
/// Between two rounds only the spans with a new fitting point change: a sharp vertex's row of
/// eq. (4) is `p_i = q_i`, so the solution on either side of it does not depend on the other
/// side, and the untouched spans come out bit for bit the same. The values are exactly those of
/// a full [`assess`].
pub(crate) fn assess_reusing<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
    previous: &mut Vec<Measured<D>>,
) -> Assessment {
    let n = data.len();
    let (mut max_d2c, mut sum2, mut count, mut max_c2d) = (0.0_f64, 0.0, 0usize, 0.0_f64);
    let segs = curve.segment_count();
    let mut verdicts = Vec::with_capacity(segs);
    let mut driven = Vec::with_capacity(segs);
    let mut now = Vec::with_capacity(segs);
    for j in 0..segs {
        let range = segment_range(fitting, j, n);
        let ctrl = curve.segment_controls(j).ok();
        let reused = previous
            .binary_search_by_key(&range.0, |m| m.range.0)
            .ok()
            .map(|o| &previous[o])
            .filter(|m| m.range == range && Some(m.ctrl) == ctrl);
        let e = match reused {
            Some(m) => m.errors.clone(),
            None => assess_segment(data, fitting, curve, closed, options, j, f64::INFINITY),
        };
        max_d2c = max_d2c.max(e.d2c);
        max_c2d = max_c2d.max(e.c2d);
        sum2 += e.sum2;
        count += e.count;
        driven.push(e.driven(options.measure));
        verdicts.push(e.verdict);
        if let Some(ctrl) = ctrl {
            now.push(Measured {
                range,
                ctrl,
                errors: e,
            });
        }
    }
    *previous = now;
    Assessment {
        max_d2c,
        rms_d2c: if count > 0 {
            (sum2 / count as f64).sqrt()
        } else {
            0.0
        },
        max_c2d,
        verdicts,
        driven,
    }
}

#[cfg(test)]
mod tests {
    use super::{COARSE_STRIDE, subsample_exceeds};
    use crate::{Closure, SubdivCurve, Vector2};

    /// The subsample's verdict against an independent oracle: each sampled data point's distance
    /// by the nearest of 20,001 points of the segment (within 10⁻⁸ here), the largest over every
    /// [`COARSE_STRIDE`]-th point of the segment (its end point left out). Just below that
    /// largest distance the subsample exceeds the tolerance, just above it not; the data points
    /// between the samples (much farther off) do not count.
    #[test]
    fn subsample_exceeds_is_the_strided_maximum() {
        let points: Vec<Vector2> = [(0.0, 0.0), (1.0, 0.9), (2.0, 1.2), (3.0, 0.4), (4.0, 0.0)]
            .iter()
            .map(|&(x, y)| Vector2::new(x, y))
            .collect();
        let curve = SubdivCurve::with_sharp(points, &[0, 4], Closure::Open).unwrap();
        // 53 data points on segment 1 (data indices 0..=52, fitting points 0 and 52): off the
        // curve along y by a varying amount, every other point far off (they are not sampled
        // when the stride is even).
        let per = 52;
        let data: Vec<Vector2> = (0..=per)
            .map(|m| {
                let p = curve.eval_segment(1, m as f64 / per as f64).unwrap();
                let off = if m % 2 == 1 {
                    0.5
                } else {
                    1e-3 * (m % 7) as f64
                };
                p + Vector2::new(0.0, off)
            })
            .collect();
        let fitting = [
            (0, true),
            (0, false),
            (per, false),
            (per, false),
            (per, true),
        ];
        // Only segment 1 is used: its range is 0..=52.
        let dense: Vec<Vector2> = (0..=20_000)
            .map(|i| curve.eval_segment(1, f64::from(i) / 20_000.0).unwrap())
            .collect();
        let oracle = |v: &Vector2| {
            dense
                .iter()
                .map(|p| (p - v).norm())
                .fold(f64::MAX, f64::min)
        };
        assert_eq!(COARSE_STRIDE % 2, 0);
        let worst = (0..per)
            .step_by(COARSE_STRIDE)
            .map(|m| oracle(&data[m]))
            .fold(0.0, f64::max);
        assert!(worst > 1e-3 && worst < 0.01, "{worst}");
        assert!(subsample_exceeds(&data, &fitting, &curve, 1, worst - 1e-7));
        assert!(!subsample_exceeds(&data, &fitting, &curve, 1, worst + 1e-7));
        // The skipped points are far off: the full maximum would exceed 0.1.
        assert!(oracle(&data[1]) > 0.1);
    }
}
