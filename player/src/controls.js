// The player's controls: its elements (the picture's stage, the bar of buttons, the views, the
// spins, the read-outs and the plot's box), the pointer and keys, and the read-outs written as time goes.
import { el } from './style.js';
import { formatStep } from './data.js';

const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4];

function button(text, title, handler, extra) {
  const b = el('button', extra || '', text);
  b.type = 'button';
  b.title = title;
  b.addEventListener('click', handler);
  return b;
}

export const controlsMethods = {
  // --- DOM ---------------------------------------------------------------------------------
  buildDom() {
    const c = this.container;
    c.textContent = '';
    const root = el('div', 'rbp');
    root.tabIndex = 0;
    root.setAttribute('role', 'group');
    root.setAttribute('aria-label', `3D player: ${this.run.title || this.run.id}`);
    const main = el('div', 'rbp-main');
    this.stage = el('div', 'rbp-stage');
    this.canvas = el('canvas');
    this.stage.appendChild(this.canvas);
    main.appendChild(this.stage);
    main.appendChild(this.buildBar());
    main.appendChild(this.ticks);
    main.appendChild(this.buildViews());
    root.append(main, this.buildSide());
    c.appendChild(root);
    this.root = root;
  },

  // The bar under the picture: play, step, the next reversal, the time slider, the speed and
  // full screen.
  buildBar() {
    const bar = el('div', 'rbp-bar');
    this.backButton = button('◀|', 'Step back one sample (←)', () => this.step(-1), 'rbp-back');
    this.playButton = button('▶ Play', 'Play / pause (space)', () => this.toggle(), 'rbp-play');
    this.forwardButton = button('|▶', 'Step forward one sample (→)', () => this.step(1), 'rbp-forward');
    // To the moment the spin passes zero, the picture a lesson stops at (hard to find by
    // stepping with the arrows, or by a click on the plot that lands near it).
    this.reversalButton = button('⟲ Reversal', '', () => this.gotoReversal(), 'rbp-reversal');
    // Full screen, for a projector: the picture and its read-outs as large as the screen allows.
    // (Words, not a symbol: the page's fonts may lack the full-screen glyph, drawn as a box.)
    this.fullButton = button(
      'Full screen',
      'Full screen (F; Esc leaves it)',
      () => this.toggleFullScreen(),
      'rbp-full',
    );
    // Present: full screen with large read-outs over the picture (present.js).
    this.presentButton = button(
      'Present',
      'Present: full screen, large read-outs (P; Esc leaves it)',
      () => this.togglePresent(),
      'rbp-present-button',
    );
    this.buildSlider();
    this.markReversals();
    this.buildSpeed();
    bar.append(
      this.backButton,
      this.playButton,
      this.forwardButton,
      this.reversalButton,
      this.slider,
      el('span', 'rbp-label', 'speed'),
      this.speedSelect,
      this.fullButton,
      this.presentButton,
    );
    return bar;
  },

  buildSlider() {
    this.slider = el('input', 'rbp-slider');
    this.slider.type = 'range';
    this.slider.min = String(this.t0);
    this.slider.max = String(this.tEnd);
    this.slider.step = 'any';
    this.slider.value = String(this.t0);
    this.slider.setAttribute('aria-label', 'time (s)');
    // The reversals as ticks on the slider's track (a datalist: the browser draws them where
    // the thumb would stand, and the thumb snaps to one it comes near); markReversals fills it.
    this.ticks = el('datalist');
    this.ticks.id = `rbp-reversals-${this.run.id || 'run'}-${Math.random().toString(36).slice(2)}`;
    this.slider.addEventListener('input', () => this.setTime(parseFloat(this.slider.value), false));
  },

  // The played run's reversals on the Reversal button and the slider's ticks (again when the
  // run is switched: spins.js).
  markReversals() {
    const reversals = this.run.reversals || [];
    this.reversalButton.title = reversals.length
      ? 'Go to the next reversal, where the spin passes zero (R)'
      : 'No reversal in this run';
    this.reversalButton.disabled = reversals.length === 0;
    this.ticks.textContent = '';
    for (const r of reversals) {
      const o = el('option');
      o.value = String(r);
      this.ticks.appendChild(o);
    }
    // (no list without ticks: the browser would draw an empty one)
    if (reversals.length) this.slider.setAttribute('list', this.ticks.id);
    else this.slider.removeAttribute('list');
  },

  buildSpeed() {
    this.speedSelect = el('select', 'rbp-speed');
    this.speedSelect.title = 'Playback speed';
    for (const s of SPEEDS) {
      const o = el('option', '', `${s}×`);
      o.value = String(s);
      if (s === 1) o.selected = true;
      this.speedSelect.appendChild(o);
    }
    // A speed chosen with the pointer gives the keys back to the player (they went to the menu:
    // → chose the next speed, space did nothing); one chosen with the keyboard (the menu tabbed
    // to, its arrows) leaves the focus on the menu, so its keys go on choosing.
    this.speedKeyed = false;
    this.speedSelect.addEventListener('keydown', () => {
      this.speedKeyed = true;
    });
    this.speedSelect.addEventListener('pointerdown', () => {
      this.speedKeyed = false;
    });
    this.speedSelect.addEventListener('blur', () => {
      this.speedKeyed = false;
    });
    this.speedSelect.addEventListener('change', () => {
      this.setSpeed(parseFloat(this.speedSelect.value));
      if (!this.speedKeyed) this.root.focus({ preventScroll: true });
    });
  },

  // The views' buttons, in the renderer's order, and Free.
  buildViews() {
    const views = el('div', 'rbp-views');
    views.appendChild(el('span', 'rbp-label', 'view'));
    this.viewButtons = {};
    for (const v of this.viewNames) {
      const b = button(
        v[0].toUpperCase() + v.slice(1),
        `View: ${v}`,
        () => this.setView(v),
        `rbp-view rbp-view-${v}`,
      );
      b.dataset.view = v;
      this.viewButtons[v] = b;
      views.appendChild(b);
    }
    this.freeButton = button(
      'Free',
      'Drag to orbit, right-drag to pan, wheel to zoom',
      () => this.setView('free'),
      'rbp-view rbp-view-free',
    );
    this.freeButton.dataset.view = 'free';
    this.viewButtons.free = this.freeButton;
    views.appendChild(this.freeButton);
    return views;
  },

  // Beside the picture: the title, the read-outs, the n(t) plot and the help.
  buildSide() {
    const side = el('div', 'rbp-side');
    side.appendChild(el('div', 'rbp-title', this.run.title || this.run.id || 'run'));
    const spins = this.buildSpins();
    if (spins) side.appendChild(spins);
    this.readTime = el('div', 'rbp-read rbp-time');
    this.readSpin = el('div', 'rbp-read rbp-spin');
    this.readSense = el('div', 'rbp-read rbp-sense');
    // The floor's checker square (the renderer's rule: it follows the body's size, so bodies are
    // compared by their squares; four times deeper in the front and side views).
    this.readScale = el('div', 'rbp-read rbp-scale');
    side.append(this.readTime, this.readSpin, this.readSense, this.readScale);
    // The plot is drawn once; the cursor on it is two elements moved over it (no redrawing).
    const plotBox = el('div', 'rbp-plotbox');
    this.plot = el('canvas', 'rbp-plot');
    this.plot.title = 'spin n(t); click to seek';
    this.cursorLine = el('div', 'rbp-cursor');
    this.cursorDot = el('div', 'rbp-dot');
    plotBox.append(this.plot, this.cursorLine, this.cursorDot);
    side.appendChild(plotBox);
    this.help = el('div', 'rbp-help', this.helpText());
    side.appendChild(this.help);
    return side;
  },

  // The help under the plot: the played run's reversals, and the keys.
  helpText() {
    const nrev = (this.run.reversals || []).length;
    return (
      (nrev
        ? `${nrev} reversal${nrev === 1 ? '' : 's'} (dashed lines; ticks on the time slider)`
        : 'No reversal in this run') +
      (this.forecast ? ", the averaged theory's forecast of the first (violet)" : '') +
      '. The arrow around the body turns as it does: orange counter-clockwise, green clockwise.' +
      ' Drag: orbit, right-drag: pan, wheel: zoom. ' +
      'Keys: space play/pause, ← → step one sample (' +
      formatStep(this.run.t) +
      '), ' +
      'Home / End the start / end, R the next reversal, ' +
      (this.runs.length > 1 ? 'S the other spin, ' : '') +
      'F full screen, P present (full screen, large read-outs; Esc leaves).'
    );
  },

  bindEvents() {
    this.root.addEventListener('keydown', (e) => this.onKey(e));
    this.bindPresent();
    this.canvas.addEventListener('pointerdown', () => this.root.focus({ preventScroll: true }));
    this.slider.addEventListener('pointerdown', () => {
      this.sliderDragging = true;
    });
    window.addEventListener('pointerup', () => {
      this.sliderDragging = false;
    });
    const seek = (e) => {
      const rect = this.plot.getBoundingClientRect();
      this.setTime(this.plotLayout().tAt(e.clientX - rect.left), false);
    };
    this.plot.addEventListener('pointerdown', (e) => {
      this.plotDragging = true;
      this.plot.setPointerCapture(e.pointerId);
      seek(e);
    });
    this.plot.addEventListener('pointermove', (e) => {
      if (this.plotDragging) seek(e);
    });
    this.plot.addEventListener('pointerup', () => {
      this.plotDragging = false;
    });
    if (typeof ResizeObserver !== 'undefined') {
      new ResizeObserver(() => this.resize()).observe(this.stage);
      this.resizeObserved = true;
    }
    if (typeof IntersectionObserver !== 'undefined') {
      new IntersectionObserver((entries) => {
        for (const e of entries) this.visible = e.isIntersecting;
        if (this.visible) this.dirty = true;
      }).observe(this.stage);
    }
  },

  // Space plays or pauses, the arrows step one sample; true when the key was used.
  onKey(e) {
    if (e.defaultPrevented || e.altKey || e.ctrlKey || e.metaKey) return false;
    const target = e.target;
    if (target && target.tagName === 'SELECT') return false;
    if (e.key === ' ' || e.code === 'Space') {
      this.toggle();
    } else if (e.key === 'ArrowLeft') {
      this.step(-1);
    } else if (e.key === 'ArrowRight') {
      this.step(1);
    } else if (e.key === 'Home' || e.key === 'End') {
      this.toEnd(e.key === 'End');
    } else if (e.key === 'r' || e.key === 'R') {
      this.gotoReversal();
    } else if ((e.key === 's' || e.key === 'S') && this.runs.length > 1) {
      this.switchRun();
    } else if (e.key === 'f' || e.key === 'F') {
      this.toggleFullScreen();
    } else if (e.key === 'p' || e.key === 'P') {
      this.togglePresent();
    } else if (e.key === 'Escape' && this.presenting) {
      this.setPresent(false);
    } else if (e.key === 'Escape' && document.fullscreenElement === this.root) {
      // A browser leaves full screen on Esc by itself; a kiosk or a driven browser (a
      // projector's, a test's) may hand the key to the page instead.
      this.toggleFullScreen();
    } else {
      return false;
    }
    e.preventDefault();
    e.stopPropagation();
    return true;
  },

  toggleFullScreen() {
    if (document.fullscreenElement) {
      if (document.exitFullscreen) document.exitFullscreen();
    } else if (this.root.requestFullscreen) {
      this.root.requestFullscreen().catch(() => {});
    }
  },

  setSpeed(s) {
    if (!(s > 0)) return;
    this.speed = s;
    this.speedSelect.value = String(s);
    if (this.speedSelect.value !== String(s)) {
      // not one of the list's speeds: add it
      const o = el('option', '', `${s}×`);
      o.value = String(s);
      this.speedSelect.appendChild(o);
      this.speedSelect.value = String(s);
    }
  },

  updatePlayButton() {
    this.playButton.textContent = this.playing ? '❚❚ Pause' : '▶ Play';
    this.playButton.classList.toggle('rbp-on', this.playing);
  },

  // The read-outs, the slider and the plot's cursor at the current time; each element is written
  // only when what it shows changes (a write costs the page a style, layout and paint pass).
  updateReadouts() {
    const t = this.time;
    this.shownTime = t; // (pause goes back to it)
    const spin = Math.abs(this.spinNow) < 0.005 ? 0 : this.spinNow;
    const signed = (spin >= 0 ? '+' : '-') + Math.abs(spin).toFixed(2);
    this.show(this.readTime, `t = ${t.toFixed(2).padStart(6)} s`);
    this.show(this.readSpin, `spin n = ${signed.padStart(6)} rad/s`);
    // Words at n ≈ 0 too: a blank line there read as a read-out gone missing, at the very moment
    // (a reversal) a lesson stops on.
    this.show(
      this.readSense,
      spin > 0.05 ? '(counter-clockwise)' : spin < -0.05 ? '(clockwise)' : '(not spinning)',
    );
    if (document.activeElement !== this.slider || !this.sliderDragging) this.slider.value = String(t);
    this.moveCursor();
  },

  show(element, text) {
    if (element.rbText !== text) {
      element.textContent = text;
      element.rbText = text;
    }
  },
};
