//! Body-independent brains: one genome that drives any body ("attention, any body",
//! "MLP, any body", "MLP-Comm, any body"; `attention-any`, `mlp-any`, `mlp-comm-any`).
//!
//! A classic family's genome holds shared genes and, for each voxel, its own genes tied to
//! the voxel's index (attention: four downstream weights per voxel), so its length depends on
//! the body and a new body needs new genes. A body-independent family keeps the classic
//! network and computes each voxel's own genes from what the voxel knows of its place, its
//! [local inputs](super::local_inputs) f (5 floats: a constant and which of its four
//! neighbours exist), through one matrix G that every voxel shares:
//! gene q of voxel i = sum_k G[q][k] f_i[k]. Nothing else changes: the attention family still
//! sends no messages, MLP-Comm's messages are still the only difference from MLP, and a
//! voxel whose local inputs equal another's runs exactly its brain.
//!
//! Genome layout (the same length for every body):
//! - first the classic family's shared genes, in [`GenomeLayout::split`] order: attention,
//!   the 32-gene attention block then the downstream bias (33); MLP, the bias (1); MLP-Comm,
//!   each output's bias (5);
//! - then G: one row of 5 genes (one per local input) for each of the classic family's
//!   per-voxel genes
//!   (attention: row r gives W[r n + i], the weight of attended reading r; MLP: row j gives the
//!   weight of reading j; MLP-Comm: row 8 o + j gives the weight from input j to output o).
//!
//! Lengths: attention-any 33 + 4 x 5 = 53, mlp-any 1 + 4 x 5 = 21, mlp-comm-any 5 + 40 x 5 =
//! 205. The attention block comes first, as in the classic genome, so it transfers the same way.

use super::local_inputs::{local_inputs, LocalInputs};
use super::params::check_genes;
use super::{build, Controller, ControllerKind, GenomeLayout, Params, Topology};
use crate::Result;

/// Genome length of the body-independent version of `classic` reading `which`.
pub(crate) fn any_body_len_with(classic: ControllerKind, which: LocalInputs) -> usize {
    let layout = GenomeLayout::of(classic);
    layout.shared_len() + layout.voxel_len() * which.width()
}

/// Genome length of the body-independent version of `classic` (the families' inputs).
pub(crate) fn any_body_len(classic: ControllerKind) -> usize {
    any_body_len_with(classic, LocalInputs::CHOSEN)
}

/// The classic genome that `genome` (a body-independent genome of the family built on
/// `classic`) amounts to on a body whose voxels have local inputs `inputs` (all of one width).
pub(crate) fn expand<F: AsRef<[f32]>>(
    classic: ControllerKind,
    genome: &[f32],
    inputs: &[F],
) -> Vec<f32> {
    let layout = GenomeLayout::of(classic);
    let (shared, generator) = genome.split_at(layout.shared_len());
    let width = inputs.first().map_or(1, |f| f.as_ref().len()).max(1);
    let voxels: Vec<Vec<f32>> = inputs
        .iter()
        .map(|f| {
            let f = f.as_ref();
            generator
                .chunks_exact(width)
                .map(|row| row.iter().zip(f).fold(0.0f32, |s, (g, x)| s + g * x))
                .collect()
        })
        .collect();
    let refs: Vec<&[f32]> = voxels.iter().map(Vec::as_slice).collect();
    layout.assemble(shared, &refs)
}

/// A body-independent brain on one body; see the module doc.
pub struct AnyBody {
    classic: ControllerKind,
    inputs: Vec<Vec<f32>>,
    params: Params,
    inner: Box<dyn Controller>,
}

impl AnyBody {
    /// The body-independent version of `classic` for `topology`, reading `which` local
    /// inputs, with every parameter at zero.
    pub(crate) fn new(classic: ControllerKind, topology: &Topology, which: LocalInputs) -> Self {
        AnyBody {
            classic,
            inputs: local_inputs(topology, which),
            params: Params::zeros(any_body_len_with(classic, which)),
            inner: build(classic, topology),
        }
    }

    /// The measurement's layout: all seven inputs per gene, those `which` does not read at 0
    /// (docs/ANALYSIS-PLAN.md, fourth question; `body_set::measure`).
    #[cfg(test)]
    pub(crate) fn masked(classic: ControllerKind, topology: &Topology, which: LocalInputs) -> Self {
        use super::local_inputs::{local_inputs_masked, LOCAL_INPUTS};
        let inputs = local_inputs_masked(topology, which)
            .iter()
            .map(|f| f.to_vec())
            .collect();
        let layout = GenomeLayout::of(classic);
        AnyBody {
            classic,
            inputs,
            params: Params::zeros(layout.shared_len() + layout.voxel_len() * LOCAL_INPUTS),
            inner: build(classic, topology),
        }
    }
}

