//! The arch volume element the world tests place on the ground (Becher's Double Arch idea):
//! `strata::volume::pipeline::scenes::arch_element`, shared with `strata bench serve`.

#[allow(unused_imports)] // Each test binary uses its own subset.
pub use strata::volume::pipeline::scenes::arch_element;
