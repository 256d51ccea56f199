//! # subdiv-fit
//!
//! Wang, Li, Tian. *Subdivision curves with sharp features and curve fitting.* 2008.
//!
//! Cubic B-spline subdivision curves with sharp vertices, their exact evaluation, and adaptive
//! fitting of such curves to ordered data points.
