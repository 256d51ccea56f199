//! Interleaved in-process timing, for the speed columns the tables report (never check).
//!
//! Single timings on a shared 2-core machine move by 20–30 % between runs. Here every round
//! calls each run in turn for about the same wall time, and a run's time is its fastest round:
//! all runs see the same load, and the minimum discards the rounds a busy machine slowed down.

use std::hint::black_box;
use std::time::Instant;

use crate::DynError;

/// A timed operation; its result is discarded after `black_box`.
pub(crate) type Run<'a> = Box<dyn FnMut() -> Result<(), DynError> + 'a>;

/// Time of one call in µs for each of `runs`, over `rounds` rounds of about `round_micros` µs
/// of calls per run (at least one call; the call count comes from one untimed warm-up call).
pub(crate) fn best_micros(
    runs: &mut [Run<'_>],
    rounds: usize,
    round_micros: f64,
) -> Result<Vec<f64>, DynError> {
    let mut calls = Vec::with_capacity(runs.len());
    for run in runs.iter_mut() {
        let start = Instant::now();
        run()?;
        let once = start.elapsed().as_secs_f64() * 1e6;
        // Saturating float-to-integer conversion: at least one call, at most about 1e6.
        calls.push((round_micros / once.max(1e-3)).ceil().clamp(1.0, 1e6) as usize);
    }
    let mut best = vec![f64::INFINITY; runs.len()];
    for _ in 0..rounds {
        for ((run, &n), best) in runs.iter_mut().zip(&calls).zip(&mut best) {
            let start = Instant::now();
            for _ in 0..n {
                black_box(run()?);
            }
            *best = best.min(start.elapsed().as_secs_f64() * 1e6 / n as f64);
        }
    }
    Ok(best)
}
