// A run's data as the player reads it (window.RATTLEBACK_RUNS[ID], tasks/player_data.hpp): its
// checks, its runs (the body spun either way), the body's geometry, the views' cameras, the
// forecast and the words for lengths and steps.
import { BufferAttribute, BufferGeometry } from 'three';

export const SERIES = ['t', 'x', 'y', 'z', 'qw', 'qx', 'qy', 'qz', 'spin'];

// Why `run` cannot be played, or '' when it can.
export function problemWith(run) {
  if (!run || typeof run !== 'object') return 'no data';
  const n = run.t && run.t.length;
  if (!n) return 'no samples';
  for (const k of SERIES)
    if (!run[k] || run[k].length !== n) return `series ${k} missing or of another length`;
  for (const k of ['top', 'bottom']) if (!run[k] || run[k].length % 3) return `points ${k} missing`;
  if (!Array.isArray(run.views) || !run.views.length) return 'views missing';
  if (run.top.length + run.bottom.length === 0) return 'no points';
  for (let i = 1; i < n; i++) if (!(run.t[i] > run.t[i - 1])) return 'times not increasing';
  return '';
}

// The runs a player offers: the data's own, and where it carries one (`other`: the series
// t … spin and the reversals, and `spun`, rad/s), the same body spun the other way, which shares
// the body, the views and the framing. An `other` that cannot be played is left out: the run's
// own still plays.
export function runsOf(run) {
  const other = run.other;
  if (!other || typeof other !== 'object' || !Number.isFinite(run.spun)) return [run];
  const spun = Object.assign({}, run, other, { other: null });
  if (problemWith(spun) || !Number.isFinite(spun.spun)) return [run];
  return [run, spun];
}

// The spacing of the body's points: the median distance to the nearest neighbour over a sample
// of about 40 points (2 r where there is no neighbour).
function medianSpacing(positions, count, r) {
  const nearest = [];
  const stride = Math.max(1, Math.floor(count / 40));
  for (let i = 0; i < count; i += stride) {
    let best = Infinity;
    for (let j = 0; j < count; j++) {
      if (j === i) continue;
      const dx = positions[3 * i] - positions[3 * j];
      const dy = positions[3 * i + 1] - positions[3 * j + 1];
      const dz = positions[3 * i + 2] - positions[3 * j + 2];
      const d = dx * dx + dy * dy + dz * dz;
      if (d > 0 && d < best) best = d;
    }
    if (best < Infinity) nearest.push(Math.sqrt(best));
  }
  nearest.sort((a, b) => a - b);
  return nearest.length ? nearest[nearest.length >> 1] : 2 * r;
}

// The body's geometry from the points: extents, spacing, footprint.
export function bodyGeometry(run) {
  const count = (run.top.length + run.bottom.length) / 3;
  const positions = new Float32Array(3 * count);
  const kinds = new Float32Array(count);
  positions.set(run.top, 0);
  positions.set(run.bottom, run.top.length);
  kinds.fill(1, run.top.length / 3);
  const low = [Infinity, Infinity, Infinity];
  const high = [-Infinity, -Infinity, -Infinity];
  let reach = 0;
  const r = +run.radius || 0.001;
  for (let i = 0; i < count; i++) {
    let n2 = 0;
    for (let k = 0; k < 3; k++) {
      const v = positions[3 * i + k];
      low[k] = Math.min(low[k], v);
      high[k] = Math.max(high[k], v);
      n2 += v * v;
    }
    reach = Math.max(reach, Math.sqrt(n2) + r);
  }
  const spacing = medianSpacing(positions, count, r);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('kind', new BufferAttribute(kinds, 1));
  const halfExtent = [0, 1, 2].map((k) => 0.5 * (high[k] - low[k]) + r);
  return {
    geometry,
    radius: r,
    spacing,
    reach: run.reach > 0 ? +run.reach : reach,
    // The length of body the views are framed for (the scene's video.frame), as in its stills
    // and videos: bodies given the same are drawn at one scale; 0: the body's own.
    frame: run.frame > 0 ? +run.frame : 0,
    halfExtent,
    // The box holding every drawn sphere, body frame (for the part of the picture to redraw).
    low: low.map((v) => v - r),
    high: high.map((v) => v + r),
    middleHeight: 0.5 * (high[2] + low[2]),
    footprintHalf: [halfExtent[0], halfExtent[1]],
  };
}

