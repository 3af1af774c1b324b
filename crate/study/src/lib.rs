//! The study tooling, native only (the wasm build does not compile it): campaigns (a study as
//! one TOML file, turned into jobs as data, their outputs merged into a table and exported to
//! `pretrained/`), the simulator's fidelity to the reference's gait ensembles, the report
//! (statistics as Markdown, figures as data to draw) and the statistics it uses. No I/O here
//! either: the command line reads and writes the files, turns jobs into command lines and runs
//! them.

pub mod campaign;
pub mod fidelity;
pub mod report;
pub mod statistics;
