//! Campaigns: a study (shapes x controllers x seeds x budgets, fine-tuning pairs, the
//! assessments of every run) written as one TOML file, turned into a job list (`plan`: each job
//! a task as data, the file it writes and the files it needs), the campaign's outputs turned
//! into a table (`merge`) and its best modules chosen for `pretrained/` (`export`). The command
//! line reads and writes the files and turns each job into a `vsr` command.

pub mod any_body;
pub mod codesign;
pub mod export;
pub mod file;
pub mod from_module;
pub mod groups;
pub mod job;
pub mod merge;
pub mod plan;
pub mod results;
pub mod run_spec;

pub use codesign::CodesignGroup;
pub use file::Campaign;
pub use job::{select, CodesignTask, Job, RunTask, Task, TrainOnBodies};
pub use plan::{earlier_runs, fidelity_path, known_runs, plan, runs, RunSpec};
pub use results::{AnyBodyData, AnyBodySpec, Results, RunData};
