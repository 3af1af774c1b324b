//! A campaign's job list: every run, validation and ablation as one job (data: the command
//! line makes it a `vsr` command) that writes one output file, in dependency order.
//!
//! Output folder layout (under the campaign's output folder):
//! - `runs/STEM.json`: run files; STEM is `SHAPE-CONTROLLER-EVALS-sSEED` from scratch and
//!   `SOURCESHAPE-CONTROLLER-SOURCEEVALS-to-SHAPE-EVALS-sSEED` for fine-tuning;
//! - `validation/STEM.SET.json`: `vsr validate --json` of a run's best on a set;
//! - `ablation/STEM.json`: `vsr ablate --json` of a run's best;
//! - `fidelity/NAME.json`: `vsr fidelity` of the reference file NAME.json (stage 1);
//! - the `[[any_body]]`, `[[codesign]]` and `[[from_module]]` groups' outputs: their modules'
//!   docs.
//!
//! Stages: a run that needs no other run is stage 1; a fine-tuning run (it needs its source
//! run) or a run that continues a shorter one is one stage after the run it needs; a run's
//! validations and ablation are one stage after the run. A job needs only files of earlier
//! stages, so running stage after stage respects every dependency (the paper's study has 3). A run listed twice (the same shape, controller, budget and seed
//! in two groups) is one job. A run from scratch with the same shape, controller and seed as a
//! shorter one (RQ2's 20,000-evaluation sources and 30,000-evaluation runs) continues it: the
//! shorter run keeps its final checkpoint (`--keep-checkpoint`) and the longer starts there
//! (`--continue`), the same run file bit for bit for a third of the work.

use super::file::Campaign;
use super::job::{Job, RunTask, Task};
pub use super::run_spec::RunSpec;
use std::path::{Path, PathBuf};

/// Every run of the campaign, each once, in campaign order: the evolve grids, then for each
/// fine-tuning group its source runs, its scratch runs and its fine-tuning runs.
pub fn runs(c: &Campaign) -> Vec<RunSpec> {
    let mut all: Vec<RunSpec> = Vec::new();
    let mut push = |r: RunSpec| {
        if !all.contains(&r) {
            all.push(r);
        }
    };
    for g in &c.evolve {
        grid(c, g, &g.evals).into_iter().for_each(&mut push);
    }
    for g in &c.finetune {
        for r in finetune_runs(c, g) {
            push(r);
        }
    }
    all
}

/// The runs of every evolve group read at its `earlier` budgets: not run by the campaign,
/// read when their files exist (a shorter run from scratch is the longer run's start).
pub fn earlier_runs(c: &Campaign) -> Vec<RunSpec> {
    c.evolve
        .iter()
        .flat_map(|g| grid(c, g, &g.earlier))
        .collect()
}

/// The runs of the non-inferiority tests' known seeds (`noninferiority.known_seeds`): the
/// treatment's and the control's on every shape and budget of the group; not run by the
/// campaign, read when their files exist (shown beside the test, never pooled).
pub fn known_runs(c: &Campaign) -> Vec<RunSpec> {
    let mut out = Vec::new();
    for g in &c.evolve {
        let Some(n) = &g.noninferiority else {
            continue;
        };
        for shape in &g.shapes {
            for controller in [n.treatment, n.control] {
                for &evals in &g.evals {
                    for &seed in &n.known_seeds {
                        out.push(RunSpec::scratch(shape, controller, evals, seed));
                    }
                }
            }
        }
    }
    out
}

/// An evolve group's grid at `budgets`: shapes x controllers x budgets x seeds.
fn grid(c: &Campaign, g: &super::file::EvolveGroup, budgets: &[u64]) -> Vec<RunSpec> {
    let seeds = g.seeds.as_ref().unwrap_or(&c.seeds);
    let mut out = Vec::new();
    for shape in &g.shapes {
        for &controller in &g.controllers {
            for &evals in budgets {
                for &seed in seeds {
                    out.push(RunSpec::scratch(shape, controller, evals, seed));
                }
            }
        }
    }
    out
}

/// A fine-tuning group's runs: sources, from-scratch comparisons, fine-tunings.
pub fn finetune_runs(c: &Campaign, g: &super::file::FinetuneGroup) -> Vec<RunSpec> {
    let seeds = g.seeds.as_ref().unwrap_or(&c.seeds);
    let mut out = Vec::new();
    for [from, to] in &g.pairs {
        for &seed in seeds {
            let source = RunSpec::scratch(from, g.controller, g.source_evals, seed);
            out.push(source.clone());
            if let Some(evals) = g.scratch_evals {
                out.push(RunSpec::scratch(to, g.controller, evals, seed));
            }
            out.push(RunSpec::finetuned(source, to, g.evals));
        }
    }
    out
}

