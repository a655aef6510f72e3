// The spin cue over the picture, as the videos draw it (docs/commands.md "The spin cue"): an arrow
// on the floor around the body, on the half of the circle nearer the camera, turning the way the
// body turns, orange counter-clockwise and bluish green clockwise (Okabe and Ito's colours, told
// apart with any colour vision and unlike the body's red and blue), its sweep |n| over the run's
// largest |n| up to a half circle; and "reversal at T s" ("reversal 2 at T s" from the second)
// for 1.5 s after each reversal. An SVG
// over the canvas: the WebGL picture and its partial redraws are untouched.
import { Vector3 } from 'three';

const SVG = 'http://www.w3.org/2000/svg';
export const CCW_COLOR = '#e69f00';
export const CW_COLOR = '#009e73';
const SLOWEST_SHOWN_SPIN = 0.05; // rad/s, as the read-out's words
const REVERSAL_SHOWN_FOR = 1.5; // s, as the videos' label
const POINTS = 32;

function svg(tag, attributes) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
  return e;
}

export const cueMethods = {
  buildCue() {
    this.cue = svg('svg', { class: 'rbp-cue', 'aria-hidden': 'true' });
    // A dark edge under the colour, as in the videos: orange alone is faint on the light floor.
    this.cueEdge = svg('path', { fill: 'none', stroke: '#1e1e1e', 'stroke-opacity': '0.8' });
    this.cueLine = svg('path', { fill: 'none' });
    this.cueHeadEdge = svg('polygon', { fill: '#1e1e1e', 'fill-opacity': '0.8' });
    this.cueHead = svg('polygon');
    this.cue.append(this.cueEdge, this.cueLine, this.cueHeadEdge, this.cueHead);
    this.stage.appendChild(this.cue);
    this.reversalLabel = document.createElement('div');
    this.reversalLabel.className = 'rbp-reversal-label';
    this.reversalLabel.hidden = true;
    this.stage.appendChild(this.reversalLabel);
    let m = 0; // (over every run played: the arrow of the same spin is as long in each)
    for (const run of this.runs) for (const v of run.spin) m = Math.max(m, Math.abs(v));
    this.cueRange = m > 0 ? m : 1;
    this.cuePoint = new Vector3();
    this.cueSense = 0; // the sense drawn: +1, −1 or 0 (none), for tests and screenshots
  },

  // The arc in CSS pixels of the stage, in the order of the turn; null where none is drawn.
  cueArc() {
    const spin = this.spinNow;
    if (!(Math.abs(spin) >= SLOWEST_SHOWN_SPIN)) return null;
    const camera = this.camera;
    const e = camera.matrixWorld.elements; // columns: right, up, back, position
    // Towards the camera along the floor: its back axis less its up axis (seen from above,
    // where the back axis is vertical, towards the picture's bottom).
    const facing = Math.atan2(e[9] - e[5], e[8] - e[4]);
    const sweep = Math.PI * Math.min(1, Math.abs(spin) / this.cueRange);
    const sense = spin > 0 ? 1 : -1;
    const radius = 1.25 * this.body.reach;
    const c = this.points.position;
    const arc = [];
    for (let k = 0; k <= POINTS; k++) {
      const a = facing + sense * sweep * (k / POINTS - 0.5);
      const p = this.cuePoint.set(c.x + radius * Math.cos(a), c.y + radius * Math.sin(a), 0);
      p.project(camera);
      if (!(p.z < 1)) return null; // behind the camera
      arc.push([((p.x + 1) / 2) * this.width, ((1 - p.y) / 2) * this.height]);
    }
    return arc;
  },

  // Called with each picture drawn, so the arrow stays with the body the picture shows.
  updateCue() {
    if (!this.cue) return;
    const arc = this.cueArc();
    this.cueSense = arc ? Math.sign(this.spinNow) : 0;
    this.cue.style.display = arc ? '' : 'none';
    if (arc) this.drawCueArrow(arc);
    // The latest reversal shown, numbered from the second as the videos number it.
    const reversals = this.run.reversals || [];
    let latest = -1;
    reversals.forEach((r, i) => {
      if (r <= this.time && this.time - r < REVERSAL_SHOWN_FOR) latest = i;
    });
    const at = latest >= 0 ? `at ${reversals[latest].toFixed(2)} s` : '';
    const text = latest < 0 ? '' : latest === 0 ? `reversal ${at}` : `reversal ${latest + 1} ${at}`;
    if (this.reversalLabel.textContent !== text) this.reversalLabel.textContent = text;
    this.reversalLabel.hidden = !text;
  },

  drawCueArrow(arc) {
    // A 120th of the picture's height wide, at least 2 px, as in the videos.
    const width = Math.max(2, this.height / 120);
    const head = 3.5 * width;
    const d = 'M' + arc.map((p) => `${p[0].toFixed(1)},${p[1].toFixed(1)}`).join('L');
    const color = this.spinNow > 0 ? CCW_COLOR : CW_COLOR;
    this.cueEdge.setAttribute('d', d);
    this.cueEdge.setAttribute('stroke-width', String(width + 2));
    this.cueLine.setAttribute('d', d);
    this.cueLine.setAttribute('stroke', color);
    this.cueLine.setAttribute('stroke-width', String(width));
    const [ax, ay] = arc[arc.length - 2];
    const [bx, by] = arc[arc.length - 1];
    const norm = Math.hypot(bx - ax, by - ay) || 1;
    const dx = (bx - ax) / norm,
      dy = (by - ay) / norm;
    const triangle = (length) => {
      const half = 0.6 * length;
      return [
        [bx + dx * length, by + dy * length],
        [bx - dy * half, by + dx * half],
        [bx + dy * half, by - dx * half],
      ]
        .map((p) => `${p[0].toFixed(1)},${p[1].toFixed(1)}`)
        .join(' ');
    };
    this.cueHeadEdge.setAttribute('points', triangle(head + 3));
    this.cueHead.setAttribute('points', triangle(head));
    this.cueHead.setAttribute('fill', color);
  },
};
