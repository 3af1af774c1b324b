//! A body-and-brain genome: a [`BodyGrid`] and genes laid out per grid cell, so that genes
//! follow voxels by grid position (the walking edit's rule made the genome's layout). The
//! genes are the controller's shared genes once (attention's 32-gene block, the bias; the
//! MLP-Comm rows' biases), then each cell's own genes in cell order, whether or not the cell
//! holds a voxel: a cell that becomes a voxel brings its genes, a removed voxel's genes stay
//! dormant for a later return.

use super::body::BodyGrid;
use super::config::CodesignConfig;
use crate::controllers::{ControllerKind, GenomeLayout};
use crate::error::Result;
use crate::random::standard_normal;
use crate::simulation::Shape;
use rand::Rng;
use serde::{Deserialize, Serialize};

/// A body and its genes; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Design {
    /// The body in its grid.
    pub body: BodyGrid,
    /// Shared genes, then every cell's genes in cell order.
    #[serde(deserialize_with = "crate::experiment::json::finite_genes")]
    pub genes: Vec<f32>,
}

/// A uniform index in `0..len`, over `u32` so 64-bit hosts and wasm32 draw the same.
fn pick(rng: &mut impl Rng, len: usize) -> usize {
    rng.gen_range(0..u32::try_from(len).unwrap_or(u32::MAX)) as usize
}

impl Design {
    /// The start of a search: the start body in the grid, its genes from the module where it
    /// has them (its shared genes; each voxel's genes when the start body is the module's own),
    /// every other gene drawn uniformly from `rng` (shared genes first, then cell by cell).
    pub(crate) fn start(config: &CodesignConfig, rng: &mut impl Rng) -> Result<Design> {
        let layout = GenomeLayout::of(config.controller);
        let body = BodyGrid::place(&config.start, config.grid_width, config.grid_height)?;
        let cells = config.grid_width * config.grid_height;
        let (low, high) = (config.init_low, config.init_high);
        let len = layout.shared_len() + cells * layout.voxel_len();
        let mut genes: Vec<f32> = (0..len)
            .map(|_| low + (high - low) * rng.gen::<f32>())
            .collect();
        if let Some(module) = &config.module {
            let n = module.shape.voxel_count();
            let (shared, voxels) = layout.split(n, &module.genome);
            genes[..shared.len()].copy_from_slice(&shared);
            if module.shape == config.start {
                for (c, own) in body.voxel_cells().into_iter().zip(&voxels) {
                    let at = layout.shared_len() + c * layout.voxel_len();
                    genes[at..at + own.len()].copy_from_slice(own);
                }
            }
        }
        Ok(Design { body, genes })
    }

    /// The robot this design drives.
    pub fn shape(&self) -> Result<Shape> {
        self.body.shape()
    }

    /// The controller genome for [`Design::shape`], in `kind`'s documented layout.
    pub fn controller_genome(&self, kind: ControllerKind) -> Vec<f32> {
        let layout = GenomeLayout::of(kind);
        let (shared, cells) = self.genes.split_at(layout.shared_len());
        let v = layout.voxel_len();
        let voxels: Vec<&[f32]> = self
            .body
            .voxel_cells()
            .into_iter()
            .map(|c| &cells[c * v..(c + 1) * v])
            .collect();
        layout.assemble(shared, &voxels)
    }

    /// A child: with probability `p_body` one body edit (add a voxel beside the body or remove
    /// one that splits nothing, each half the time, the other when one is impossible under
    /// the voxel bounds), otherwise a Gaussian mutation of every gene in use (the shared genes
    /// past the frozen block, and the voxels' own genes; dormant genes are left as they are).
    /// When no gene evolves ([`CodesignConfig::bodies_only`]: a brain for any body, frozen
    /// whole) every child is a body edit, `p_body` unused (the parent's body again when no
    /// edit is possible).
    pub(crate) fn vary(&self, config: &CodesignConfig, rng: &mut impl Rng) -> Design {
        if config.bodies_only() {
            return Design {
                body: self
                    .edit_body(config, rng)
                    .unwrap_or_else(|| self.body.clone()),
                genes: self.genes.clone(),
            };
        }
        if rng.gen::<f64>() < config.p_body {
            if let Some(body) = self.edit_body(config, rng) {
                return Design {
                    body,
                    genes: self.genes.clone(),
                };
            }
        }
        self.mutate(config, rng)
    }

