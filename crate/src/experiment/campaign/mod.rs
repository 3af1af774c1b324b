//! Campaigns: a study (shapes x controllers x seeds x budgets, fine-tuning pairs, the
//! assessments of every run) written as one TOML file, turned into a job list of `vsr`
//! commands (`plan`), and the campaign's outputs turned into a table (`merge`) and a report
//! (`report`, with `figures`). The command line reads and writes the files and runs the jobs.

pub mod export;
pub mod figures;
pub mod file;
pub mod job;
pub mod merge;
pub mod plan;
pub mod report;
pub mod results;

pub use file::Campaign;
pub use job::{select, Job};
pub use plan::{plan, runs, RunSpec};
pub use report::{report, Report};
pub use results::{Results, RunData};
