//! Per-segment errors of a round (Sec. 5, eqs. 5–6, and the two-sided measure).

use bez_core::Vector;

use crate::SubdivCurve;
use crate::bspline::bspline_basis;
use crate::curve::combine;
use crate::distance::{foot_point_ctrl, point_polyline_distance};
use crate::fit::{ErrorMeasure, FitOptions};
use crate::insertion::{Verdict, segment_range};

/// Chord-length parameters of data a..=b (indices mod n), the paper's Newton start (Sec. 5).
pub(crate) fn chord_params<const D: usize>(data: &[Vector<D>], a: usize, b: usize) -> Vec<f64> {
    let n = data.len();
    let mut acc = Vec::with_capacity(b - a + 1);
    let mut s = 0.0;
    acc.push(0.0);
    for i in a..b {
        s += (data[(i + 1) % n] - data[i % n]).norm();
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
/// its chord-length parameter, and dense curve samples against the segment's data polyline.
pub(crate) fn assess_segment<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
    j: usize,
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
    let chord = chord_params(data, a, b);
    let (mut seg_max, mut seg_arg, mut sum2, mut count) = (0.0_f64, None, 0.0, 0);
    for (off, t0) in chord.iter().enumerate() {
        // The segment's end data points are counted once, by the segment that starts there
        // (for open data the last point also by the last segment).
        let last_of_open = !closed && j + 1 == segs && off + 1 == chord.len();
        if off + 1 == chord.len() && !last_of_open {
            continue;
        }
        let v = data[(a + off) % n];
        let (_, d) = foot_point_ctrl(&ctrl, &v, *t0);
        sum2 += d * d;
        count += 1;
        if d > seg_max {
            seg_max = d;
            if off > 0 && a + off < b {
                seg_arg = Some((a + off) % n);
            }
        }
    }
    let mut verdict = Verdict {
        fails: seg_max > tol,
        worst_point: seg_arg.filter(|_| seg_max > tol),
    };
    let mut c2d = 0.0_f64;
    if options.measure == ErrorMeasure::TwoSided || !verdict.fails {
        let poly: Vec<Vector<D>> = (a..=b).map(|i| data[i % n]).collect();
        let s = options.samples_per_segment;
        let mut worst_u = 0.0;
        for m in 0..=s {
            let u = m as f64 / s as f64;
            let d = point_polyline_distance(&combine(&ctrl, bspline_basis(u)), &poly);
            if d > c2d {
                c2d = d;
                worst_u = u;
            }
        }
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

/// Errors of every segment of `curve`.
pub(crate) fn assess<const D: usize>(
    data: &[Vector<D>],
    fitting: &[(usize, bool)],
    curve: &SubdivCurve<D>,
    closed: bool,
    options: &FitOptions,
) -> Assessment {
    let (mut max_d2c, mut sum2, mut count, mut max_c2d) = (0.0_f64, 0.0, 0usize, 0.0_f64);
    let segs = curve.segment_count();
    let mut verdicts = Vec::with_capacity(segs);
    let mut driven = Vec::with_capacity(segs);
    for j in 0..segs {
        let e = assess_segment(data, fitting, curve, closed, options, j);
        max_d2c = max_d2c.max(e.d2c);
        max_c2d = max_c2d.max(e.c2d);
        sum2 += e.sum2;
        count += e.count;
        driven.push(e.driven(options.measure));
        verdicts.push(e.verdict);
    }
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