impl Controller for AnyBody {
    fn genome(&self) -> &Params {
        &self.params
    }

    /// Only for reading: replace the genome with `set_params`, which also sets the network.
    fn genome_mut(&mut self) -> &mut Params {
        &mut self.params
    }

    fn set_params(&mut self, p: &[f32]) -> Result<()> {
        check_genes("the new genome", "this controller", self.params.len(), p)?;
        self.inner
            .set_params(&expand(self.classic, p, &self.inputs))?;
        self.params.set(p)
    }

    fn reset(&mut self) {
        self.inner.reset();
    }

    fn control(&mut self, sensors: &[f32], out: &mut [f32]) {
        self.inner.control(sensors, out);
    }

    fn needs_every_step(&self) -> bool {
        self.inner.needs_every_step()
    }

    fn attention(&self) -> Option<&[f32]> {
        self.inner.attention()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controllers::test_util::random_vec;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    fn biped() -> Topology {
        let cells = [(0, 0), (3, 0), (0, 1), (1, 1), (2, 1), (3, 1)];
        Topology::from_cells(&cells).unwrap()
    }

    #[test]
    fn lengths_do_not_depend_on_the_body() {
        assert_eq!(any_body_len(ControllerKind::Attention), 53);
        assert_eq!(any_body_len(ControllerKind::Mlp), 21);
        assert_eq!(any_body_len(ControllerKind::MlpComm), 205);
    }

    #[test]
    fn a_constant_only_brain_gives_every_voxel_the_same_weights() {
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let genome = random_vec(&mut rng, 37, 1.0);
        let inputs = local_inputs(&biped(), LocalInputs::Constant);
        let classic = expand(ControllerKind::Attention, &genome, &inputs);
        assert_eq!(classic.len(), ControllerKind::Attention.param_count(6));
        assert_eq!(classic[..32], genome[..32], "the attention block is kept");
        assert_eq!(classic.last(), Some(&genome[32]), "the bias is kept");
        for r in 0..4 {
            let row = &classic[32 + 6 * r..32 + 6 * (r + 1)];
            assert!(row.iter().all(|&w| w == genome[33 + r]), "row {r}");
        }
    }

    #[test]
    fn a_voxel_reads_its_weights_from_its_place() {
        let mut genome = vec![0.0f32; 21];
        // Weight of reading 2 (vy): 0.5 plus 2 x (has an up neighbour).
        genome[1 + 2 * 5] = 0.5;
        genome[1 + 2 * 5 + 1] = 2.0;
        let inputs = local_inputs(&biped(), LocalInputs::CHOSEN);
        let classic = expand(ControllerKind::Mlp, &genome, &inputs);
        // MLP layout: W[4 i + j], then the bias. Feet (0, 1) have an up neighbour, the top
        // row (2..6) has none.
        let vy: Vec<f32> = (0..6).map(|i| classic[4 * i + 2]).collect();
        assert_eq!(vy, [2.5, 2.5, 0.5, 0.5, 0.5, 0.5]);
    }

    #[test]
    fn one_genome_drives_bodies_of_any_size() {
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        for classic in [
            ControllerKind::Attention,
            ControllerKind::Mlp,
            ControllerKind::MlpComm,
        ] {
            let genome = random_vec(&mut rng, any_body_len(classic), 1.0);
            for n in [1, 6, 25] {
                let cells: Vec<(i32, i32)> = (0..n).map(|x| (x, 0)).collect();
                let t = Topology::from_cells(&cells).unwrap();
                let mut c = AnyBody::new(classic, &t, LocalInputs::CHOSEN);
                c.set_params(&genome).unwrap();
                let mut out = vec![0.0; n as usize];
                c.control(&random_vec(&mut rng, 4 * n as usize, 1.0), &mut out);
                assert!(out.iter().all(|u| u.is_finite() && u.abs() <= 1.0));
                assert!(out.iter().any(|&u| u != 0.0), "{classic} {n}");
            }
        }
    }

    #[test]
    fn a_bad_genome_is_refused_and_changes_nothing() {
        let mut c = AnyBody::new(ControllerKind::Attention, &biped(), LocalInputs::CHOSEN);
        assert!(c.set_params(&[0.0; 52]).is_err());
        let mut nan = vec![0.0; 53];
        nan[40] = f32::NAN;
        assert!(c.set_params(&nan).is_err());
        assert!(c.genome().iter().all(|&g| g == 0.0));
    }
}
