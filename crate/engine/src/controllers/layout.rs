//! Where each voxel's genes sit in a genome, so a genome can follow its robot when the body
//! changes (the page's "edit while it walks").
//!
//! Every controller family lays its genome out the same way: a `prefix` shared by all voxels
//! (attention's 32 genes), then `rows` rows, each holding `per_voxel` genes per voxel (in
//! voxel index order) followed by `row_tail` shared genes, then a `tail` of shared genes:
//! - attention: 32 | 4 rows of (1 per voxel) | bias            (SPEC 7: W[r n + i], b)
//! - slow attention: the same with 3 tail genes (bias, then alpha and eta genes)
//! - MLP: 1 row of (4 per voxel) | bias                         (W[4 i + j], b)
//! - MLP-Comm: 5 rows of (8 per voxel, then the row's bias)     (P[o (8n + 1) + 8 i + j])
//! - the body-independent families (any_body): the whole genome is shared, so a body change
//!   keeps it as it is

use super::slow::SLOW_GENES;
use super::{ControllerKind, ATTENTION_PARAMS};
use crate::random::rng_from;
use crate::simulation::Shape;
use crate::Result;
use rand::Rng;

/// The layout of one family's genome; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct GenomeLayout {
    prefix: usize,
    rows: usize,
    per_voxel: usize,
    row_tail: usize,
    tail: usize,
}

impl GenomeLayout {
    /// The layout of `kind`'s genome.
    pub(crate) fn of(kind: ControllerKind) -> Self {
        let (prefix, rows, per_voxel, row_tail, tail) = match kind {
            ControllerKind::Attention => (ATTENTION_PARAMS, 4, 1, 0, 1),
            ControllerKind::SlowAttention => (ATTENTION_PARAMS, 4, 1, 0, 1 + SLOW_GENES),
            ControllerKind::Mlp => (0, 1, 4, 0, 1),
            ControllerKind::MlpComm | ControllerKind::MlpCommLatched => (0, 5, 8, 1, 0),
            // One genome for every body: all of it is shared (any_body).
            ControllerKind::AttentionAny | ControllerKind::MlpAny | ControllerKind::MlpCommAny => {
                (kind.param_count(0), 0, 0, 0, 0)
            }
        };
        GenomeLayout {
            prefix,
            rows,
            per_voxel,
            row_tail,
            tail,
        }
    }

    /// Genome length for `n` voxels (equals [`ControllerKind::param_count`]).
    pub(crate) fn len(&self, n: usize) -> usize {
        self.prefix + self.rows * (self.per_voxel * n + self.row_tail) + self.tail
    }

    /// Where gene `k` of voxel `i` in row `r` sits, for `n` voxels.
    fn voxel_gene(&self, n: usize, r: usize, i: usize, k: usize) -> usize {
        self.prefix + r * (self.per_voxel * n + self.row_tail) + i * self.per_voxel + k
    }

    /// Genes shared by every voxel: the prefix, each row's tail, the tail.
    pub(crate) fn shared_len(&self) -> usize {
        self.prefix + self.rows * self.row_tail + self.tail
    }

    /// Genes of one voxel, over all rows.
    pub(crate) fn voxel_len(&self) -> usize {
        self.rows * self.per_voxel
    }

    /// A controller genome for `voxels.len()` voxels from the shared genes (prefix, then each
    /// row's tail in row order, then the tail: [`GenomeLayout::shared_len`]) and each voxel's
    /// own genes (row by row: [`GenomeLayout::voxel_len`]), in voxel index order.
    pub(crate) fn assemble(&self, shared: &[f32], voxels: &[&[f32]]) -> Vec<f32> {
        let n = voxels.len();
        let mut out = vec![0.0f32; self.len(n)];
        out[..self.prefix].copy_from_slice(&shared[..self.prefix]);
        let row_tails = &shared[self.prefix..self.prefix + self.rows * self.row_tail];
        let tail = &shared[self.prefix + self.rows * self.row_tail..];
        for r in 0..self.rows {
            for k in 0..self.row_tail {
                out[self.row_tail_gene(n, r, k)] = row_tails[r * self.row_tail + k];
            }
            for (i, genes) in voxels.iter().enumerate() {
                for k in 0..self.per_voxel {
                    out[self.voxel_gene(n, r, i, k)] = genes[r * self.per_voxel + k];
                }
            }
        }
        let start = out.len() - self.tail;
        out[start..].copy_from_slice(tail);
        out
    }