    fn edit_body(&self, config: &CodesignConfig, rng: &mut impl Rng) -> Option<BodyGrid> {
        let n = self.body.voxel_count();
        let addable = if n < config.max_voxels {
            self.body.addable()
        } else {
            Vec::new()
        };
        let removable = if n > config.min_voxels {
            self.body.removable()
        } else {
            Vec::new()
        };
        let add = match (addable.is_empty(), removable.is_empty()) {
            (true, true) => return None,
            (false, true) => true,
            (true, false) => false,
            (false, false) => rng.gen::<bool>(),
        };
        Some(if add {
            self.body.with(addable[pick(rng, addable.len())], true)
        } else {
            self.body.with(removable[pick(rng, removable.len())], false)
        })
    }

    fn mutate(&self, config: &CodesignConfig, rng: &mut impl Rng) -> Design {
        let layout = GenomeLayout::of(config.controller);
        let mut genes = self.genes.clone();
        let sigma = f64::from(config.sigma);
        let v = layout.voxel_len();
        let voxel_genes = self
            .body
            .voxel_cells()
            .into_iter()
            .flat_map(|c| layout.shared_len() + c * v..layout.shared_len() + (c + 1) * v);
        for g in (config.frozen_shared()..layout.shared_len()).chain(voxel_genes) {
            genes[g] = (f64::from(genes[g]) + sigma * standard_normal(rng)) as f32;
        }
        Design {
            body: self.body.clone(),
            genes,
        }
    }