// The body's closed surface where the run's scene draws it so (video.surface: triangles; the
// data's `vertices`, x, y, z each about the CM, and `faces`, three vertex indices each, wound
// outwards): one corner per face and vertex, not shared, each with its face's normal and colour
// (red where the normal points up in the body frame, blue where down, as render/frame.hpp's
// facesUp: a rim vertex belongs to red faces above and blue below). Null where there are none,
// or where a face names a vertex that is not there: the points are drawn then.
export function triangleGeometry(run) {
  const v = run.vertices,
    f = run.faces;
  if (!Array.isArray(v) || !Array.isArray(f) || !f.length || f.length % 3 || v.length % 3) return null;
  const count = v.length / 3;
  const positions = new Float32Array(3 * f.length);
  const normals = new Float32Array(3 * f.length);
  const kinds = new Float32Array(f.length);
  const a = [0, 0, 0],
    b = [0, 0, 0],
    n = [0, 0, 0];
  for (let i = 0; i < f.length; i += 3) {
    for (const k of [0, 1, 2])
      if (!(f[i + k] >= 0 && f[i + k] < count && Number.isInteger(f[i + k]))) return null;
    const p = f[i],
      q = f[i + 1],
      r = f[i + 2];
    for (let k = 0; k < 3; k++) {
      a[k] = v[3 * q + k] - v[3 * p + k];
      b[k] = v[3 * r + k] - v[3 * p + k];
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    const length = Math.hypot(n[0], n[1], n[2]) || 1;
    // The data's µm rounding turns a face within about 1e-5 rad of vertical either way: those
    // are taken as vertical, which facesUp colours red.
    const kind = n[2] >= -1e-4 * length ? 0 : 1;
    for (let c = 0; c < 3; c++) {
      const corner = 3 * (i + c),
        from = 3 * f[i + c];
      for (let k = 0; k < 3; k++) {
        positions[corner + k] = v[from + k];
        normals[corner + k] = n[k] / length;
      }
      kinds[i + c] = kind;
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(normals, 3));
  geometry.setAttribute('kind', new BufferAttribute(kinds, 1));
  return geometry;
}

// The averaged theory's forecast of the first reversal, from the container's data-forecast
// (analyze's "predicted_first_reversal", JSON): {time, range} when it applies (the body stands,
// n²ρ/g and the rocking within the theory's reach: range not "outside") and falls within the
// run, else null, as the report's text gives no time then.
export function forecastOf(container, t0, tEnd) {
  const text = container.getAttribute('data-forecast');
  if (!text) return null;
  let f;
  try {
    f = JSON.parse(text);
  } catch (e) {
    return null;
  }
  if (!f || f.applies !== true || f.range === 'outside') return null;
  if (typeof f.time_s !== 'number' || !Number.isFinite(f.time_s)) return null;
  if (f.time_s < t0 || f.time_s > tEnd) return null;
  return { time: f.time_s, range: typeof f.range === 'string' ? f.range : '' };
}

// A length as the renderer's read-out gives it (render/overlay.cpp lengthText): "2 cm", "5 mm",
// "1 m", the unit that makes it at least 1.
export function lengthText(metres) {
  const m = metres * (1 + 1e-6);
  const fmt = (v) => String(Number(v.toPrecision(6)));
  if (m >= 1) return `${fmt(metres)} m`;
  if (m >= 0.01) return `${fmt(metres * 100)} cm`;
  return `${fmt(metres * 1000)} mm`;
}

export function formatStep(t) {
  if (t.length < 2) return 'one sample';
  const dt = (t[t.length - 1] - t[0]) / (t.length - 1);
  return `${+dt.toPrecision(3)} s`;
}

// The views' cameras by name, as the renderer places them (its table, util/picture.hpp, comes
// with the data): {oblique: {projection, toward_eye, up, elevation_deg, fov_deg, margin, eye_r,
// near_r, far_r}, …}, in the renderer's order.
export function viewsOf(run) {
  const views = {};
  for (const v of run.views) views[v.name] = v;
  return views;
}
