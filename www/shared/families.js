// @ts-check
/**
 * The brain families the page offers (the core's list: `defaults().controllers`), named for a
 * newcomer, and the two facts about a family the page acts on: whether it has the paper's
 * attention block (so it can be fine-tuned, frozen mid-walk, its a, b, c, d read), and whether
 * one genome drives every body (a brain for any body: `crate/engine/src/controllers/any_body.rs`; it
 * crosses to a new body whole, keeps its genes through every edit, and a body search with it
 * frozen evolves bodies only). No imports: the viewer's worker reads it too.
 */

/** Each family's name in the page's words (the menus, what drives the robot). */
export const FAMILY_NAMES = Object.freeze({
  attention: 'attention',
  mlp: 'mlp',
  'mlp-comm': 'mlp-comm',
  'attention-any': 'attention, any body',
  'mlp-any': 'MLP, any body',
  'mlp-comm-any': 'MLP-Comm, any body',
});

/**
 * What the page says of the study's brain for any body (attention, trained on many bodies) while
 * pretrained/ has none: the module list, the note under the family menu and the tour's chapter
 * about it say it in these words.
 */
export const NOT_YET = 'not yet: the study is still training it';

/** Families whose one genome drives every body (`ControllerKind::is_body_independent`). */
const ANY_BODY = new Set(['attention-any', 'mlp-any', 'mlp-comm-any']);
/** Families with the paper's attention block first in their genome (`ControllerKind::has_attention`). */
const ATTENTION = new Set(['attention', 'slow-attention', 'attention-any']);

/** A family's name in words (its own name when the page has no other). @param {string} kind */
export function familyName(kind) {
  return FAMILY_NAMES[/** @type {keyof typeof FAMILY_NAMES} */ (kind)] ?? kind;
}

/** Whether one genome of `kind` drives every body. @param {string} kind */
export function isAnyBody(kind) {
  return ANY_BODY.has(kind);
}

/** Whether `kind` has the attention block (fine-tuning keeps it; Freeze holds its matrices). @param {string} kind */
export function hasAttention(kind) {
  return ATTENTION.has(kind);
}
