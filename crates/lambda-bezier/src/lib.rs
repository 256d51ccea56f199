//! # lambda-bezier
//!
//! Wu Xiaoqin (吴晓勤). *Bézier curve with shape parameter* (带形状参数的 Bézier 曲线).
//! Journal of Image and Graphics (中国图象图形学报) 11(2):269–274, 2006.
//!
//! λ-Bézier curves: polynomial curves of degree n + 1 on n + 1 control points with a shape
//! parameter λ, generalizing Han & Liu's quadratic extension (eq. (1)) by the recurrence (2),
//! and their tensor-product surfaces. At λ = 0 they are ordinary degree n Bézier curves; other
//! λ pull the curve towards (λ > 0) or away from (λ < 0) the control polygon. Every λ-curve is
//! exactly a degree n + 1 Bézier curve whose control points cut the corners of the control
//! polygon ([`corner_cut_ratio`]): this crate evaluates, differentiates and splits through that
//! form, and gives the exact valid λ interval of every degree ([`LambdaRange`]), which the paper
//! states only for n = 2, 3, 4.
//!
//! ```
//! use bez_core::{BezierForm, Vector2};
//! use lambda_bezier::{LambdaBezierCurve, LambdaRange};
//!
//! let p = vec![
//!     Vector2::new(-1.0, 0.0),
//!     Vector2::new(-1.0, 1.2),
//!     Vector2::new(1.0, 1.2),
//!     Vector2::new(1.0, 0.0),
//! ];
//! let half_circle = LambdaBezierCurve::new(p, 0.56)?; // the paper's circle example (4.2)
//! let top = half_circle.eval(0.5)?;
//! assert!((top.y() - 1.0).abs() < 0.02);
//! assert_eq!(LambdaRange::new(3)?.min(), -3.0);
//! assert!(half_circle.with_lambda(-3.5).is_err()); // outside [-3, 1]
//! # Ok::<(), lambda_bezier::LambdaError>(())
//! ```

mod basis;
#[cfg(feature = "paper")]
pub mod cases;
mod curve;
mod error;
#[cfg(feature = "fit")]
mod fit;
mod interpolate;
mod join;
mod range;
mod surface;
mod surface_join;

pub use crate::basis::{LambdaBasis, corner_cut_ratio};
pub use crate::curve::LambdaBezierCurve;
pub use crate::error::LambdaError;
#[cfg(feature = "fit")]
pub use crate::fit::{LambdaFit, LambdaTarget, fit_lambda, minimize_over_range};
pub use crate::interpolate::{shape_preserving_curves, shape_preserving_polygons};
pub use crate::join::{Continuity, continuity, hermite_segment, join_c1, join_g1, join_g2};
pub use crate::range::{LambdaRange, lambda_range};
pub use crate::surface::LambdaBezierSurface;
pub use crate::surface_join::{PatchJoin, join_patches};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
