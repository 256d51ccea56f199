//! # class-a
//!
//! Zhang G, Yang L. *Interactive generation of Class A Bézier curves.* 2014
//! (after Farin 2006 and Yoshida & Saito).
//!
//! Class A Bézier curves, whose control polygon legs are Δbⱼ = Mʲ Δb₀ for a Class A matrix M,
//! generated interactively from a few points; their log spirals and logarithmic curvature and
//! torsion graphs.