    /// Whether the design fits `config`: a connected body within the voxel bounds in the
    /// grid, as many genes as the layout needs, and the module's frozen genes unchanged (its
    /// attention block, or a brain for any body frozen whole).
    pub(crate) fn check(&self, config: &CodesignConfig) -> Result<()> {
        let layout = GenomeLayout::of(config.controller);
        let cells = config.grid_width * config.grid_height;
        let bad = |m: String| Err(crate::error::Error::Input(m));
        if self.body.width() != config.grid_width || self.body.height() != config.grid_height {
            return bad(format!(
                "a body is {} x {} cells, the search grid {} x {}",
                self.body.width(),
                self.body.height(),
                config.grid_width,
                config.grid_height
            ));
        }
        if self.genes.len() != layout.shared_len() + cells * layout.voxel_len() {
            return bad(format!(
                "a design has {} genes, the layout needs {}",
                self.genes.len(),
                layout.shared_len() + cells * layout.voxel_len()
            ));
        }
        let n = self.body.voxel_count();
        if n < config.min_voxels || n > config.max_voxels {
            return bad(format!(
                "a body has {n} voxels, outside {} to {}",
                config.min_voxels, config.max_voxels
            ));
        }
        let k = config.frozen_shared();
        if let (true, Some(module)) = (k > 0, &config.module) {
            if self.genes[..k] != module.genome[..k] {
                return bad(if config.bodies_only() {
                    "a design's genes differ from the frozen module's (a brain for any body, \
                     kept whole)"
                        .into()
                } else {
                    "a design's attention block differs from the frozen module's".into()
                });
            }
        }
        self.shape().map(|_| ())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::codesign::BrainMode;
    use crate::experiment::config::SourceRun;
    use crate::random::rng_from;

    fn module() -> SourceRun {
        let kind = ControllerKind::Attention;
        let shape = Shape::parse("biped-4x3").unwrap();
        SourceRun {
            genome: (0..kind.param_count(10))
                .map(|g| g as f32 / 100.0)
                .collect(),
            shape,
            controller: kind,
            seed: 1,
            budget_evals: 100,
            fitness: 1.0,
        }
    }

    #[test]
    fn thousands_of_variations_stay_connected_within_bounds_and_frozen() {
        let m = module();
        let mut config = CodesignConfig::new(
            BrainMode::Frozen,
            ControllerKind::Attention,
            Some(m.clone()),
            m.shape.clone(),
            100,
            3,
        );
        (config.min_voxels, config.max_voxels) = (4, 14);
        (config.grid_width, config.grid_height) = (8, 5);
        let mut rng = rng_from(11);
        let start = Design::start(&config, &mut rng).unwrap();
        assert_eq!(
            start.controller_genome(config.controller),
            m.genome,
            "the module on its own body"
        );
        let mut pool = vec![start];
        let mut sizes = std::collections::BTreeSet::new();
        for step in 0..6000 {
            let parent = &pool[rng.gen_range(0..pool.len())];
            let child = parent.vary(&config, &mut rng);
            child
                .check(&config)
                .unwrap_or_else(|e| panic!("step {step}: {e}"));
            assert!(child.body.is_connected());
            sizes.insert(child.body.voxel_count());
            if pool.len() < 50 {
                pool.push(child);
            } else {
                let i = rng.gen_range(0..pool.len());
                pool[i] = child;
            }
        }
        assert_eq!(sizes.first(), Some(&4), "reaches the minimum: {sizes:?}");
        assert_eq!(sizes.last(), Some(&14), "reaches the maximum: {sizes:?}");
    }

    #[test]
    fn genes_follow_their_cells_through_a_removal_and_a_return() {
        let config = CodesignConfig::new(
            BrainMode::Scratch,
            ControllerKind::Mlp,
            None,
            Shape::parse("box-3x3").unwrap(),
            100,
            1,
        );
        let start = Design::start(&config, &mut rng_from(1)).unwrap();
        let c = start.body.removable()[0];
        let without = Design {
            body: start.body.with(c, false),
            genes: start.genes.clone(),
        };
        let back = Design {
            body: without.body.with(c, true),
            genes: without.genes.clone(),
        };
        assert_eq!(
            back.controller_genome(config.controller),
            start.controller_genome(config.controller)
        );
        assert_eq!(
            without.controller_genome(config.controller).len(),
            ControllerKind::Mlp.param_count(8)
        );
    }

    fn any_body_module() -> SourceRun {
        let kind = ControllerKind::AttentionAny;
        SourceRun {
            genome: (0..kind.param_count(0))
                .map(|g| g as f32 / 50.0 - 0.5)
                .collect(),
            shape: Shape::parse("biped-4x3").unwrap(),
            controller: kind,
            seed: 1,
            budget_evals: 100,
            fitness: 1.0,
        }
    }

    #[test]
    fn a_brain_for_any_body_frozen_changes_only_bodies_and_fine_tuned_keeps_its_attention() {
        let m = any_body_module();
        let frozen = CodesignConfig::with_module(
            BrainMode::Frozen,
            Some(m.clone()),
            ControllerKind::Mlp,
            Some("box-3x3"),
            100,
            2,
        )
        .unwrap();
        assert_eq!(
            frozen.controller,
            ControllerKind::AttentionAny,
            "the module's family"
        );
        assert!(frozen.bodies_only());
        assert_eq!(frozen.frozen_shared(), m.genome.len());
        let mut rng = rng_from(5);
        let parent = Design::start(&frozen, &mut rng).unwrap();
        assert_eq!(parent.genes, m.genome, "the whole genome, no gene per cell");
        let mut bodies = std::collections::BTreeSet::new();
        for _ in 0..200 {
            let child = parent.vary(&frozen, &mut rng);
            child.check(&frozen).unwrap();
            assert_eq!(child.genes, m.genome);
            assert_eq!(child.controller_genome(frozen.controller), m.genome);
            assert_ne!(child.body, parent.body, "every child is a body edit");
            bodies.insert(child.shape().unwrap().to_rows());
        }
        assert!(bodies.len() > 5, "{bodies:?}");

        let finetune = CodesignConfig {
            brain: BrainMode::Finetune,
            ..frozen.clone()
        };
        assert!(!finetune.bodies_only());
        assert_eq!(finetune.frozen_shared(), 32);
        let child = parent.mutate(&finetune, &mut rng);
        child.check(&finetune).unwrap();
        assert_eq!(
            child.genes[..32],
            m.genome[..32],
            "the attention block held"
        );
        assert!(child.genes[32..]
            .iter()
            .zip(&m.genome[32..])
            .all(|(a, b)| a != b));
        let mut moved = child.clone();
        moved.genes[3] += 1.0;
        let err = moved.check(&finetune).unwrap_err().to_string();
        assert!(err.contains("attention block differs"), "{err}");
        let err = moved.check(&frozen).unwrap_err().to_string();
        assert!(err.contains("kept whole"), "{err}");
    }
}
