//! Test shapes for the reproduction (placeholder, filled below).
