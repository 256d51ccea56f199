//! Experiment definitions shared by tests and xtask.
