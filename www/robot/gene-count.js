// @ts-check
/**
 * The gene count under “3 · Give it a brain”: how many numbers evolution tunes for the chosen
 * controller family on the drawn body, and, for attention, which of them every voxel shares
 * and which belong to one voxel position (its glossary words linked). Its raw number is in `data-value`.
 */
import { withTerms } from '../shared/simple-words.js';
import { SENSOR_NAMES } from '../workers/protocol.js';
import { hasAttention, isAnyBody } from '../shared/families.js';

/**
 * @param {HTMLElement} el @param {import('../workers/core.js').ShapeCheck} check the drawing's
 * @param {string} kind the controller family @param {number} attentionGenes the attention block's size
 * @param {string} walking what walks while the drawing is not a robot (its last whole body), in words
 */
export function showGeneCount(el, check, kind, attentionGenes, walking = '') {
  const genes = check.params.find(([k]) => k === kind)?.[1] ?? 0;
  const n = check.voxels;
  const anyBody = isAnyBody(kind);
  const detail = kind === 'attention' && n > 0
    ? `: ${attentionGenes} for the attention block, shared by every voxel, ${genes - attentionGenes - 1} for the outputs, `
      + `one set of weights per voxel position (each voxel adds ${SENSOR_NAMES.length}, one per sensor), and 1 bias shared by every voxel`
    : anyBody && n > 0
      ? `, the same number for any body you draw, all shared by every voxel: ${hasAttention(kind) ? `${attentionGenes} for the attention block, then ` : ''}`
        + 'the genes with which each voxel works out its own weights from what it knows of its place (such as which neighbours it has)'
      : '';
  // A drawing in pieces is counted as drawn, beside the robot that still walks (its last whole body).
  const pending = !check.ok && n > 0 ? ` (for your drawing of ${n} voxels, once it is one piece; ${walking || 'the robot walking is your last whole drawing'})` : '';
  // The breakdown in its own span: a tour question about it hides it until answered (tour.css).
  const breakdown = el.ownerDocument.createElement('span');
  breakdown.className = 'gene-detail expert'; // in simple words the count alone, its genes explained (shared/simple-words.js)
  breakdown.append(...withTerms(el.ownerDocument, detail));
  // The same breakdown in simple words (an attention brain's: which numbers all voxels share, which are one voxel's own).
  // Shown by its style only (classroom.css), so that the count's text stays the expert's.
  const plain = el.ownerDocument.createElement('span');
  plain.className = 'gene-detail gene-plain';
  if (kind === 'attention' && n > 0) {
    plain.dataset.plain = `${attentionGenes} shared by all the voxels (how each one listens), ${genes - attentionGenes - 1} that belong to one voxel each `
      + `(${SENSOR_NAMES.length} for every voxel), and 1 more`;
  }
  el.replaceChildren(...(n > 0 ? [...withTerms(el.ownerDocument, `${genes} genes${pending}`), breakdown, plain] : []));
  el.title = anyBody
    ? 'Genes: the numbers evolution changes. A brain for any body has no gene of its own per voxel: every voxel runs the same genes '
      + 'and works out its own weights from its place in the body (such as which neighbours it has), so one brain drives every body.'
    : 'Genes: the numbers evolution changes. Every voxel runs the same small network; '
      + 'what differs between voxels is only the output weights of its position.';
  el.dataset.value = String(genes);
}