    /// The inverse of [`GenomeLayout::assemble`] for a genome of `n` voxels: its shared genes
    /// and each voxel's own genes.
    pub(crate) fn split(&self, n: usize, genome: &[f32]) -> (Vec<f32>, Vec<Vec<f32>>) {
        let mut shared = genome[..self.prefix].to_vec();
        for r in 0..self.rows {
            for k in 0..self.row_tail {
                shared.push(genome[self.row_tail_gene(n, r, k)]);
            }
        }
        shared.extend_from_slice(&genome[genome.len() - self.tail..]);
        let voxels = (0..n)
            .map(|i| {
                (0..self.rows)
                    .flat_map(|r| (0..self.per_voxel).map(move |k| (r, k)))
                    .map(|(r, k)| genome[self.voxel_gene(n, r, i, k)])
                    .collect()
            })
            .collect();
        (shared, voxels)
    }

    /// Where shared gene `k` of row `r` sits (its `row_tail`), for `n` voxels.
    fn row_tail_gene(&self, n: usize, r: usize, k: usize) -> usize {
        self.prefix + r * (self.per_voxel * n + self.row_tail) + self.per_voxel * n + k
    }
}

/// Moves `genome` (of a `kind` controller on `from`) onto the body `to`, by grid position:
/// the shared genes are kept, each voxel of `to` whose cell also holds a voxel in `from`
/// keeps that voxel's genes, and the genes of new voxels are drawn uniformly in [-1, 1] from
/// a stream seeded by `seed`, in voxel order. Cell (x, y) of `to` is cell (x + shift.0,
/// y + shift.1) of `from` (a drawing cropped to its cells moves when its left column or
/// bottom row changes). A genome of the wrong length is refused.
pub fn remap_genome(
    kind: ControllerKind,
    genome: &[f32],
    from: &Shape,
    to: &Shape,
    shift: (i64, i64),
    seed: u64,
) -> Result<Vec<f32>> {
    let layout = GenomeLayout::of(kind);
    let (n_from, n_to) = (from.voxel_count(), to.voxel_count());
    kind.check_genome("the genome", n_from, genome)?;
    let mut out = vec![0.0f32; layout.len(n_to)];
    out[..layout.prefix].copy_from_slice(&genome[..layout.prefix]);
    let tail_from = genome.len() - layout.tail;
    let tail_to = out.len() - layout.tail;
    out[tail_to..].copy_from_slice(&genome[tail_from..]);
    let mut rng = rng_from(seed);
    for r in 0..layout.rows {
        for k in 0..layout.row_tail {
            out[layout.row_tail_gene(n_to, r, k)] = genome[layout.row_tail_gene(n_from, r, k)];
        }
    }
    for (j, &(x, y)) in to.voxels().iter().enumerate() {
        let (fx, fy) = (x as i64 + shift.0, y as i64 + shift.1);
        let old = match (usize::try_from(fx), usize::try_from(fy)) {
            (Ok(fx), Ok(fy)) if from.is_filled(fx as i64, fy as i64) => from.index_of(fx, fy),
            _ => None,
        };
        for r in 0..layout.rows {
            for k in 0..layout.per_voxel {
                out[layout.voxel_gene(n_to, r, j, k)] = match old {
                    Some(i) => genome[layout.voxel_gene(n_from, r, i, k)],
                    None => rng.gen_range(-1.0f32..=1.0),
                };
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_lengths_match_the_parameter_counts() {
        for kind in ControllerKind::ALL {
            for n in [1, 10, 11, 37] {
                assert_eq!(
                    GenomeLayout::of(kind).len(n),
                    kind.param_count(n),
                    "{kind} {n}"
                );
            }
        }
    }

    #[test]
    fn remapping_onto_the_same_body_changes_nothing() {
        let biped = Shape::parse("biped-4x3").unwrap();
        for kind in ControllerKind::ALL {
            let genome: Vec<f32> = (0..kind.param_count(10)).map(|g| g as f32).collect();
            let same = remap_genome(kind, &genome, &biped, &biped, (0, 0), 1).unwrap();
            assert_eq!(same, genome, "{kind}");
        }
    }

    #[test]
    fn surviving_voxels_keep_their_genes_and_new_ones_are_drawn() {
        let from = Shape::parse("11-11").unwrap(); // voxels 0 (0,0) 1 (1,0) 2 (0,1) 3 (1,1)
        let to = Shape::parse("110-111").unwrap(); // voxels (0,0) (1,0) (2,0) (0,1) (1,1)
        let kind = ControllerKind::Attention;
        let genome: Vec<f32> = (0..kind.param_count(4)).map(|g| 100.0 + g as f32).collect();
        let out = remap_genome(kind, &genome, &from, &to, (0, 0), 7).unwrap();
        assert_eq!(out.len(), kind.param_count(5));
        assert_eq!(out[..32], genome[..32], "attention block kept");
        assert_eq!(out.last(), genome.last(), "bias kept");
        // Row r of the downstream: old W[32 + 4r + i], new W[32 + 5r + j].
        for r in 0..4 {
            for (j, i) in [(0, 0), (1, 1), (3, 2), (4, 3)] {
                assert_eq!(
                    out[32 + 5 * r + j],
                    genome[32 + 4 * r + i],
                    "row {r} voxel {j}"
                );
            }
            let fresh = out[32 + 5 * r + 2];
            assert!((-1.0..=1.0).contains(&fresh), "new voxel gene {fresh}");
        }
        assert_eq!(
            out,
            remap_genome(kind, &genome, &from, &to, (0, 0), 7).unwrap()
        );
        assert_ne!(
            out,
            remap_genome(kind, &genome, &from, &to, (0, 0), 8).unwrap()
        );
    }

    #[test]
    fn mlp_comm_keeps_each_rows_bias() {
        let from = Shape::parse("1").unwrap();
        let to = Shape::parse("11").unwrap();
        let kind = ControllerKind::MlpComm;
        let genome: Vec<f32> = (0..kind.param_count(1)).map(|g| g as f32).collect();
        let out = remap_genome(kind, &genome, &from, &to, (0, 0), 0).unwrap();
        for o in 0..5 {
            assert_eq!(out[o * 17 + 16], genome[o * 9 + 8], "bias of output {o}");
            assert_eq!(out[o * 17..o * 17 + 8], genome[o * 9..o * 9 + 8]);
        }
    }

    #[test]
    fn a_shift_follows_a_drawing_that_lost_its_left_column() {
        let from = Shape::parse("111").unwrap();
        let to = Shape::parse("11").unwrap(); // the old cells 1 and 2
        let kind = ControllerKind::Mlp;
        let genome: Vec<f32> = (0..kind.param_count(3)).map(|g| g as f32).collect();
        let out = remap_genome(kind, &genome, &from, &to, (1, 0), 0).unwrap();
        assert_eq!(out, [4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0]);
    }

    #[test]
    fn split_and_assemble_are_inverse_for_every_family() {
        for kind in ControllerKind::ALL {
            let layout = GenomeLayout::of(kind);
            for n in [1, 4, 10] {
                let genome: Vec<f32> = (0..kind.param_count(n)).map(|g| g as f32).collect();
                let (shared, voxels) = layout.split(n, &genome);
                assert_eq!(shared.len(), layout.shared_len(), "{kind}");
                assert!(voxels.iter().all(|v| v.len() == layout.voxel_len()));
                let refs: Vec<&[f32]> = voxels.iter().map(Vec::as_slice).collect();
                assert_eq!(layout.assemble(&shared, &refs), genome, "{kind} {n}");
            }
        }
    }

    #[test]
    fn a_wrong_length_is_refused() {
        let biped = Shape::parse("biped-4x3").unwrap();
        let err =
            remap_genome(ControllerKind::Mlp, &[0.0; 3], &biped, &biped, (0, 0), 0).unwrap_err();
        assert!(err.to_string().contains("3 genes"), "{err}");
    }
}
