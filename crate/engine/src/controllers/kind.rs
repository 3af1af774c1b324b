//! The controller families a user can pick by name, their parameter-count formulas, and
//! the factory that builds one for a topology.

use super::any_body::{any_body_len, AnyBody};
use super::local_inputs::LocalInputs;
use super::params::check_genes;
use super::{Attention, Controller, Mlp, MlpComm, SlowAttention, Topology};
use crate::{Error, Result};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// A controller family, named in run files and on the command line
/// (`attention`, `mlp`, `mlp-comm`, `slow-attention`, `mlp-comm-latched`, and the
/// body-independent `attention-any`, `mlp-any`, `mlp-comm-any`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ControllerKind {
    /// Local self-attention (SPEC 7): 32 + 4n + 1 parameters.
    Attention,
    /// Communication-less MLP baseline: 4n + 1 parameters.
    Mlp,
    /// Message-passing MLP baseline: (8n + 1) x 5 parameters.
    MlpComm,
    /// Attention with a slowly updated matrix: 32 + 4n + 1 + 2 parameters.
    SlowAttention,
    /// MLP-Comm exchanging messages only when the actuation is latched (every 20 steps), as
    /// the original code does; same genome as `MlpComm`.
    MlpCommLatched,
    /// Attention for any body: the attention block, a bias and each voxel's four weights
    /// computed from its local inputs (`any_body`): 53 parameters for every body.
    AttentionAny,
    /// MLP for any body (no messages): 21 parameters for every body.
    MlpAny,
    /// MLP-Comm for any body (messages are the only difference from `mlp-any`): 205.
    MlpCommAny,
}

impl ControllerKind {
    /// Every kind, in the order used for help texts.
    pub const ALL: [ControllerKind; 8] = [
        ControllerKind::Attention,
        ControllerKind::Mlp,
        ControllerKind::MlpComm,
        ControllerKind::SlowAttention,
        ControllerKind::MlpCommLatched,
        ControllerKind::AttentionAny,
        ControllerKind::MlpAny,
        ControllerKind::MlpCommAny,
    ];

    /// The name accepted by `FromStr` and printed by `Display`.
    pub fn name(self) -> &'static str {
        match self {
            ControllerKind::Attention => "attention",
            ControllerKind::Mlp => "mlp",
            ControllerKind::MlpComm => "mlp-comm",
            ControllerKind::SlowAttention => "slow-attention",
            ControllerKind::MlpCommLatched => "mlp-comm-latched",
            ControllerKind::AttentionAny => "attention-any",
            ControllerKind::MlpAny => "mlp-any",
            ControllerKind::MlpCommAny => "mlp-comm-any",
        }
    }

    /// For a body-independent family, the classic family whose network it runs (its
    /// per-voxel genes computed from local inputs); `None` for the classic families.
    pub fn any_body_of(self) -> Option<ControllerKind> {
        match self {
            ControllerKind::AttentionAny => Some(ControllerKind::Attention),
            ControllerKind::MlpAny => Some(ControllerKind::Mlp),
            ControllerKind::MlpCommAny => Some(ControllerKind::MlpComm),
            _ => None,
        }
    }

    /// True when one genome drives every body (the genome length does not depend on it).
    pub fn is_body_independent(self) -> bool {
        self.any_body_of().is_some()
    }

    /// True when the family has the paper's attention block first in its genome.
    pub fn has_attention(self) -> bool {
        matches!(
            self,
            ControllerKind::Attention
                | ControllerKind::SlowAttention
                | ControllerKind::AttentionAny
        )
    }

    /// Genome length for a robot of `n_voxels` voxels (73 / 41 / 405 / 75 for the biped;
    /// 53 / 21 / 205 for every body, body-independent).
    pub fn param_count(self, n_voxels: usize) -> usize {
        match self {
            ControllerKind::Attention => Attention::param_count_for(n_voxels),
            ControllerKind::Mlp => Mlp::param_count_for(n_voxels),
            ControllerKind::MlpComm | ControllerKind::MlpCommLatched => {
                MlpComm::param_count_for(n_voxels)
            }
            ControllerKind::SlowAttention => SlowAttention::param_count_for(n_voxels),
            ControllerKind::AttentionAny | ControllerKind::MlpAny | ControllerKind::MlpCommAny => {
                self.any_body_of().map_or(0, any_body_len)
            }
        }
    }

    /// The one genome check: `genome` (named `what` in messages, e.g. "the best genome")
    /// must have exactly this family's length for `n_voxels` voxels, and only finite genes.
    pub fn check_genome(self, what: &str, n_voxels: usize, genome: &[f32]) -> Result<()> {
        let whose = format!("the {self} controller of a {n_voxels}-voxel robot");
        check_genes(what, &whose, self.param_count(n_voxels), genome)
    }
}

impl fmt::Display for ControllerKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ControllerKind {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        let wanted = s.trim().to_ascii_lowercase();
        Self::ALL
            .into_iter()
            .find(|k| k.name() == wanted)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|k| k.name()).collect();
                Error::Input(format!(
                    "unknown controller '{s}', expected one of: {}",
                    names.join(", ")
                ))
            })
    }
}

/// Builds a controller of `kind` for `topology`, with every parameter at zero.
pub fn build(kind: ControllerKind, topology: &Topology) -> Box<dyn Controller> {
    let n = topology.voxel_count();
    match kind {
        ControllerKind::Attention => Box::new(Attention::new(n)),
        ControllerKind::Mlp => Box::new(Mlp::new(n)),
        ControllerKind::MlpComm => Box::new(MlpComm::new(topology.clone())),
        ControllerKind::SlowAttention => Box::new(SlowAttention::new(n)),
        ControllerKind::MlpCommLatched => Box::new(MlpComm::latched(topology.clone())),
        ControllerKind::AttentionAny | ControllerKind::MlpAny | ControllerKind::MlpCommAny => {
            let classic = kind.any_body_of().unwrap_or(ControllerKind::Attention);
            Box::new(AnyBody::new(classic, topology, LocalInputs::CHOSEN))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_list_the_choices() {
        for k in ControllerKind::ALL {
            assert_eq!(k.to_string().parse::<ControllerKind>().unwrap(), k);
        }
        let err = "transformer"
            .parse::<ControllerKind>()
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("mlp-comm") && err.contains("slow-attention"),
            "{err}"
        );
    }

    #[test]
    fn serde_uses_the_same_names() {
        let json = serde_json::to_string(&ControllerKind::MlpComm).unwrap();
        assert_eq!(json, "\"mlp-comm\"");
        let back: ControllerKind = serde_json::from_str("\"slow-attention\"").unwrap();
        assert_eq!(back, ControllerKind::SlowAttention);
    }

    #[test]
    fn stateful_controllers_say_so_and_only_attention_exposes_matrices() {
        let t = Topology::isolated(3);
        let flags: Vec<(bool, bool)> = ControllerKind::ALL
            .iter()
            .map(|&k| {
                let c = build(k, &t);
                (c.needs_every_step(), c.attention().is_some())
            })
            .collect();
        // attention, mlp, mlp-comm, slow-attention, mlp-comm-latched, and the any-body three
        assert_eq!(
            flags,
            [
                (false, true),
                (false, false),
                (true, false),
                (true, true),
                (false, false),
                (false, true),
                (false, false),
                (true, false)
            ]
        );
    }
}
