//! The one place that composes genome -> controller -> world -> fitness.

pub mod seeds;
