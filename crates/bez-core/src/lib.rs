//! # bez-core
//!
//! The Bézier kernel of bezkit: the Bernstein basis, de Casteljau evaluation and subdivision,
//! degree elevation and reduction, derivatives (hodographs), curvature and torsion, arc length,
//! nearest points, bounding boxes, and tensor-product surfaces. Every paper crate of the
//! workspace stands on it.
//!
//! Points and vectors are bez-core's own [`Vector<D>`] (aliases [`Vector2`], [`Vector3`]), so one
//! generic implementation serves planar and spatial curves. Constructors validate their input
//! and every fallible method returns [`CoreError`]; nothing panics on user input.
//!
//! ```
//! use bez_core::{BezierCurve, Vector2};
//!
//! let curve = BezierCurve::new(vec![
//!     Vector2::new(0.0, 0.0),
//!     Vector2::new(1.0, 2.0),
//!     Vector2::new(3.0, 2.0),
//!     Vector2::new(4.0, 0.0),
//! ])?;
//! let mid = curve.eval(0.5)?;                 // de Casteljau
//! let (left, right) = curve.split(0.5)?;      // subdivision
//! let higher = curve.elevate(2)?;             // same curve, degree 5
//! assert_eq!(left.end(), mid);
//! assert!((higher.eval(0.3)? - curve.eval(0.3)?).norm() < 1e-14);
//! println!("length {:.6}, curvature at ½ {:.6}", curve.arc_length(1e-10)?, curve.signed_curvature(0.5)?);
//! # let _ = right;
//! # Ok::<(), bez_core::CoreError>(())
//! ```
//!
//! ## The curve trait
//! [`BezierForm`] is the trait of every curve on [0, 1] that is exactly a polynomial and keeps
//! its Bézier form. An implementor lends that form ([`BezierForm::as_bezier`], a free borrow)
//! and gets evaluation, the derivative, splitting, subsegments, arc length, the nearest point,
//! the tight bounding box and curvature, with the checked semantics (and, for a
//! [`BezierCurve`], the bits) of `BezierCurve`'s own methods. `BezierCurve` implements it, and
//! so do the λ-Bézier curves, Class A curves and subdivision-curve segments of the paper crates;
//! bez-subdiv's flatteners accept any `&C` with `C: BezierForm<2> + ?Sized`.
//!
//! ```
//! use bez_core::{BezierCurve, BezierForm, Vector2};
//!
//! /// Generic over every curve with a Bézier form, trait objects included.
//! fn describe<C: BezierForm<2> + ?Sized>(c: &C) -> Result<(f64, f64), bez_core::CoreError> {
//!     let b = c.bounding_box();
//!     Ok((c.arc_length(1e-10)?, b.max.y() - b.min.y()))
//! }
//!
//! let arch = BezierCurve::new(vec![
//!     Vector2::new(0.0, 0.0),
//!     Vector2::new(1.0, 2.0),
//!     Vector2::new(2.0, 0.0),
//! ])?;
//! let (length, height) = describe(&arch)?;
//! assert_eq!(height, 1.0);
//! assert_eq!(length, arch.arc_length(1e-10)?); // the same code, bit for bit
//! let shapes: Vec<Box<dyn BezierForm<2>>> = vec![Box::new(arch.clone()), Box::new(arch.reverse())];
//! assert_eq!(describe(shapes[1].as_ref())?.1, 1.0);
//! # Ok::<(), bez_core::CoreError>(())
//! ```
//!
//! ## Accuracy
//! Subdivision and subsegments use de Casteljau (never the power basis), accurate at degree
//! 100. [`BezierCurve::eval_many`] is O(n) per point (Horner in t/(1 − t)) and agrees with de
//! Casteljau to a few ulps; [`BezierCurve::eval_compensated`] doubles the working precision for
//! ill-conditioned evaluations.
//!
//! ## Features
//! None is enabled by default.
//! - `serde`: `Serialize`/`Deserialize` for vectors (a flat sequence `[x, y, …]`), curves,
//!   surfaces and boxes (deserialization validates).
//! - `nalgebra`: `From` both ways between [`Vector<D>`] and `nalgebra::SVector<f64, D>`.
//! - `glam`: `From` both ways between [`Vector2`]/[`Vector3`] and `glam::DVec2`/`DVec3`, and
//!   curve constructors and accessors in glam types.
//! - `mint`: `From` both ways between [`Vector2`]/[`Vector3`] and `mint::Point2<f64>`,
//!   `mint::Vector2<f64>`, `mint::Point3<f64>`, `mint::Vector3<f64>`.
//! - `kurbo`: `From` both ways between [`Vector2`] and `kurbo::Point`/`Vec2`; `Line`, `QuadBez`
//!   and `CubicBez` into [`BezierCurve<2>`] and back (`TryFrom`, by degree); `BezPath` to and
//!   from lists of curves (`bez_path_to_curves`, `curves_to_bez_path`).
//! - `proptest-support`: strategies for random control polygons, and `check_bezier_form` (every
//!   method of a [`BezierForm`] implementor against an independent oracle), for dependent
//!   crates' tests.

#![cfg_attr(not(any(feature = "std", test)), no_std)]

extern crate alloc;

mod arclen;
mod bbox;
mod bernstein;
mod bezier_form;
mod casteljau;
mod curve;
mod differential;
mod error;
mod halve;
#[cfg(feature = "glam")]
mod interop_glam;
#[cfg(feature = "kurbo")]
mod interop_kurbo;
#[cfg(feature = "mint")]
mod interop_mint;
#[cfg(feature = "nalgebra")]
mod interop_nalgebra;
mod limits;
mod math;
mod nearest;
mod reduce;
mod roots;
mod surface;
mod vector;

#[cfg(feature = "proptest-support")]
pub mod proptest_support;

pub use crate::arclen::DEFAULT_ACCURACY;
pub use crate::bbox::Aabb;
pub use crate::bernstein::{
    EXACT_BINOMIAL_DEGREE, bernstein, bernstein_derivative, bernstein_derivative_coeffs,
    bernstein_elevate, bernstein_product, bernstein_row, binomial, eval_bernstein_poly,
};
pub use crate::bezier_form::BezierForm;
pub use crate::casteljau::{
    ControlPoint, HORNER_MAX_DEGREE, HornerBernstein, compensated_de_casteljau, de_casteljau,
    de_casteljau_in_place, de_casteljau_split, de_casteljau_split_array, elevate_slice,
    hodograph_slice, lerp,
};
pub use crate::curve::BezierCurve;
pub use crate::error::CoreError;
pub use crate::halve::{de_casteljau_halve, de_casteljau_halve_array, de_casteljau_halve_in_place};
#[cfg(feature = "kurbo")]
pub use crate::interop_kurbo::{bez_path_to_curves, curves_to_bez_path};
pub use crate::limits::{MAX_COORDINATE, MAX_DEGREE, MAX_SAMPLES};
pub use crate::nearest::Nearest;
pub use crate::reduce::Reduced;
pub use crate::roots::roots_in_unit_interval;
pub use crate::surface::BezierSurface;
pub use crate::vector::{Vector, Vector2, Vector3};

/// The README's example, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
