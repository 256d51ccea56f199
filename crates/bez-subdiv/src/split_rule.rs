//! Split rules: where to subdivide a piece (Ma et al., Sec. 2).

use core::cell::Cell;

#[cfg(feature = "paper")]
use argmin::core::{CostFunction, Executor, State};
#[cfg(feature = "paper")]
use argmin::solver::brent::BrentOpt;
use bez_core::{Vector2, de_casteljau_split};

use crate::error::SubdivError;
use crate::measure::{flatness, hull_area};

/// What an optimal split parameter minimizes, summed over the two pieces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Objective {
    /// Dis(T₁) + Dis(T₂), the flatness of Def. 2.2 ("flatness method", 扁平法).
    Flatness,
    /// Area(T₁) + Area(T₂), the convex-hull areas of Def. 2.1 ("hull method", 凸包法).
    HullArea,
}

/// How the optimum of the objective is searched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Search {
    /// The paper's scan t = 0.2 + 0.05k, k = 0..12 (13 evaluations).
    Grid,
    /// Beyond the paper: scan t = 0.05k, k = 1..19, then Brent's method (argmin) on the
    /// bracket around the best grid point, to 1e-8 in t. Used to compare with the paper's grid;
    /// feature `paper` (it brings argmin).
    #[cfg(feature = "paper")]
    Exact,
}

/// At which subdivision levels the parameter is optimized (0.5 elsewhere).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Levels {
    /// The first N levels (depth 0..N−1), as in the paper (N = 3 for Table 1).
    First(usize),
    /// Beyond the paper (its "future work"): optimize on a piece until its optimum falls within
    /// [`ADAPTIVE_BAND`] of 0.5; its descendants then split at 0.5 (the paper observes that short
    /// pieces have optima near 0.5, Property 2.1/2.3).
    Adaptive,
}

/// Distance from 0.5 under which [`Levels::Adaptive`] stops optimizing a piece's descendants.
pub const ADAPTIVE_BAND: f64 = 0.05;

/// A rule for choosing the subdivision parameter of each piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SplitRule {
    /// t = 0.5 always: the classical de Casteljau "fixed-parameter method" (定参法).
    Fixed,
    /// Minimize an objective at some levels, 0.5 elsewhere.
    Optimal {
        /// What is minimized.
        objective: Objective,
        /// How the minimum is searched.
        search: Search,
        /// At which levels.
        levels: Levels,
    },
}

/// The paper's number of optimized levels for Table 1.
pub const PAPER_LEVELS: usize = 3;

impl SplitRule {
    /// The paper's flatness method: grid scan at the first 3 levels.
    #[must_use]
    pub const fn flatness() -> Self {
        Self::Optimal {
            objective: Objective::Flatness,
            search: Search::Grid,
            levels: Levels::First(PAPER_LEVELS),
        }
    }

    /// The paper's hull-area method: grid scan at the first 3 levels.
    #[must_use]
    pub const fn hull_area() -> Self {
        Self::Optimal {
            objective: Objective::HullArea,
            search: Search::Grid,
            levels: Levels::First(PAPER_LEVELS),
        }
    }

    /// A short name for tables.
    #[must_use]
    pub fn name(&self) -> String {
        match self {
            Self::Fixed => "fixed".into(),
            Self::Optimal {
                objective,
                search,
                levels,
            } => {
                let o = match objective {
                    Objective::Flatness => "flatness",
                    Objective::HullArea => "hull",
                };
                let s = match search {
                    Search::Grid => "grid",
                    #[cfg(feature = "paper")]
                    Search::Exact => "exact",
                };
                let l = match levels {
                    Levels::First(n) => format!("N={n}"),
                    Levels::Adaptive => "adaptive N".into(),
                };
                format!("{o} ({s}, {l})")
            }
        }
    }

    /// The split parameter for a piece at `depth`; `branch` is [`Branch::Settled`] once an
    /// adaptive rule has stopped optimizing this branch (see [`Choice::next`]).
    ///
    /// # Errors
    /// [`SubdivError::Optimizer`] if Brent's method fails.
    pub fn choose(
        &self,
        points: &[Vector2],
        depth: usize,
        branch: Branch,
    ) -> Result<Choice, SubdivError> {
        let fixed = Choice {
            t: 0.5,
            evaluations: 0,
            next: Branch::Settled,
        };
        let Self::Optimal {
            objective,
            search,
            levels,
        } = *self
        else {
            return Ok(fixed);
        };
        let active = match levels {
            Levels::First(n) => depth < n,
            Levels::Adaptive => branch == Branch::Searching,
        };
        if !active || points.len() < 3 {
            return Ok(fixed);
        }
        let counter = Cell::new(0usize);
        let f = |t: f64| {
            counter.set(counter.get() + 1);
            split_objective(objective, points, t)
        };
        let t = match search {
            Search::Grid => grid_minimum(&f, (0..=12).map(|k| 0.2 + 0.05 * f64::from(k))),
            #[cfg(feature = "paper")]
            Search::Exact => {
                let t0 = grid_minimum(&f, (1..=19).map(|k| 0.05 * f64::from(k)));
                brent(&f, (t0 - 0.05).max(1e-3), (t0 + 0.05).min(1.0 - 1e-3))?
            }
        };
        let next = match levels {
            Levels::First(_) => Branch::Searching,
            Levels::Adaptive if (t - 0.5).abs() > ADAPTIVE_BAND => Branch::Searching,
            Levels::Adaptive => Branch::Settled,
        };
        Ok(Choice {
            t,
            evaluations: counter.get(),
            next,
        })
    }
}

