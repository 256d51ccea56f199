//! Integration tests of lambda-bezier: exact-arithmetic oracles, property tests of the basis and
//! the curves, and serialization.

mod bezier_form;
mod exact;
mod properties;
mod serialization;
