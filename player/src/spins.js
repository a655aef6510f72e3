// The two spins: a run whose data carries the same body spun the other way (`other`,
// tasks/player_data.hpp) is played either way, switched by two buttons beside the picture (and
// S). A body spun the way it prefers does not reverse; spun the other way it does, and a lesson
// shows the two one after the other, on the same floor, at the same moment of the run.
import { el } from './style.js';

// "−5 rad/s" / "+5 rad/s": the spin the run was given, signed as the read-out signs n.
function spunText(spun) {
  const size = +Math.abs(spun).toPrecision(4);
  return `${spun < 0 ? '\u2212' : '+'}${size} rad/s`;
}

// What the run did, from its own reversals (not from the theory, which may be wrong for a body
// outside its reach): "reverses at 2.37 s", "no reversal".
export function runLabel(run) {
  const reversals = run.reversals || [];
  const did = reversals.length
    ? `reverses at ${reversals[0].toFixed(2)} s` +
      (reversals.length > 1 ? ` (${reversals.length} reversals)` : '')
    : 'no reversal';
  return `${spunText(+run.spun)}: ${did}`;
}

export const spinsMethods = {
  // The buttons, one a run, the selected one pressed; nothing where there is one run.
  buildSpins() {
    if (this.runs.length < 2) return null;
    const box = el('div', 'rbp-spins');
    box.setAttribute('role', 'group');
    box.setAttribute('aria-label', 'spin');
    box.appendChild(el('div', 'rbp-label', 'spun'));
    this.spinButtons = this.runs.map((run, k) => {
      const b = el('button', 'rbp-spun', runLabel(run));
      b.type = 'button';
      b.title = `Play the run spun ${spunText(+run.spun)} (S switches)`;
      b.addEventListener('click', () => {
        this.selectRun(k);
        this.root.focus({ preventScroll: true });
      });
      box.appendChild(b);
      return b;
    });
    this.markSpin();
    return box;
  },

  markSpin() {
    if (!this.spinButtons) return;
    this.spinButtons.forEach((b, k) => {
      b.classList.toggle('rbp-on', k === this.runIndex);
      b.setAttribute('aria-pressed', String(k === this.runIndex));
    });
  },

  // The next run (S).
  switchRun() {
    if (this.runs.length > 1) this.selectRun((this.runIndex + 1) % this.runs.length);
  },

  // Plays run k from the time shown (the two runs start alike; at the same moment the two
  // bodies are compared), playing on if it was playing.
  selectRun(k) {
    if (!(k >= 0 && k < this.runs.length) || k === this.runIndex) return;
    const wasPlaying = this.playing;
    this.pause();
    this.useRun(k);
    this.markSpin();
    this.applyTime(this.time);
    this.redrawAll = true;
    this.render();
    if (wasPlaying) this.play();
  },

  // The state that follows the run: its series, its span, its reversals (the button, the
  // slider's ticks, the help, the plot) and the forecast, which is of the scene's own spin.
  useRun(k) {
    const run = this.runs[k];
    this.runIndex = k;
    this.run = run;
    this.n = run.t.length;
    this.t0 = run.t[0];
    this.tEnd = run.t[this.n - 1];
    this.forecast = k === 0 ? this.ownForecast : null;
    if (!this.slider) return; // (building: the controls read these as they are made)
    this.slider.min = String(this.t0);
    this.slider.max = String(this.tEnd);
    this.markReversals();
    this.help.textContent = this.helpText();
    this.layout = null;
    this.plotDrawn = null;
    this.cursorX = undefined;
  },
};
