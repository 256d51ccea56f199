//! # subdiv-fit
//!
//! Wang Dong, Li Guiqing, Tian Xuhong.
//! *Parameterization of subdivision curve with sharp feature and their applications*
//! (带尖锐特征的细分曲线参数化及曲线拟合).
//! Journal of Image and Graphics 13(8), 2008, 1554–1559.
//!
//! Cubic B-spline subdivision curves whose vertices may be sharp or, beyond the paper, tangent
//! (a double knot: G1 with a curvature jump) or curved sharp (a corner whose sides keep their
//! curvature: the first segment on each side is a parabola instead of starting straight)
//! ([`SubdivCurve`], [`VertexKind`]),
//! their refinement (Sec. 2.1), their exact evaluation at any parameter with first and second
//! derivatives (Sec. 2.2), exact conversion of every segment to a cubic Bézier curve, and the
//! adaptive fitting of such curves to ordered data points (Secs. 3–5, [`fit`]), with a per-round
//! report, a two-sided error measure, a least-squares mode, corners whose turn stays within
//! [`FitOptions::corner_tolerance`] of the data's and tangent joints (given to [`fit_with_joints`]
//! or detected with [`FitOptions::tangent_jump`]) beyond the paper.
//!
//! The paper's eigen-structure closed form (Theorem 2, eq. 3) collapses, once its misprints are
//! corrected, to one uniform cubic B-spline segment per polygon edge: a sharp vertex `p_i` acts as if
//! its neighbour across it were the phantom point `2 p_i − p_{i+1}`.
//! [`SubdivCurve::segment_controls`] implements that; module `eigen` (feature `paper`) keeps the corrected eigen
//! form, and the tests check that the two agree with each other and with repeated refinement.
//! The phantom point gives the curve zero curvature at the corner on both sides; a
//! [`VertexKind::SharpCurved`] vertex instead makes each side's first segment a parabola through
//! the corner (the parabolic end condition, derived in module `curved_corner`), with the same
//! control points.
//!
//! ## Which fit should I use
//!
//! | goal | options | on the printable ASCII of DejaVu Sans at 10⁻³ em |
//! |---|---|---|
//! | the default, fastest at coarse tolerances | [`FitOptions::new`] | 1.49x TrueType's points |
//! | fewest control points | `.with_reduction(Reduction::Refit).with_corner_kind(VertexKind::SharpCurved)` | 0.96x, kept corners' turns unchecked |
//! | fewest points with every corner's turn within 1° of the outline's | the same `.with_corner_tolerance(Some(EXACT_CORNER_TOLERANCE))` with `fit_bez_path` (feature `kurbo`) or [`fit_with_known_corners`] | 0.99x, every kept corner within 0.90°, under 1 ms per glyph (1.3–1.5x the time of the row above) |
//! | the paper's configuration | [`FitOptions::paper`] | |
//! | lines meeting arcs tangentially (the curvature jumps) | the joints given ([`fit_with_joints`]) or detected ([`FitOptions::tangent_jump`]) with `.with_reduction(Reduction::Refit).with_corner_kind(VertexKind::SharpCurved)`: smooth joints ([`Corner::smooth`]), G1 to [`SMOOTH_JOINT_TURN`] | (on lines meeting arcs: 0.11–0.72x the control points of the interpolating fit's double knots) |
//!
//! (`docs/papers/subdiv-fit.md` in the repository has the measured table.)
//!
//! ```
//! use subdiv_fit::{Closure, SubdivCurve, Vector2};
//!
//! let square = vec![
//!     Vector2::new(0.0, 0.0),
//!     Vector2::new(1.0, 0.0),
//!     Vector2::new(1.0, 1.0),
//!     Vector2::new(0.0, 1.0),
//! ];
//! // One sharp corner, three smooth ones.
//! let curve = SubdivCurve::with_sharp(square, &[0], Closure::Closed)?;
//! // A sharp vertex is interpolated; a regular one reaches (p_{i-1} + 4 p_i + p_{i+1}) / 6.
//! assert_eq!(curve.eval(0.0)?, Vector2::new(0.0, 0.0));
//! assert!((curve.eval(2.0)? - Vector2::new(5.0 / 6.0, 5.0 / 6.0)).norm() < 1e-15);
//! // Each segment is an exact cubic Bézier curve.
//! let beziers = curve.to_beziers()?;
//! assert_eq!(beziers.len(), 4);
//! # Ok::<(), subdiv_fit::SubdivFitError>(())
//! ```
//!
//! Fitting ordered data with corners: 64 points around the unit square.
//!
//! ```
//! use subdiv_fit::{Closure, FitOptions, Vector2, fit};
//!
//! let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
//! let data: Vec<Vector2> = (0..64)
//!     .map(|k| {
//!         let ((x0, y0), (x1, y1)) = (corners[k / 16], corners[(k / 16 + 1) % 4]);
//!         let s = (k % 16) as f64 / 16.0;
//!         Vector2::new(x0 + s * (x1 - x0), y0 + s * (y1 - y0))
//!     })
//!     .collect();
//! let result = fit(&data, Closure::Closed, &FitOptions::new(0.01))?;
//! let last = result.last().expect("one report per round");
//! assert!(last.max_data_to_curve <= 0.01 && last.max_curve_to_data <= 0.01);
//! // The corners are sharp control points sitting on their data points.
//! assert_eq!(result.curve.kinds().iter().filter(|k| k.is_sharp()).count(), 4);
//! let path = subdiv_fit::svg_path(&result.curve)?; // exact cubic Béziers
//! assert!(path.starts_with("M "));
//! # Ok::<(), subdiv_fit::SubdivFitError>(())
//! ```

