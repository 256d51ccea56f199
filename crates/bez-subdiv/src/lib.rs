//! # bez-subdiv
//!
//! Ma Xiaohui, Lin Fengming, Shen Liyong. *Optimal subdivision parameters for planar Bézier
//! curves* (平面 Bézier 曲线细分算法的参数优化). Journal of University of Chinese Academy of
//! Sciences, 2016, 33(3): 311–316.
//!
//! Adaptive subdivision ("flattening") of planar Bézier curves into control polygons that are
//! flat to a tolerance (eq. (3)), with the split parameter of each piece chosen by a
//! [`SplitRule`]: the classical t = ½, or the parameter minimizing the pieces' flatness
//! (Def. 2.2) or convex-hull area (Def. 2.1), searched on the paper's grid or exactly.
//!
//! **Start with [`Flattener`]**: one entry point with an absolute tolerance, the points streamed
//! to a closure, paths of several curves, and a [`Method`] (see its "which method" table); the
//! default, [`Method::Fast`], is guaranteed and the fastest.
//!
//! Beyond the paper, flattenings with a Hausdorff guarantee: [`flatten_wang`] (Wang's uniform
//! count, no subdivision), [`flatten_guaranteed`] (halving
//! until the control points are near the chord segment), [`flatten_local_wang`] (Wang's bound
//! piece by piece, O(n) per point, the fast one at high degree) and [`flatten_near_optimal`]
//! (close to the lower bound [`optimal_segment_count`]); [`flatten_fixed_into`] is the fixed rule
//! without allocation, and [`measured_hausdorff`] checks any of them.
//!
//! Every flattening entry point and [`measured_hausdorff`] take `&C` for any
//! `C: `[`BezierForm<2>`](bez_core::BezierForm)` + ?Sized`: a `BezierCurve`, and equally a
//! λ-Bézier curve, a Class A curve or a subdivision-curve segment of the other crates, or a
//! `&dyn BezierForm<2>`. They flatten the exact Bézier form, which the curve lends for free.
//!
//! Feature `rayon`: [`flatten_batch`] flattens many curves in parallel. Feature `kurbo`:
//! `Flattener::flatten_bez_path`. Feature `serde`: serde on
//! the data types. Feature `paper`: what exists only to reproduce or compare with the paper, the
//! seeded test curves of Table 1 (`cases`), the exact-optimum split search (`Search::Exact`,
//! with argmin) and `split_objective`; it brings rand and argmin, which the library itself
//! does not need.
//!
//! ```
//! use bez_core::{BezierCurve, Vector2};
//! use bez_subdiv::{FlattenOptions, SplitRule, flatten};
//!
//! let curve = BezierCurve::new(vec![
//!     Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0),
//!     Vector2::new(3.0, -1.0), Vector2::new(4.0, 1.0),
//! ])?;
//! let options = FlattenOptions::default().with_rule(SplitRule::flatness());
//! let result = flatten(&curve, &options)?;
//! assert_eq!(result.stats.splits + 1, result.stats.pieces);
//! assert_eq!(result.polyline[0], curve.start());
//! # Ok::<(), bez_subdiv::SubdivError>(())
//! ```

mod batch;
mod bound;
#[cfg(feature = "paper")]
pub mod cases;
mod chord;
mod error;
mod fixed;
mod flatten;
mod flattener;
mod guaranteed;
mod hausdorff;
mod limits;
mod local_wang;
mod measure;
mod near_optimal;
pub mod optimal;
mod split_rule;
#[cfg(test)]
mod test_support;
mod wang;

pub use crate::batch::flatten_batch;
pub use crate::bound::{max_second_difference, wang_depth, wang_segment_count};
pub use crate::chord::chord_deviation;
pub use crate::error::SubdivError;
pub use crate::fixed::flatten_fixed_into;
pub use crate::flatten::{
    DEFAULT_MAX_DEPTH, DEFAULT_TOLERANCE, FlattenOptions, FlattenStats, Flattening, Piece,
    curve_size, flatten,
};
pub use crate::flattener::{Flattener, Method, PathPoint};
pub use crate::guaranteed::{FlatPoint, distance_to_segment, flatten_guaranteed};
pub use crate::hausdorff::{HausdorffSampling, measured_hausdorff};
pub use crate::limits::MAX_FLATTEN_DEPTH;
pub use crate::local_wang::{LOCAL_WANG_STEPS, flatten_local_wang};
pub use crate::measure::{distance_to_chord_line, flatness, hull_area, max_chord_distance};
pub use crate::near_optimal::{flatten_near_optimal, optimal_segment_count};
#[cfg(feature = "paper")]
pub use crate::split_rule::split_objective;
pub use crate::split_rule::{
    ADAPTIVE_BAND, Branch, Choice, Levels, Objective, PAPER_LEVELS, Search, SplitRule,
};
pub use crate::wang::{MAX_WANG_SEGMENTS, flatten_wang};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
