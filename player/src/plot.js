// The n(t) plot beside the picture: drawn once, with the reversals (dark dashed lines, yellow
// dots: as the videos' ticks and label, and not the spin cue's orange) and the averaged theory's
// forecast (violet); a cursor over it follows the time.

const REVERSAL_LINE = '#333';
const REVERSAL_DOT = '#f0e442';
const FORECAST_COLOR = '#7a3fd0'; // the forecast first reversal on the n(t) plot (violet)
const FORECAST_LABEL_HEIGHT = 12; // px at the plot's top: its label, 9 px type from 2 px down

export const plotMethods = {
  plotLayout() {
    // Present mode shows the plot scaled up over the picture (style.js): drawn finer for it.
    const scaled = this.presenting;
    const dpr = Math.min(window.devicePixelRatio || 1, 2) * (scaled ? 2 : 1);
    if (this.layout && this.layout.dpr === dpr) return this.layout;
    const w = 270,
      h = 130;
    this.plot.width = Math.round(w * dpr);
    this.plot.height = Math.round(h * dpr);
    this.plotDrawn = null;
    // One scale for every run the player plays: switched, the two spins' curves compare.
    let m = 0;
    for (const run of this.runs) for (const v of run.spin) m = Math.max(m, Math.abs(v));
    m = m > 0 ? 1.1 * m : 1;
    const box = { left: 34, right: w - 8, top: 8, bottom: h - 20 };
    const span = this.tEnd - this.t0 || 1;
    this.layout = {
      dpr,
      w,
      h,
      m,
      box,
      x: (t) => box.left + ((t - this.t0) / span) * (box.right - box.left),
      y: (n) => box.top + ((m - n) / (2 * m)) * (box.bottom - box.top),
      tAt: (px) => this.t0 + ((px - box.left) / (box.right - box.left)) * span,
    };
    return this.layout;
  },

  // The cursor at the current time: a line across the plot and a dot on the curve, moved (CSS
  // transforms, whole 0.1 px) over the plot drawn once. The plot's border is 1 px.
  moveCursor() {
    const L = this.plotLayout();
    if (!this.plotDrawn) this.drawPlot();
    const x = Math.round(10 * (1 + L.x(this.time))) / 10;
    const y = Math.round(10 * (1 + L.y(this.spinNow))) / 10;
    if (x === this.cursorX && y === this.cursorY) return;
    if (this.cursorX === undefined) {
      // Below the forecast's label, which it would cover near the reversal; see-through, so
      // that the reversal's dashed line under it stays dark.
      const top = L.box.top + (this.forecast ? FORECAST_LABEL_HEIGHT : 0);
      this.cursorLine.style.top = `${1 + top}px`;
      this.cursorLine.style.height = `${L.box.bottom - top}px`;
    }
    this.cursorX = x;
    this.cursorY = y;
    this.cursorLine.style.transform = `translate(${x - 0.75}px,0)`;
    this.cursorDot.style.transform = `translate(${x - 3}px,${y - 3}px)`;
  },

  // The plot without its cursor, drawn once.
  drawPlot() {
    const L = this.plotLayout();
    const g = this.plot.getContext('2d');
    g.setTransform(L.dpr, 0, 0, L.dpr, 0, 0);
    g.clearRect(0, 0, L.w, L.h);
    g.fillStyle = '#fff';
    g.fillRect(0, 0, L.w, L.h);
    const { box } = L;
    g.strokeStyle = '#bbb';
    g.lineWidth = 1;
    g.strokeRect(box.left, box.top, box.right - box.left, box.bottom - box.top);
    g.beginPath();
    g.moveTo(box.left, L.y(0));
    g.lineTo(box.right, L.y(0));
    g.stroke();
    this.drawReversalLines(g, L);
    this.drawForecast(g, L);
    this.drawCurve(g, L);
    this.drawLabels(g, L);
    this.plotDrawn = true;
  },

  // Reversals: dashed dark lines.
  drawReversalLines(g, L) {
    const { box } = L;
    g.strokeStyle = REVERSAL_LINE;
    g.setLineDash([3, 3]);
    for (const tr of this.run.reversals || []) {
      g.beginPath();
      g.moveTo(L.x(tr), box.top);
      g.lineTo(L.x(tr), box.bottom);
      g.stroke();
    }
    g.setLineDash([]);
  },

  // The averaged theory's forecast of the first reversal: a thin violet line, labelled.
  drawForecast(g, L) {
    if (!this.forecast) return;
    const { box } = L;
    const x = Math.round(L.x(this.forecast.time)) + 0.5;
    g.strokeStyle = FORECAST_COLOR;
    g.lineWidth = 1;
    g.beginPath();
    g.moveTo(x, box.top);
    g.lineTo(x, box.bottom);
    g.stroke();
    g.fillStyle = FORECAST_COLOR;
    g.font = '9px system-ui,sans-serif';
    g.textBaseline = 'top';
    // left of the line where it fits (the forecast is seldom late: the run's reversal, its
    // dashed line, is then clear of the label)
    const left = x - box.left > 44;
    g.textAlign = left ? 'right' : 'left';
    g.fillText('forecast', x + (left ? -2 : 2), box.top + 2);
  },

  // n(t), at most about 600 points, and the reversals on it: yellow dots. The other spin's
  // n(t), where there is one, pale under it: the two runs compared at a glance.
  drawCurve(g, L) {
    for (const run of this.runs) if (run !== this.run) this.strokeCurve(g, L, run, '#c4c7ce', 1);
    this.strokeCurve(g, L, this.run, '#2a2a2a', 1.3);
    g.fillStyle = REVERSAL_DOT;
    g.strokeStyle = REVERSAL_LINE;
    g.lineWidth = 1;
    for (const tr of this.run.reversals || []) {
      g.beginPath();
      g.arc(L.x(tr), L.y(0), 3.5, 0, 2 * Math.PI);
      g.fill();
      g.stroke();
    }
  },

  strokeCurve(g, L, run, color, width) {
    g.strokeStyle = color;
    g.lineWidth = width;
    g.beginPath();
    const { t, spin } = run;
    const n = t.length;
    const every = Math.max(1, Math.floor(n / 600));
    for (let i = 0; i < n; i += every) {
      if (i === 0) g.moveTo(L.x(t[i]), L.y(spin[i]));
      else g.lineTo(L.x(t[i]), L.y(spin[i]));
    }
    g.lineTo(L.x(t[n - 1]), L.y(spin[n - 1]));
    g.stroke();
  },

  // The axes' labels: ±the largest spin, 0, the first and last times.
  drawLabels(g, L) {
    const { box } = L;
    g.fillStyle = '#444';
    g.font = '10px system-ui,sans-serif';
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    const label = (v) => (Math.abs(v) >= 10 ? v.toFixed(0) : v.toFixed(1));
    g.fillText(`+${label(L.m / 1.1)}`, box.left - 3, L.y(L.m / 1.1));
    g.fillText('0', box.left - 3, L.y(0));
    g.fillText(`−${label(L.m / 1.1)}`, box.left - 3, L.y(-L.m / 1.1));
    g.textBaseline = 'top';
    g.textAlign = 'left';
    g.fillText(`${this.t0.toFixed(0)} s`, box.left, box.bottom + 4);
    g.textAlign = 'center';
    g.fillText('n (rad/s) over t', (box.left + box.right) / 2, box.bottom + 4);
    g.textAlign = 'right';
    g.fillText(`${this.tEnd.toFixed(this.tEnd % 1 ? 1 : 0)} s`, box.right, box.bottom + 4);
  },
};
