//! The paper's examples with exact solutions.
