//! # bez-subdiv
//!
//! Flattening of planar Bézier curves of any degree into polylines within a guaranteed
//! distance, and the reproduction of Ma Xiaohui, Lin Fengming, Shen Liyong. *Optimal
//! subdivision parameters for planar Bézier curves* (平面 Bézier 曲线细分算法的参数优化).
//! Journal of University of Chinese Academy of Sciences, 2016, 33(3): 311–316.
//!
//! **[`Flattener`] is the entry point**: an absolute tolerance, the points streamed to a
//! closure with their parameters, paths of several curves, batches (in parallel with the
//! `rayon` feature), and a [`Method`]:
//!
//! | method | guarantee | segments / N* (random cubics, tol = 1e-3 × size) | cost |
//! |---|---|---|---|
//! | [`Method::Fast`] (default) | Hausdorff ≤ tol | about 2 (Wang's count, lyon_geom's) | a few flops per point, no subdivision |
//! | [`Method::Optimal`] | Hausdorff ≤ tol | median 1.05, 90th percentile 1.10 | below kurbo's `flatten` on cubics (0.84–0.88 × its time on random ones on a quiet machine); above degree 3 O(1) per point, O(n) per quintic model, about 0.08 µs per point at degree 25 (medians 1.07–1.09 N* there at 1e-3 × size, 1.01–1.03 at 1e-5) |
//! | [`Method::LocalWang`] | Hausdorff ≤ tol | 1.6–2.0 | one halving per up to 16 points |
//! | [`Method::Halving`] | Hausdorff ≤ tol | about 1.7 | one halving per segment |
//! | [`Method::PaperRule`] | **none** (eq. (3) on degenerate input: 2,007 × tol) | — | reproduction of Table 1 |
//!
//! N* = ∫ √(|κ| / (8 tol)) ds is the asymptotic lower bound ([`optimal_segment_count`]);
//! [`measured_hausdorff`] checks any polyline against its curve.
//!
//! The paper's adaptive subdivision splits each piece at the parameter chosen by a
//! [`SplitRule`] (t = ½, or the parameter minimizing the pieces' flatness, Def. 2.2, or
//! convex-hull area, Def. 2.1) until eq. (3) holds; [`Method::PaperRule`] runs it. With the
//! `paper` feature, its piece lists and statistics (`flatten`, `FlattenOptions`,
//! `flatten_fixed_into`), the seeded test curves of Table 1 (`cases`), the exact-optimum split
//! search (`Search::Exact`, with argmin) and `split_objective` are public too; they bring rand
//! and argmin, which the library itself does not need.
//!
//! Every flattening takes `&C` for any `C: `[`BezierForm<2>`](bez_core::BezierForm)` + ?Sized`:
//! a `BezierCurve`, and equally a λ-Bézier curve, a Class A curve or a subdivision-curve
//! segment of the other crates. Feature `kurbo`: `Flattener::flatten_bez_path`. Feature
//! `serde`: serde on the data types.
//!
//! ```
//! use bez_core::{BezierCurve, Vector2};
//! use bez_subdiv::{Flattener, Method};
//!
//! let curve = BezierCurve::new(vec![
//!     Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0),
//!     Vector2::new(3.0, -1.0), Vector2::new(4.0, 1.0),
//! ])?;
//! let mut polyline = Vec::new();
//! let segments = Flattener::new(1e-3)
//!     .with_method(Method::Optimal)
//!     .flatten(&curve, |p| polyline.push((p.t, p.point)))?;
//! assert_eq!(polyline.len(), segments + 1);
//! assert_eq!(polyline[0], (0.0, curve.start()));
//! # Ok::<(), bez_subdiv::SubdivError>(())
//! ```

#[cfg_attr(
    not(feature = "paper"),
    allow(unreachable_pub, reason = "re-exported with the paper feature only")
)]
mod bound;
mod bump;
#[cfg(feature = "paper")]
pub mod cases;
mod chord;
mod error;
#[cfg_attr(
    not(feature = "paper"),
    allow(unreachable_pub, reason = "re-exported with the paper feature only")
)]
mod fixed;
#[cfg_attr(
    not(feature = "paper"),
    allow(unreachable_pub, reason = "re-exported with the paper feature only")
)]
mod flatten;
mod flattener;
mod forward_difference;
mod guaranteed;
mod hausdorff;
mod limits;
mod local_wang;
mod measure;
mod model_march;
mod near_optimal;
mod optimal;
mod order;
mod parabola;
mod quintic_model;
mod split_rule;
mod stack_horner;
#[cfg(test)]
mod test_support;
mod wang;

pub use crate::bound::wang_segment_count;
#[cfg(feature = "paper")]
pub use crate::bound::{max_second_difference, wang_depth};
pub use crate::chord::chord_deviation;
pub use crate::error::SubdivError;
#[cfg(feature = "paper")]
pub use crate::fixed::flatten_fixed_into;
pub use crate::flatten::curve_size;
#[cfg(feature = "paper")]
pub use crate::flatten::{
    DEFAULT_MAX_DEPTH, DEFAULT_TOLERANCE, FlattenOptions, FlattenStats, Flattening, Piece, flatten,
};
pub use crate::flattener::{Flattener, Method, PathPoint};
pub use crate::guaranteed::{FlatPoint, distance_to_segment};
pub use crate::hausdorff::{HausdorffSampling, MAX_HAUSDORFF_WORK, measured_hausdorff};
pub use crate::limits::MAX_FLATTEN_DEPTH;
pub use crate::local_wang::LOCAL_WANG_STEPS;
pub use crate::measure::{distance_to_chord_line, flatness, hull_area, max_chord_distance};
pub use crate::near_optimal::optimal_segment_count;
#[cfg(feature = "paper")]
pub use crate::split_rule::split_objective;
pub use crate::split_rule::{
    ADAPTIVE_BAND, Branch, Choice, Levels, Objective, PAPER_LEVELS, Search, SplitRule,
};
pub use crate::stack_horner::MAX_STACK_DEGREE;
pub use crate::wang::MAX_WANG_SEGMENTS;

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
