//! # lambda-bezier
//!
//! Wu R J. *Bézier curve with shape parameter.* 2006.
//!
//! λ-Bézier curves: degree n + 1 polynomial curves on n + 1 control points with a shape
//! parameter λ, generalizing Han & Liu's quadratic extension, and their tensor-product surfaces.