mod assess;
mod band_lu;
mod banded;
mod bspline;
#[cfg(feature = "paper")]
pub mod cases;
mod chord;
mod corner;
mod corner_angles;
mod corners;
mod curvature;
mod curve;
mod curved_corner;
mod distance;
#[cfg(feature = "paper")]
pub mod eigen;
mod error;
mod fit;
mod insertion;
mod joints;
mod knots;
#[cfg(feature = "kurbo")]
mod line_samples;
mod on_rays;
#[cfg(feature = "kurbo")]
mod path;
mod reduction;
mod refit;
mod seeding;
mod segment;
mod svg;
mod tangent;
mod tangent_joints;
mod tangent_rows;
mod tridiagonal;
mod vertex;

pub use crate::bspline::{bspline_basis, bspline_basis_d1, bspline_basis_d2, bspline_to_bezier};
pub use crate::corner::Corner;
pub use crate::corner_angles::{CORNER_TOLERANCE, EXACT_CORNER_TOLERANCE, SMOOTH_JOINT_TURN};
pub use crate::corners::SCALE_RATIO;
pub use crate::curvature::{FeaturePoint, discrete_curvature, feature_points, turning_angle};
pub use crate::curve::{Closure, CurvePoint, SubdivCurve};
pub use crate::distance::{foot_point, point_polyline_distance};
pub use crate::error::{BestCurve, SubdivFitError};
pub use crate::fit::{
    ErrorMeasure, Fit, FitMode, FitOptions, Insertion, MAX_DATA_COORDINATE, MAX_FEATURE_SCALE,
    MAX_FIT_POINTS, MAX_ROUNDS, MAX_SAMPLES_PER_SEGMENT, Reduction, RoundReport, Seeding,
    TANGENT_JUMP, fit, fit_with_corners, fit_with_joints, fit_with_known_corners, scaled_corners,
};
pub use crate::joints::Joints;
#[cfg(feature = "kurbo")]
pub use crate::line_samples::{LINE_END_SAMPLES, LINE_MAX_STEP, LineSampling};
#[cfg(feature = "kurbo")]
pub use crate::path::{
    JOINT_ROOM, PATH_CORNER_ANGLE, SampledContour, fit_bez_path, sample_bez_path,
    sample_bez_path_with, sample_svg_path,
};
pub use crate::reduction::MAX_REDUCED;
pub use crate::segment::Segment;
pub use crate::svg::svg_path;
pub use crate::vertex::VertexKind;
pub use bez_core::{Vector, Vector2, Vector3};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
