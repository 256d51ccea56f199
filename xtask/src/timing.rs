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
    let start = Instant::now();
    best_by(runs, rounds, round_micros, || {
        start.elapsed().as_secs_f64() * 1e6
    })
}

/// [`best_micros`] in CPU time of the calling thread (µs, from `/proc/thread-self/schedstat` on
/// Linux), which leaves out the time the thread waits for a core on a machine busier than its
/// cores; wall-clock time where that file cannot be read. Returns the times and whether they are
/// CPU times.
pub(crate) fn best_cpu_micros(
    runs: &mut [Run<'_>],
    rounds: usize,
    round_micros: f64,
) -> Result<(Vec<f64>, bool), DynError> {
    if thread_cpu_micros().is_some() {
        let clock = || thread_cpu_micros().unwrap_or(f64::NAN);
        Ok((best_by(runs, rounds, round_micros, clock)?, true))
    } else {
        Ok((best_micros(runs, rounds, round_micros)?, false))
    }
}

/// CPU time of the calling thread in µs (the first field of `/proc/thread-self/schedstat`, in
/// ns), if the system provides it.
fn thread_cpu_micros() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: u64 = stat.split_whitespace().next()?.parse().ok()?;
    Some(ns as f64 / 1e3)
}

/// [`best_micros`] with `clock` (µs from any origin) as the time.
fn best_by(
    runs: &mut [Run<'_>],
    rounds: usize,
    round_micros: f64,
    clock: impl Fn() -> f64,
) -> Result<Vec<f64>, DynError> {
    let mut calls = Vec::with_capacity(runs.len());
    for run in runs.iter_mut() {
        // The calls per round from one call's wall-clock time: a thread's CPU time may not
        // advance over one short call (it is updated at scheduler events), which would ask for
        // the most calls per round (a run of a few ms then took hours).
        let start = Instant::now();
        run()?;
        let once = start.elapsed().as_secs_f64() * 1e6;
        // Saturating float-to-integer conversion: at least one call, at most about 1e6.
        calls.push((round_micros / once.max(1e-3)).ceil().clamp(1.0, 1e6) as usize);
    }
    let mut best = vec![f64::INFINITY; runs.len()];
    for _ in 0..rounds {
        for ((run, &n), best) in runs.iter_mut().zip(&calls).zip(&mut best) {
            let start = clock();
            for _ in 0..n {
                black_box(run()?);
            }
            // A clock that did not advance (a thread's CPU time is only updated at scheduler
            // events) says nothing about the round.
            let t = (clock() - start) / n as f64;
            if t > 0.0 {
                *best = best.min(t);
            }
        }
    }
    if best.iter().any(|b| !b.is_finite()) {
        return Err("the clock did not advance over any round of a run".into());
    }
    Ok(best)
}