/// A chosen split parameter and what it cost.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Choice {
    /// The split parameter in (0, 1).
    pub t: f64,
    /// Objective evaluations spent (each one is a de Casteljau split plus two measures).
    pub evaluations: usize,
    /// Whether an adaptive rule keeps optimizing the two children.
    pub next: Branch,
}

/// Whether a rule still optimizes the split parameter on a branch of the subdivision tree.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Branch {
    /// The rule optimizes the split of this piece.
    Searching,
    /// An adaptive rule found splits near ½ above this piece and splits it at ½.
    Settled,
}

/// The objective of a split at t: measure(left piece) + measure(right piece).
///
/// Cost O(n²) for the split plus O(n) (flatness) or O(n log n) (hull area).
#[must_use]
#[cfg_attr(
    not(feature = "paper"),
    expect(unreachable_pub, reason = "exported with the paper feature")
)]
pub fn split_objective(objective: Objective, points: &[Vector2], t: f64) -> f64 {
    let n = points.len();
    let mut left = vec![Vector2::zeros(); n];
    let mut right = vec![Vector2::zeros(); n];
    if de_casteljau_split(points, t, &mut left, &mut right).is_err() {
        return f64::NAN;
    }
    match objective {
        Objective::Flatness => flatness(&left) + flatness(&right),
        Objective::HullArea => hull_area(&left) + hull_area(&right),
    }
}

/// The grid point with the smallest objective (the first one on ties).
fn grid_minimum(f: &impl Fn(f64) -> f64, grid: impl Iterator<Item = f64>) -> f64 {
    let mut best = (0.5, f64::INFINITY);
    for t in grid {
        let v = f(t);
        if v < best.1 {
            best = (t, v);
        }
    }
    best.0
}

#[cfg(feature = "paper")]
struct Cost<'a, F>(&'a F);

#[cfg(feature = "paper")]
impl<F: Fn(f64) -> f64> CostFunction for Cost<'_, F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, t: &f64) -> Result<f64, argmin::core::Error> {
        Ok((self.0)(*t))
    }
}

#[cfg(feature = "paper")]
fn brent(f: &impl Fn(f64) -> f64, lo: f64, hi: f64) -> Result<f64, SubdivError> {
    let solver = BrentOpt::new(lo, hi).set_tolerance(1e-8, 1e-12);
    let res = Executor::new(Cost(f), solver)
        .configure(|s| s.max_iters(100))
        .run()
        .map_err(|e| SubdivError::Optimizer {
            message: e.to_string(),
        })?;
    res.state()
        .get_best_param()
        .copied()
        .ok_or_else(|| SubdivError::Optimizer {
            message: "no parameter returned".into(),
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_rule_and_inactive_levels_give_one_half() {
        let p = [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 3.0),
            Vector2::new(4.0, 0.0),
        ];
        assert_eq!(
            SplitRule::Fixed.choose(&p, 0, Branch::Searching).unwrap().t,
            0.5
        );
        let c = SplitRule::flatness()
            .choose(&p, 3, Branch::Searching)
            .unwrap();
        assert_eq!((c.t, c.evaluations), (0.5, 0));
        let c = SplitRule::flatness()
            .choose(&p, 0, Branch::Searching)
            .unwrap();
        assert_eq!(c.evaluations, 13);
    }

    #[test]
    fn adaptive_levels_optimize_until_the_optimum_is_near_one_half() {
        let rule = SplitRule::Optimal {
            objective: Objective::Flatness,
            search: Search::Grid,
            levels: Levels::Adaptive,
        };
        // Lopsided: the flatness optimum is far from ½ and the search goes on at any depth.
        let lopsided = [
            Vector2::new(0.0, 0.0),
            Vector2::new(0.2, 4.0),
            Vector2::new(0.4, 0.0),
            Vector2::new(6.0, 0.0),
        ];
        let c = rule.choose(&lopsided, 10, Branch::Searching).unwrap();
        assert!(
            (c.t - 0.5).abs() > ADAPTIVE_BAND && c.next == Branch::Searching,
            "{c:?}"
        );
        // Symmetric: the optimum is ½ (Property 2.2), so the descendants stop searching.
        let symmetric = [
            Vector2::new(0.0, 0.0),
            Vector2::new(1.0, 3.0),
            Vector2::new(3.0, 3.0),
            Vector2::new(4.0, 0.0),
        ];
        let c = rule.choose(&symmetric, 0, Branch::Searching).unwrap();
        assert!(c.t == 0.5 && c.next == Branch::Settled, "{c:?}");
        let c = rule.choose(&lopsided, 0, Branch::Settled).unwrap();
        assert_eq!((c.t, c.evaluations), (0.5, 0));
    }
}
