//! # class-a
//!
//! Zhang Zhiyi, Yang Xi. *Interactively controlled generation method for Class A Bézier curve*
//! (A 级贝塞尔曲线的交互式控制生成方法). Computer Applications and Software 31(2), 2014,
//! doi:10.3969/j.issn.1000-386x.2014.02.028; after G. Farin, *Class A Bézier curves*, CAGD 23
//! (2006) 573–581, and N. Yoshida, T. Saito, *Interactive control of planar Class A Bézier curves
//! using logarithmic curvature graphs*, CAD&A 5 (2008).
//!
//! Class A Bézier curves have control polygon legs Δbⱼ = Mʲ Δb₀ for a Class A matrix M. This
//! crate reports each of Farin's matrix conditions separately, proves monotone curvature and
//! torsion of the curve itself (exact integer Bernstein form of the derivative's numerator), generates
//! typical planar curves from three points with a bracketed root solve (the paper uses
//! Nelder–Mead, kept for comparison), typical spatial curves from four points, the log-spiral
//! pole of the control points, and logarithmic curvature/torsion graphs.
//!
//! Features: `serde` (serde on the data types) and `paper`: what exists only to reproduce or
//! compare with the paper (its cases, the Nelder–Mead baselines, the printed pole of eq. (19)),
//! with the rand and argmin dependencies only that code needs.
//!
//! ```
//! use bez_core::Vector2;
//! use class_a::TypicalPlanar;
//! let (a0, a1, a2) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), Vector2::new(1.6, 1.0));
//! let c = TypicalPlanar::from_points(&a0, &a1, &a2, 7)?;
//! let curve = c.curve()?;
//! assert!((curve.end() - a2).norm() < 1e-12);
//! assert!(c.margin() >= 0.0); // exact monotone curvature, condition (4)
//! # Ok::<(), class_a::ClassAError>(())
//! ```

mod certificate;
mod continuation;
mod curve;
mod dd;
mod edit;
mod end_curvature;
mod error;
mod exact;
mod filter;
mod general;
mod hermite;
mod hermite_search;
mod hermite_spatial;
mod interpolation;
mod lcg;
mod matrix;
mod planar;
mod sign;
mod spatial;
mod spatial_end_curvature;
mod spiral;
mod spline;
mod spline_spatial;
mod square;
mod squarefree;

#[cfg(feature = "paper")]
pub mod cases;

pub use crate::certificate::{
    Certificate, Monotonicity, Proof, UndecidedCause, curvature_certificate, curvature_numerator,
    torsion_certificate, torsion_numerator,
};
pub use crate::curve::{ClassACurve, class_a_curve};
pub use crate::edit::{EditFrame, FRAME_SAMPLES};
pub use crate::end_curvature::{end_curvatures, end_curvatures_torsions};
pub use crate::error::{ClassAError, MAX_DEGREE};
pub use crate::exact::ScaledBernstein;
pub use crate::general::{end_preserving_curve, perturb2, perturb3};
pub use crate::hermite::{Knot, hermite_planar};
pub use crate::hermite_spatial::{SpatialKnot, hermite_spatial};
pub use crate::interpolation::{INTERPOLATION_TOLERANCE, Interpolation};
pub use crate::lcg::{
    LogGraph, curvature_samples, curvature_with_derivative, log_graph, log_graph_from_points,
    torsion_samples, torsion_with_derivative,
};
pub use crate::matrix::{
    ClassAReport, Condition, SUBCURVE_SAMPLES, typical_matrix2, typical_planar_margin,
};
pub use crate::planar::{
    PlanarFeasibility, PlanarGeometry, TypicalPlanar, planar_feasibility, solve_scale,
};
pub use crate::sign::{MAX_PIECES, MAX_SUBDIVISION_DEPTH};
pub use crate::spatial::{SpatialRequirement, TypicalSpatial, rotation};
pub use crate::spiral::{apollonius_pole, log_spiral_pole, spiral_deviation};
pub use crate::spline::{ClassASpline, MAX_KNOTS};
pub use crate::spline_spatial::SpatialClassASpline;
pub use crate::square::{Matrix, Matrix2, Matrix3};
#[cfg(feature = "paper")]
pub use crate::{planar::planar_nelder_mead, spiral::printed_pole_eq19};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