/// True when some evolve group with `ablate` lists this run (fine-tuning runs are not ablated).
fn ablated(c: &Campaign, r: &RunSpec) -> bool {
    r.source.is_none()
        && r.has_attention()
        && c.evolve.iter().any(|g| {
            g.ablate
                && g.shapes.contains(&r.shape)
                && g.controllers.contains(&r.controller)
                && g.evals.contains(&r.evals)
                && g.seeds.as_ref().unwrap_or(&c.seeds).contains(&r.seed)
        })
}

/// The job list of campaign `c` with outputs under `out`, in dependency order.
pub fn plan(c: &Campaign, out: &Path) -> Vec<Job> {
    let mut jobs = Vec::new();
    let all = runs(c);
    for r in &all {
        let run_path = r.run_path(out);
        let prefix = prefix_of(&all, r);
        let stage = stage_of(&all, r);
        let keep = all.iter().any(|q| prefix_of(&all, q) == Some(r));
        jobs.push(run_job(c, r, out, stage, (prefix, keep)));
        for &set in &c.validate {
            jobs.push(Job::validate(
                stage + 1,
                &run_path,
                set,
                c.seconds,
                r.validation_path(out, set),
            ));
        }
        let sets = if ablated(c, r) {
            &c.ablation.sets[..]
        } else {
            &[]
        };
        for &set in sets {
            jobs.push(Job {
                stage: stage + 1,
                task: Task::Ablate {
                    genome: run_path.clone(),
                    last_second: c.ablation.last_second,
                    terrain: set.first_terrain(),
                    seconds: c.seconds,
                },
                out: r.ablation_path(out, set),
                needs: vec![run_path.clone()],
            });
        }
    }
    for g in &c.fidelity {
        let reference = PathBuf::from(&g.reference);
        jobs.push(Job {
            stage: 1,
            out: fidelity_path(out, &reference),
            task: Task::Fidelity { reference },
            needs: vec![],
        });
    }
    for g in &c.codesign {
        jobs.extend(g.jobs(&c.seeds, c.seconds, &c.terrain, &c.validate, out));
    }
    for g in &c.any_body {
        jobs.extend(g.jobs(&c.seeds, (c.seconds, c.population, &c.terrain), out));
    }
    jobs.extend(super::any_body::floor_jobs(
        &c.any_body,
        &c.seeds,
        c.seconds,
        out,
    ));
    for g in &c.from_module {
        let settings = (c.seconds, c.population, c.terrain.as_str());
        jobs.extend(g.jobs(&c.seeds, settings, &c.validate, out));
    }
    jobs.sort_by_key(|j| j.stage);
    jobs
}

/// The measurement of the reference file `reference` under `out`.
pub fn fidelity_path(out: &Path, reference: &Path) -> PathBuf {
    let name = reference.file_name().unwrap_or(reference.as_os_str());
    out.join("fidelity").join(name)
}

/// The run from scratch that `r` continues: the same shape, controller and seed with the
/// largest smaller budget planned. A run's draws never depend on its budget, so `r` passes
/// through that run's final state and can start from its kept checkpoint.
fn prefix_of<'a>(all: &'a [RunSpec], r: &RunSpec) -> Option<&'a RunSpec> {
    let same = |p: &&RunSpec| {
        p.source.is_none()
            && (&p.shape, p.controller, p.seed) == (&r.shape, r.controller, r.seed)
            && p.evals < r.evals
    };
    if r.source.is_some() {
        return None;
    }
    all.iter().filter(same).max_by_key(|p| p.evals)
}

/// The stage of run `r`'s job: 1 for a run that needs no other run, else one more than the
/// latest run it needs (its source, the shorter run it continues).
fn stage_of(all: &[RunSpec], r: &RunSpec) -> u32 {
    let needs = r.source.as_deref().into_iter().chain(prefix_of(all, r));
    1 + needs.map(|n| stage_of(all, n)).max().unwrap_or(0)
}

/// The evolution or fine-tuning job of run `r`; `prefix` is the run it continues, `keep`
/// says that another run continues it.
fn run_job(
    c: &Campaign,
    r: &RunSpec,
    out: &Path,
    stage: u32,
    (prefix, keep): (Option<&RunSpec>, bool),
) -> Job {
    let from = r.source.as_ref().map(|s| s.run_path(out));
    let continued = prefix.map(|p| p.run_path(out));
    let needs = from.iter().chain(&continued).cloned().collect();
    Job {
        stage,
        task: Task::Run(RunTask {
            from,
            shape: r.shape.clone(),
            controller: r.controller,
            evals: r.evals,
            seed: r.seed,
            seconds: c.seconds,
            population: c.population,
            terrain: c.terrain.clone(),
            keep_checkpoint: keep,
            continue_from: continued.as_deref().map(checkpoint_of),
            bodies: None,
        }),
        out: r.run_path(out),
        needs,
    }
}

/// The checkpoint `vsr evolve` keeps next to the run file `run`.
fn checkpoint_of(run: &Path) -> PathBuf {
    let mut name = run.as_os_str().to_owned();
    name.push(".checkpoint");
    PathBuf::from(name)
}

#[cfg(test)]
pub(crate) mod tests;
