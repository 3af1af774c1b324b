// @ts-check
/**
 * Room kept for lines whose words change on their own while a run goes (the live figures under
 * the robot, the lines that say what drives it and how fast it walked), so that what stands
 * below them does not jump. While a run follows its best, every newer best starts a walk of its
 * own: the clock's "(its episode is over; it walks on)" comes and goes, the line under the robot
 * is written again, and each time the run's Pause, Step and Stop moved up and down the page
 * (a click on Stop could land on the run's figures under it). While held, each line keeps the
 * tallest height it has had at its width (min-height); let go, it takes its own again.
 * The lines have no padding or border: their height is their content's.
 */
export class SteadyRoom {
  /** @param {HTMLElement[]} lines */
  constructor(lines) {
    this.lines = lines;
    this.held = false;
    /** The height kept for each line, at the width it had. @type {Map<HTMLElement, {width: number, height: number}>} */
    this.kept = new Map();
    this.observer = new ResizeObserver((entries) => {
      if (this.held) for (const entry of entries) this.keep(/** @type {HTMLElement} */ (entry.target));
    });
  }

  /** Keeps the lines' room (a run started) or lets it go (it ended). @param {boolean} on */
  hold(on) {
    this.held = on;
    this.kept.clear();
    for (const line of this.lines) {
      line.style.minHeight = '';
      if (on) this.observer.observe(line);
      else this.observer.unobserve(line);
    }
  }

  /** @param {HTMLElement} line */
  keep(line) {
    const kept = this.kept.get(line);
    let { width, height } = line.getBoundingClientRect();
    if (kept && kept.width !== width) { // another width (a window resized, a panel shown): its own height again
      line.style.minHeight = '';
      ({ width, height } = line.getBoundingClientRect());
    } else if (kept && height <= kept.height) return;
    this.kept.set(line, { width, height });
    line.style.minHeight = height > 0 ? `${height}px` : '';
  }
}
