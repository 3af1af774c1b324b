//! The one look of each kind of series in every figure (the only place colours are chosen):
//! a controller has the same colour in every curve and box plot, and so have a frozen and
//! a fine-tuned module. Colours from the Okabe-Ito palette (Okabe and Ito 2008), safe for
//! the common colour-vision deficiencies; series that are no brain (alpha and eta, the
//! reference physics) are grey, so that none is mistaken for a controller.

use plotters::style::RGBColor;
use vsr::controllers::ControllerKind;
use vsr_study::report::figures::Role;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// Its colour (lines, band fill, box, dots).
    pub colour: RGBColor,
    /// A dashed line (a frozen controller other than attention, beside frozen attention).
    pub dashed: bool,
}

const BLUE: RGBColor = RGBColor(0, 114, 178);
const SKY_BLUE: RGBColor = RGBColor(86, 180, 233);
const VERMILLION: RGBColor = RGBColor(213, 94, 0);
const BLUISH_GREEN: RGBColor = RGBColor(0, 158, 115);
const REDDISH_PURPLE: RGBColor = RGBColor(204, 121, 167);
const ORANGE: RGBColor = RGBColor(230, 159, 0);
const BLACK: RGBColor = RGBColor(0, 0, 0);
/// The brains for any body: a darker shade of their classic family's colour (the palette has
/// no more hues that are not taken).
const DARK_BLUE: RGBColor = RGBColor(0, 68, 106);
const DARK_VERMILLION: RGBColor = RGBColor(128, 56, 0);
const DARK_BLUISH_GREEN: RGBColor = RGBColor(0, 95, 69);

/// The greys of series that are no brain, in the order they come in a figure.
const GREYS: [RGBColor; 2] = [RGBColor(80, 80, 80), RGBColor(150, 150, 150)];

/// The look of a series of `role`; `other` is its place among the figure's series of
/// role `Other`.
pub fn look(role: Role, other: usize) -> Look {
    let colour = match role {
        Role::Controller(kind) => match kind {
            ControllerKind::Attention => BLUE,
            ControllerKind::SlowAttention => SKY_BLUE,
            ControllerKind::Mlp => VERMILLION,
            ControllerKind::MlpComm => BLUISH_GREEN,
            ControllerKind::MlpCommLatched => REDDISH_PURPLE,
            ControllerKind::AttentionAny => DARK_BLUE,
            ControllerKind::MlpAny => DARK_VERMILLION,
            ControllerKind::MlpCommAny => DARK_BLUISH_GREEN,
        },
        Role::Frozen(_) => BLACK,
        Role::FineTuned => ORANGE,
        Role::Other => GREYS[other % GREYS.len()],
    };
    let dashed = matches!(role, Role::Frozen(kind) if kind != ControllerKind::Attention);
    Look { colour, dashed }
}

/// The look of each of `roles`, in order (series of role `Other` numbered among themselves).
pub fn looks(roles: impl Iterator<Item = Role>) -> Vec<Look> {
    let mut others = 0;
    roles
        .map(|role| {
            let l = look(role, others);
            others += usize::from(role == Role::Other);
            l
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_controller_and_variant_has_its_own_colour() {
        let mut roles: Vec<Role> = ControllerKind::ALL.map(Role::Controller).to_vec();
        roles.extend([Role::Frozen(ControllerKind::Attention), Role::FineTuned]);
        let colours: Vec<RGBColor> = roles.iter().map(|&r| look(r, 0).colour).collect();
        for (i, c) in colours.iter().enumerate() {
            assert!(!colours[..i].contains(c), "{:?} shares a colour", roles[i]);
            assert!(!GREYS.contains(c), "{:?} is grey", roles[i]);
        }
    }

    #[test]
    fn other_series_take_the_greys_in_turn() {
        let roles = [Role::Other, Role::FineTuned, Role::Other];
        let l = looks(roles.into_iter());
        assert_eq!((l[0].colour, l[2].colour), (GREYS[0], GREYS[1]));
    }
}
