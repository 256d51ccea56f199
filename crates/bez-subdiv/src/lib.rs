//! # bez-subdiv
//!
//! Ma X H, Lin F M, Shen L Y. *Optimal subdivision parameters for planar Bézier curves.*
//! Journal of University of Chinese Academy of Sciences, 2016, 33(3): 311-316.
//!
//! Adaptive subdivision (flattening) of planar Bézier curves with the split parameter chosen
//! to minimize the flatness or the convex-hull area of the two pieces, beside the classical
//! fixed t = ½ de Casteljau rule.
