//! # pde-bezier
//!
//! Xu, Wang. *Bézier approximation of PDE surfaces.* 2007.
//!
//! Bézier surfaces that approximately solve linear elliptic PDEs (Laplace-type and fourth-order
//! Bloor-Wilson operators) under boundary conditions, by constrained least squares on the
//! Bernstein coefficients of the residual, with multi-patch refinement.
