// The report page's interactive player of a simulated rattleback run (three.js).
//
// The page holds, for each run, <div class="rb-player" data-run="ID"></div> and a classic
// script ID.player.js that stores the run in window.RATTLEBACK_RUNS[ID] (see README.md beside
// this folder's package.json for the fields); this script, loaded last, builds a player in each
// such element. It is bundled into one classic script (build.sh): no module imports, no fetch,
// nothing from the network, so the page works from file://.
//
// Frames: world z is up and the floor is the plane z = 0, as in the data; the body's points are
// in its own frame about the centre of mass, posed each frame by the run's position (linear
// between samples) and attitude (slerp between samples). A "frame" of the step buttons and
// arrow keys is one sample interval of the data. Playback stops at the end of the run (play
// again starts it over).
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  CustomBlending,
  Matrix3,
  Matrix4,
  Mesh,
  OrthographicCamera,
  PerspectiveCamera,
  PlaneGeometry,
  Points,
  Quaternion,
  SRGBColorSpace,
  Scene,
  ShaderMaterial,
  Vector2,
  Vector3,
  WebGLRenderer,
  ZeroFactor,
  OneFactor,
  SrcColorFactor,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

const DEG = Math.PI / 180;
const ELEVATION = 10 * DEG; // front and side look this far down (render/camera.cpp)
const BACKGROUND = [0.93, 0.94, 0.96]; // the renderer's kBackground (sRGB)
const VIEWS = ['oblique', 'above', 'front', 'side', 'follow'];
const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4];
const FORECAST_COLOR = '#7a3fd0'; // the forecast first reversal on the n(t) plot (violet)
const FORECAST_LABEL_HEIGHT = 12; // px at the plot's top: its label, 9 px type from 2 px down
const UP = new Vector3(0, 0, 1);

// ---------------------------------------------------------------------------------------------
// Shaders (GLSL ES 3.0 through three's ShaderMaterial; colours are written as sRGB as they are).

// The body's points as sphere impostors: one GL point per sphere, sized to its projected radius
// (perspective and orthographic alike), shaded from the sprite's coordinates; a ported subset
// of the renderer's points.vert / points.frag. What is the same over a sprite reaches its
// pixels in one vec4 varying (SwiftShader sets up and interpolates each varying for every point
// and pixel: four cost the points 5–8 % more).
const POINTS_VERTEX = /* glsl */ `
attribute float kind;          // 0 top (red), 1 bottom (blue)
uniform float radius;          // sphere radius, m
uniform float spacing;         // distance between neighbouring points, m
uniform float viewportHeight;  // drawing buffer pixels
varying vec4 vSprite;          // kind; sprite / sphere radius; sphere radius / edge; highlight
void main() {
  vec4 view = modelViewMatrix * vec4(position, 1.0);
  gl_Position = projectionMatrix * view;
  float w = projectionMatrix[2][3] == 0.0 ? 1.0 : -view.z;
  float pxPerM = abs(projectionMatrix[1][1]) * viewportHeight * 0.5 / w;
  // Spheres of a pixel or two grow towards their neighbours so the surface reads as one.
  float radiusPx = max(radius * pxPerM, min(0.6 * spacing * pxPerM, 2.0));
  float radiusM = radiusPx / pxPerM;
  float spherePx = max(radiusPx, 0.75);
  float edgePx = clamp(spherePx - 1.5, 0.05, 1.0);
  float halfPx = spherePx + 0.5 * edgePx;
  gl_PointSize = 2.0 * halfPx;
  vSprite = vec4(kind, halfPx / spherePx, spherePx / edgePx, 0.3 * smoothstep(1.5, 2.5, spherePx));
  // The sprite's depth is the sphere's nearest point.
  vec4 front = projectionMatrix * vec4(view.xy, view.z + radiusM, 1.0);
  gl_Position.z = front.z / front.w * gl_Position.w;
}`;

const POINTS_FRAGMENT = /* glsl */ `
uniform vec3 lightView;  // unit vector towards the light, view frame
uniform vec3 halfView;   // halfway between the light and the eye, view frame
uniform vec3 floorDepth; // the floor plane's depth at window (x, y): dot(floorDepth, (x, y, 1))
varying vec4 vSprite;
void main() {
  vec2 p = (gl_PointCoord * 2.0 - 1.0) * vSprite.y;
  p.y = -p.y;  // gl_PointCoord runs down the screen
  float rr = dot(p, p);
  float coverage = clamp((1.0 - sqrt(rr)) * vSprite.z + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  // Behind the floor (a sphere at the contact reaches below it): hidden, as the floor's depth
  // would hide it (floorDepth: Player.updateFloorDepth). Not where the floor is nearer than the
  // near plane (it is not drawn there).
  float floorZ = dot(floorDepth, vec3(gl_FragCoord.xy, 1.0));
  if (gl_FragCoord.z > floorZ && floorZ >= 0.0) discard;
  vec3 n = vec3(p, sqrt(max(0.0, 1.0 - rr)));
  float diffuse = max(dot(n, lightView), 0.0);
  float s = max(dot(n, halfView), 0.0);
  s *= s; s *= s; s *= s; s *= s; s *= s;  // s^32
  vec3 color = vSprite.x < 0.5 ? vec3(0.86, 0.13, 0.10) : vec3(0.13, 0.32, 0.88);
  gl_FragColor = vec4(color * (0.35 + 0.65 * diffuse) + vec3(s * vSprite.w), coverage);
}`;

// The floor: a box-filtered checker fading into the background, with a soft contact shadow
// under the body (the renderer's floor.frag and floor_common.frag). On software WebGL this
// shader runs for most of the canvas's pixels, so each pixel does only what its view needs.
// The fade (with distance from the target, or the fog of the orthographic views along the
// floor, FOG) is computed at the vertices of a mesh that covers only where the floor shows,
// fine enough that the picture is within two levels of the fade computed per pixel:
// rings about the target from fadeNear to fadeFar (the background beyond is the clear colour),
// or rows across the view from fogNear to fogFar. The mode is a define (its own program, not a
// branch that runs both sides). The shadow (SHADOW) is drawn only in a quad around the body,
// over the floor, with the same formula computed per pixel and the shadow; outside the
// shadow's ellipse the quad's pixels are the floor's. Where neither fade nor fog has begun (the
// disc inside fadeNear, the rows before fogNear: NEAR, the first part of each mesh) the floor
// is the checker alone, without the varyings that carry them (on SwiftShader a varying costs
// each pixel about as much as the checker's arithmetic). The checker's position reaches the
// fragments in checker periods (two squares), so that the pixels do not divide by the square.
const FLOOR_VERTEX = /* glsl */ `
uniform float tile;            // checker square, m
uniform vec2 center;           // where the floor fades from, m
uniform float fadeNear;
uniform float fadeFar;
uniform vec2 depthDirection;   // orthographic views along the floor: away from the camera
uniform float fogNear;
uniform float fogFar;
uniform float reach;           // FOG: the band's half width and how far it reaches back, m
varying vec2 vPeriods;         // position on the floor in checker periods (two squares)
varying float vFade;
varying float vFog;
void main() {
#if defined(SHADOW)
  vec4 world = modelMatrix * vec4(position, 1.0);
#elif defined(FOG)
  // position: x across the view in [-1, 1]; y < 0 the row nearest the camera, else [0, 1]
  // from fogNear to fogFar.
  float depth = position.y < 0.0 ? -reach : mix(fogNear, fogFar, position.y);
  vec2 across = vec2(depthDirection.y, -depthDirection.x);
  vec4 world = vec4(center + depthDirection * depth + across * (position.x * reach), 0.0, 1.0);
  vFade = smoothstep(fogNear, fogFar, depth);
  vFog = smoothstep(fogNear, mix(fogNear, fogFar, 0.5), depth);
#else
  // position: x the angle about the centre, y < 0 the centre, else [0, 1] from fadeNear to
  // fadeFar.
  float r = position.y < 0.0 ? 0.0 : mix(fadeNear, fadeFar, position.y);
  vec4 world = vec4(center + r * vec2(cos(position.x), sin(position.x)), 0.0, 1.0);
  vFade = smoothstep(fadeNear, fadeFar, r);
#endif
  vPeriods = world.xy * (0.5 / tile);
  gl_Position = projectionMatrix * viewMatrix * world;
}`;

const FLOOR_FRAGMENT = /* glsl */ `
uniform float tile;            // checker square, m
uniform vec3 background;
uniform vec2 center;
uniform float fadeNear;
uniform float fadeFar;
uniform vec2 depthDirection;
uniform float fogNear;
uniform float fogFar;
uniform vec2 shadowCenter;
uniform vec2 shadowAxis;       // the body's long axis on the floor
uniform vec2 shadowHalf;       // half extents across and along it, m
uniform float shadowStrength;
varying vec2 vPeriods;
varying float vFade;
varying float vFog;
void main() {
  // The square wave of each axis box-filtered over the pixel's footprint w (in periods): the
  // difference of its integral, a triangle wave, across the footprint, over w.
  vec2 q = vPeriods;
  vec2 w = fwidth(q) + 0.5e-4;
  vec2 h = 0.5 * w;
  vec2 i = abs(fract(q - h) - 0.5) - abs(fract(q + h) - 0.5);
  float checker = 0.5 - 0.5 * i.x * i.y / (w.x * w.y);
#if defined(SHADOW)
  vec2 xy = q * (2.0 * tile);  // m
#endif
#if defined(NEAR)
  float fade = 0.0;
#elif defined(SHADOW) && defined(FOG)
  float depth = dot(xy - center, depthDirection);
  checker = mix(checker, 0.5, smoothstep(fogNear, mix(fogNear, fogFar, 0.5), depth));
  float fade = smoothstep(fogNear, fogFar, depth);
#elif defined(SHADOW)
  float fade = smoothstep(fadeNear, fadeFar, length(xy - center));
#elif defined(FOG)
  checker = mix(checker, 0.5, vFog);
  float fade = vFade;
#else
  float fade = vFade;
#endif
  vec3 color = mix(vec3(0.80, 0.80, 0.78), vec3(0.66, 0.67, 0.66), checker);
#ifdef SHADOW
  vec2 d = xy - shadowCenter;
  vec2 local = vec2(dot(d, vec2(shadowAxis.y, -shadowAxis.x)), dot(d, shadowAxis));
  color *= 1.0 - shadowStrength * (1.0 - smoothstep(0.55, 1.15, length(local / shadowHalf)));
#endif
#ifdef NEAR
  gl_FragColor = vec4(color, 1.0);
#else
  gl_FragColor = vec4(mix(color, background, fade), 1.0);
#endif
}`;

// The shadow alone, over the floor where neither fade nor fog has begun under its quad (the
// floor there is the checker alone, NEAR): it multiplies the floor drawn under it by the
// shadow's factor, the same as FLOOR_FRAGMENT's with SHADOW there, at a fraction of the cost.
// vLocal: the quad's own coordinates, in the footprint's half extents.
const SHADOW_VERTEX = /* glsl */ `
varying vec2 vLocal;
void main() {
  vLocal = position.xy;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

const SHADOW_FRAGMENT = /* glsl */ `
uniform float shadowStrength;
varying vec2 vLocal;
void main() {
  float s = 1.0 - shadowStrength * (1.0 - smoothstep(0.55, 1.15, length(vLocal)));
  gl_FragColor = vec4(s, s, s, 1.0);
}`;

// The shadow's reach: it fades out at 1.15 of the footprint's half extents (FLOOR_FRAGMENT);
// its quad, and the part of the canvas redrawn for it, reach a little further.
const SHADOW_REACH = 1.2;

// ---------------------------------------------------------------------------------------------
// Style: injected once, so that the page needs no CSS of its own. The canvas's stage has square
// corners and clips nothing: with rounded corners (border-radius, overflow: hidden) Chromium
// composites the canvas through a masked layer of its own, which doubled the cost of each frame
// on software WebGL (bench/player_speed.py).

const STYLE = `
.rbp{display:flex;flex-wrap:wrap;gap:10px;align-items:flex-start;font:14px/1.35 system-ui,-apple-system,"Segoe UI",sans-serif;color:#1e1e1e;outline:none;margin:8px 0}
.rbp:focus-visible{box-shadow:0 0 0 2px #6b8fd6;border-radius:4px}
.rbp-main{flex:1 1 480px;min-width:280px;max-width:100%}
.rbp-stage{position:relative;width:100%;aspect-ratio:16/9;background:#eef0f5;border:1px solid #c9ccd4}
.rbp-stage canvas{display:block;width:100%;height:100%;touch-action:none;cursor:grab}
.rbp-stage.rbp-fixed{aspect-ratio:auto;width:auto}
.rbp-bar,.rbp-views{display:flex;flex-wrap:wrap;gap:4px;align-items:center;margin-top:6px}
.rbp button,.rbp select{font:inherit;font-size:13px;padding:2px 8px;border:1px solid #b7bcc7;border-radius:3px;background:#f7f8fa;color:#1e1e1e;cursor:pointer}
.rbp button:hover{background:#e9ecf2}
.rbp button.rbp-on{background:#3b5fa8;border-color:#3b5fa8;color:#fff}
.rbp-play{min-width:4.5em}
.rbp-slider{flex:1 1 160px;min-width:120px;margin:0 6px}
.rbp-label{font-size:12px;color:#555;margin-right:2px}
.rbp-side{flex:0 0 270px;max-width:100%}
.rbp-title{font-weight:600;margin-bottom:4px;word-break:break-word}
.rbp-read{font:13px/1.5 ui-monospace,"DejaVu Sans Mono",Menlo,Consolas,monospace;white-space:pre}
.rbp-plotbox{position:relative;width:272px;margin-top:6px}
.rbp-plot{display:block;width:270px;height:130px;border:1px solid #c9ccd4;border-radius:3px;background:#fff;cursor:crosshair}
.rbp-cursor,.rbp-dot{position:absolute;left:0;top:0;background:#d0211a;pointer-events:none;will-change:transform}
.rbp-cursor{width:1.5px;opacity:.6}
.rbp-dot{width:6px;height:6px;border-radius:50%}
.rbp-help{font-size:12px;color:#666;margin-top:6px}
.rbp-reversal:disabled{opacity:.45;cursor:default}
.rbp:fullscreen{background:#fff;margin:0;padding:16px;box-sizing:border-box;overflow:auto;align-items:flex-start;flex-wrap:nowrap}
.rbp:fullscreen .rbp-main{flex:1 1 auto;min-width:0}
.rbp:fullscreen .rbp-stage{width:min(100%,calc((100vh - 120px) * 16 / 9))}
.rbp:fullscreen .rbp-side{flex:0 0 300px}
.rbp:fullscreen .rbp-read{font-size:20px}
.rbp-missing{padding:10px 12px;border:1px dashed #c9a0a0;border-radius:4px;color:#7a2e2e;background:#fbf4f4;font:14px system-ui,sans-serif;margin:8px 0}
`;

function injectStyle() {
  if (document.getElementById('rb-player-style')) return;
  const style = document.createElement('style');
  style.id = 'rb-player-style';
  style.textContent = STYLE;
  (document.head || document.documentElement).appendChild(style);
}

function el(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

// ---------------------------------------------------------------------------------------------
// The run's data.

const SERIES = ['t', 'x', 'y', 'z', 'qw', 'qx', 'qy', 'qz', 'spin'];

// Why `run` cannot be played, or '' when it can.
function problemWith(run) {
  if (!run || typeof run !== 'object') return 'no data';
  const n = run.t && run.t.length;
  if (!n) return 'no samples';
  for (const k of SERIES) if (!run[k] || run[k].length !== n) return `series ${k} missing or of another length`;
  for (const k of ['top', 'bottom']) if (!run[k] || run[k].length % 3) return `points ${k} missing`;
  if (run.top.length + run.bottom.length === 0) return 'no points';
  for (let i = 1; i < n; i++) if (!(run.t[i] > run.t[i - 1])) return 'times not increasing';
  return '';
}

// The body's geometry from the points: extents, spacing, footprint.
function bodyGeometry(run) {
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
  // Spacing: the median distance to the nearest neighbour over a sample of points.
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
  const spacing = nearest.length ? nearest[nearest.length >> 1] : 2 * r;
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

// The floor's meshes, in the parameters FLOOR_VERTEX places them by. Rings: the centre and
// FADE_RINGS + 1 rings from fadeNear to fadeFar, FADE_SIDES around (the polygon's chords fall
// short of the circle by 0.2 %); rows: one nearest the camera and FOG_ROWS + 1 from fogNear to
// fogFar, each two vertices across. Each mesh has two groups: up to where the fade or fog
// begins (the disc inside the first ring, the rows up to fogNear: drawn NEAR) and beyond.
const FADE_SIDES = 48;
const FADE_RINGS = 10;
const FOG_ROWS = 16;

function fadeRings() {
  const position = [0, -1, 0];
  for (let k = 0; k <= FADE_RINGS; k++) {
    for (let j = 0; j < FADE_SIDES; j++) position.push((2 * Math.PI * j) / FADE_SIDES, k / FADE_RINGS, 0);
  }
  const index = [];
  const at = (k, j) => 1 + k * FADE_SIDES + (j % FADE_SIDES);
  for (let j = 0; j < FADE_SIDES; j++) index.push(0, at(0, j), at(0, j + 1));
  const near = index.length;
  for (let k = 0; k < FADE_RINGS; k++) {
    for (let j = 0; j < FADE_SIDES; j++) {
      index.push(at(k, j), at(k + 1, j), at(k + 1, j + 1), at(k, j), at(k + 1, j + 1), at(k, j + 1));
    }
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(position), 3));
  geometry.setIndex(index);
  geometry.addGroup(0, near, 0);
  geometry.addGroup(near, index.length - near, 1);
  return geometry;
}

function fogRows() {
  const position = [-1, -1, 0, 1, -1, 0];
  for (let k = 0; k <= FOG_ROWS; k++) position.push(-1, k / FOG_ROWS, 0, 1, k / FOG_ROWS, 0);
  const index = [];
  for (let k = 0; k <= FOG_ROWS; k++) {
    const a = 2 * k, b = 2 * k + 2; // this row's left vertex, the next row's
    index.push(a, a + 1, b + 1, a, b + 1, b);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(position), 3));
  geometry.setIndex(index);
  geometry.addGroup(0, 6, 0);
  geometry.addGroup(6, index.length - 6, 1);
  return geometry;
}

// ---------------------------------------------------------------------------------------------
// One player.

const players = [];

// The averaged theory's forecast of the first reversal, from the container's data-forecast
// (analyze's "predicted_first_reversal", JSON): {time, range} when it applies (the body stands,
// n²ρ/g and the rocking within the theory's reach: range not "outside") and falls within the
// run, else null, as the report's text gives no time then.
function forecastOf(container, t0, tEnd) {
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

class Player {
  constructor(container, run) {
    this.container = container;
    this.run = run;
    this.n = run.t.length;
    this.t0 = run.t[0];
    this.tEnd = run.t[this.n - 1];
    this.time = this.t0;
    this.playing = false;
    this.speed = 1;
    this.viewName = 'oblique';
    this.lastView = 'oblique';
    this.dirty = true;
    this.visible = true;
    this.fixedSize = null;
    this.frameTimes = []; // intervals between consecutive drawn animation frames, ms
    this.renderTimes = []; // CPU time of renderer.render, ms
    this.lastFrameAt = null;
    this.drawnKey = new Float64Array(36); // the camera and canvas of the last frame drawn
    this.drawnCamera = null;
    this.bodyDrawnAt = null; // where the body and its shadow were in the last frame drawn
    this.redrawAll = true; // the next frame is drawn whole
    this.alwaysAll = false; // every frame is drawn whole (to compare, measure)
    this.shortcuts = true; // floor without depth, shadow alone, where they may be (to compare)
    this.partialFrames = 0;
    this.drawnFrames = 0;
    this.scratch = new Vector3();
    this.bufferSize = new Vector2();
    this.floorMatrix = new Matrix4();
    this.floorRows = new Matrix3();
    this.axis = new Vector3();
    this.forward = new Vector3();
    this.spinNow = run.spin[0];
    this.forecast = forecastOf(container, this.t0, this.tEnd);
    this.qa = new Quaternion();
    this.qb = new Quaternion();
    this.buildDom();
    this.buildScene();
    this.bindEvents();
    this.setView('oblique');
    this.applyTime(this.t0);
    this.render();
    this.loop = this.loop.bind(this);
    this.heldReadouts = false;
    this.drawQueued = false;
    this.pixel = new Uint8Array(4);
    this.afterFrame = typeof MessageChannel !== 'undefined' ? new MessageChannel() : null;
    if (this.afterFrame) this.afterFrame.port1.onmessage = () => this.drawAfterFrame();
    requestAnimationFrame(this.loop);
  }

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

    const bar = el('div', 'rbp-bar');
    const button = (text, title, handler, extra) => {
      const b = el('button', extra || '', text);
      b.type = 'button';
      b.title = title;
      b.addEventListener('click', handler);
      return b;
    };
    this.backButton = button('◀|', 'Step back one sample (←)', () => this.step(-1), 'rbp-back');
    this.playButton = button('▶ Play', 'Play / pause (space)', () => this.toggle(), 'rbp-play');
    this.forwardButton = button('|▶', 'Step forward one sample (→)', () => this.step(1), 'rbp-forward');
    // To the moment the spin passes zero, the picture a lesson stops at (a teacher's trial:
    // found by stepping with the arrows, or by a click on the plot that lands near it).
    const reversals = this.run.reversals || [];
    this.reversalButton = button('⟲ Reversal', reversals.length ? 'Go to the next reversal, where the spin passes zero (R)' : 'No reversal in this run',
                                 () => this.gotoReversal(), 'rbp-reversal');
    this.reversalButton.disabled = reversals.length === 0;
    // Full screen, for a projector: the picture and its read-outs as large as the screen allows.
    // (Words, not a symbol: the page's fonts may lack the full-screen glyph, drawn as a box.)
    this.fullButton = button('Full screen', 'Full screen (F; Esc leaves it)', () => this.toggleFullScreen(), 'rbp-full');
    this.slider = el('input', 'rbp-slider');
    this.slider.type = 'range';
    this.slider.min = String(this.t0);
    this.slider.max = String(this.tEnd);
    this.slider.step = 'any';
    this.slider.value = String(this.t0);
    this.slider.setAttribute('aria-label', 'time (s)');
    this.slider.addEventListener('input', () => this.setTime(parseFloat(this.slider.value), false));
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
    this.speedSelect.addEventListener('keydown', () => { this.speedKeyed = true; });
    this.speedSelect.addEventListener('pointerdown', () => { this.speedKeyed = false; });
    this.speedSelect.addEventListener('blur', () => { this.speedKeyed = false; });
    this.speedSelect.addEventListener('change', () => {
      this.setSpeed(parseFloat(this.speedSelect.value));
      if (!this.speedKeyed) this.root.focus({ preventScroll: true });
    });
    bar.append(this.backButton, this.playButton, this.forwardButton, this.reversalButton, this.slider,
               el('span', 'rbp-label', 'speed'), this.speedSelect, this.fullButton);
    main.appendChild(bar);

    const views = el('div', 'rbp-views');
    views.appendChild(el('span', 'rbp-label', 'view'));
    this.viewButtons = {};
    for (const v of VIEWS) {
      const b = button(v[0].toUpperCase() + v.slice(1), `View: ${v}`, () => this.setView(v), `rbp-view rbp-view-${v}`);
      b.dataset.view = v;
      this.viewButtons[v] = b;
      views.appendChild(b);
    }
    this.freeButton = button('Free', 'Drag to orbit, right-drag to pan, wheel to zoom', () => this.setView('free'), 'rbp-view rbp-view-free');
    this.freeButton.dataset.view = 'free';
    this.viewButtons.free = this.freeButton;
    views.appendChild(this.freeButton);
    main.appendChild(views);

    const side = el('div', 'rbp-side');
    side.appendChild(el('div', 'rbp-title', this.run.title || this.run.id || 'run'));
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
    const nrev = (this.run.reversals || []).length;
    side.appendChild(el('div', 'rbp-help',
      (nrev ? `${nrev} reversal${nrev === 1 ? '' : 's'} (orange)` : 'No reversal in this run') +
      (this.forecast ? ', the averaged theory\'s forecast of the first (violet)' : '') +
      '. Drag: orbit, right-drag: pan, wheel: zoom. ' +
      'Keys: space play/pause, ← → step one sample (' + formatStep(this.run.t) + '), ' +
      'Home / End the start / end, R the next reversal, F full screen.'));
    root.append(main, side);
    c.appendChild(root);
    this.root = root;
  }

  // --- three.js scene ----------------------------------------------------------------------
  buildScene() {
    const run = this.run;
    // The context is made here, not by three.js, which always asks for an alpha channel: an
    // opaque canvas (alpha: false) lets Chromium draw it over nothing and skip what is under
    // it, instead of blending it over the page each frame (on software WebGL that halved the
    // cost of a frame on the report page; bench/player_speed.py).
    const attributes = {
      alpha: false,
      depth: true,
      stencil: false,
      antialias: false, // the spheres and the checker smooth their own edges: cheaper
      premultipliedAlpha: true,
      preserveDrawingBuffer: true, // kept between frames: render() redraws only what changed
      powerPreference: 'low-power',
    };
    const context = this.canvas.getContext('webgl2', attributes);
    if (!context) throw new Error('WebGL 2 is unavailable');
    this.renderer = new WebGLRenderer({ canvas: this.canvas, context, ...attributes });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.canvas.addEventListener('webglcontextrestored', () => {
      this.redrawAll = true;
      this.dirty = true;
    });
    this.scene = new Scene();
    this.scene.background = new Color().setRGB(...BACKGROUND, SRGBColorSpace);
    const body = bodyGeometry(run);
    this.body = body;
    this.framing = {
      center: new Vector3(run.x[0], run.y[0], run.z[0]),
      radius: 1.25 * (body.frame > 0 ? 0.5 * body.frame : body.reach),
    };
    this.pointsMaterial = new ShaderMaterial({
      vertexShader: POINTS_VERTEX,
      fragmentShader: POINTS_FRAGMENT,
      uniforms: {
        radius: { value: body.radius },
        spacing: { value: body.spacing },
        viewportHeight: { value: 720 },
        lightView: { value: new Vector3(0.3, 0.5, 0.81).normalize() },
        halfView: { value: new Vector3(0.3, 0.5, 1.81).normalize() },
        floorDepth: { value: new Vector3(0, 0, 2) },
      },
      transparent: true,
      depthWrite: true,
    });
    this.points = new Points(body.geometry, this.pointsMaterial);
    this.points.frustumCulled = false;
    this.scene.add(this.points);

    // The floor: over the body's whole wander, and far enough beyond it to fade out.
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (let i = 0; i < this.n; i++) {
      x0 = Math.min(x0, run.x[i]); x1 = Math.max(x1, run.x[i]);
      y0 = Math.min(y0, run.y[i]); y1 = Math.max(y1, run.y[i]);
    }
    const size = body.frame > 0 ? 0.5 * body.frame : Math.max(...body.halfExtent);
    const margin = 14 * size + 20 * this.framing.radius;
    // FOG's band reaches as far as the floor did when it was a plane over this rectangle.
    const reach = Math.hypot(x1 - x0 + 2 * margin, y1 - y0 + 2 * margin);
    this.floorGeometries = { fade: fadeRings(), fog: fogRows() };
    const raw = size / 5;
    const decade = Math.pow(10, Math.floor(Math.log10(raw)));
    this.tile = raw / decade < 2 ? decade : raw / decade < 5 ? 2 * decade : 5 * decade;
    // The read-out of the square, seen level (front, side: four times deeper) or not; made once.
    this.scaleText = {
      level: `floor squares ${lengthText(4 * this.tile)}`,
      other: `floor squares ${lengthText(this.tile)}`,
    };
    this.size = size;
    const floorUniforms = {
      tile: { value: this.tile },
      background: { value: new Vector3(...BACKGROUND) },
      center: { value: new Vector2() },
      fadeNear: { value: 3 * size },
      fadeFar: { value: 12 * size },
      depthDirection: { value: new Vector2() },
      fogNear: { value: 0 },
      fogFar: { value: 0 },
      shadowCenter: { value: new Vector2() },
      shadowAxis: { value: new Vector2(0, 1) },
      shadowHalf: { value: new Vector2(...body.footprintHalf) },
      shadowStrength: { value: 0.45 },
      reach: { value: reach },
    };
    this.floorMaterial = new ShaderMaterial({
      vertexShader: FLOOR_VERTEX,
      fragmentShader: FLOOR_FRAGMENT,
      uniforms: floorUniforms,
      defines: {},
    });
    // (where the fade or fog has not begun: the same, NEAR)
    this.floorNearMaterial = new ShaderMaterial({
      vertexShader: FLOOR_VERTEX,
      fragmentShader: FLOOR_FRAGMENT,
      uniforms: floorUniforms,
      defines: { NEAR: 1 },
    });
    this.floor = new Mesh(this.floorGeometries.fade, [this.floorNearMaterial, this.floorMaterial]);
    this.floor.frustumCulled = false; // placed by its shader
    this.floor.renderOrder = -2;
    this.scene.add(this.floor);
    // The contact shadow: a quad over the floor around the body (placed in applyTime), drawn
    // after the floor with the floor's formula and the shadow (same uniforms), before the body.
    this.shadowMaterial = new ShaderMaterial({
      vertexShader: FLOOR_VERTEX,
      fragmentShader: FLOOR_FRAGMENT,
      uniforms: floorUniforms,
      defines: { SHADOW: 1 },
      depthTest: false,
      depthWrite: false,
    });
    // (where the floor under the quad is NEAR: the shadow alone, multiplying it: chooseShadow)
    this.shadowOverMaterial = new ShaderMaterial({
      vertexShader: SHADOW_VERTEX,
      fragmentShader: SHADOW_FRAGMENT,
      uniforms: floorUniforms,
      depthTest: false,
      depthWrite: false,
      blending: CustomBlending,
      blendSrc: ZeroFactor,
      blendDst: SrcColorFactor,
      blendSrcAlpha: ZeroFactor,
      blendDstAlpha: OneFactor,
    });
    this.shadow = new Mesh(new PlaneGeometry(2 * SHADOW_REACH, 2 * SHADOW_REACH), this.shadowMaterial);
    this.shadow.scale.set(body.footprintHalf[0], body.footprintHalf[1], 1);
    this.shadow.renderOrder = -1;
    this.scene.add(this.shadow);

    // Cameras, z up: a perspective one (oblique, follow) and an orthographic one (above, front,
    // side), each with its own orbit controls; any drag or zoom makes the view "free".
    this.perspective = new PerspectiveCamera(30, 16 / 9, 0.01, 100);
    this.orthographic = new OrthographicCamera(-1, 1, 1, -1, 0.01, 100);
    this.controls = {};
    for (const camera of [this.perspective, this.orthographic]) {
      camera.up.copy(UP);
      const controls = new OrbitControls(camera, this.canvas);
      controls.enabled = false;
      controls.enableDamping = false;
      controls.zoomToCursor = false;
      // Never under the floor, nor inside the body or so far off that it vanishes (a teacher's
      // trial: orbit went below the floor, zoom into the body or out until nothing showed).
      controls.maxPolarAngle = 88 * DEG;
      if (camera.isPerspectiveCamera) {
        controls.minDistance = 1.2 * this.body.reach;
        controls.maxDistance = 40 * this.framing.radius;
      }
      let interacting = false;
      controls.addEventListener('start', () => { interacting = true; });
      controls.addEventListener('end', () => { interacting = false; });
      controls.addEventListener('change', () => {
        if (interacting && this.viewName !== 'free') this.makeFree();
        this.dirty = true;
      });
      this.controls[camera.type] = controls;
    }
    this.camera = this.perspective;
    this.resize();
  }

  activeControls() {
    return this.controls[this.camera.type];
  }

  useCamera(camera) {
    this.camera = camera;
    for (const c of Object.values(this.controls)) c.enabled = false;
    this.activeControls().enabled = true;
  }

  // The stage's size: 16:9 across the column, or as fixed by the test hook.
  resize() {
    let w, h;
    if (this.fixedSize) {
      [w, h] = this.fixedSize;
    } else {
      w = Math.max(16, Math.round(this.stage.clientWidth || 640));
      h = Math.max(9, Math.round(this.stage.clientHeight || (w * 9) / 16));
    }
    this.updateSampling(w, h);
    if (w === this.width && h === this.height) return;
    this.width = w;
    this.height = h;
    this.renderer.setSize(w, h, false);
    this.renderer.getDrawingBufferSize(this.bufferSize);
    this.pointsMaterial.uniforms.viewportHeight.value = this.bufferSize.y;
    if (this.viewName === 'free') {
      // Keep the free camera, fit its projection to the new aspect.
      const aspect = w / h;
      this.perspective.aspect = aspect;
      this.perspective.updateProjectionMatrix();
      const o = this.orthographic;
      const halfH = o.top;
      o.left = -halfH * aspect;
      o.right = halfH * aspect;
      o.updateProjectionMatrix();
    } else {
      this.placeCamera();
    }
    this.dirty = true;
  }

  // How the compositor samples the canvas onto the page: nearest (image-rendering: pixelated)
  // where the drawing buffer is one to one with the device pixels the canvas covers, else as
  // usual (filtered). Chromium compositing on the CPU draws a WebGL canvas through a transform
  // (most likely a flip: its rows are read back bottom first), and Skia samples it with a
  // bilinear filter even one to one at a whole pixel unless told nearest: the same picture, for
  // 2–3 ms more of the GPU process's CPU a follow frame (docs/speed.md, eighth session).
  // A box of fractional CSS pixels (the stage's 16:9 of its column's width) is within a device
  // pixel of the buffer: nearest there shows every pixel as drawn but for a row or column
  // dropped or doubled at most, where a filter would smear them all by the fraction. Scaled
  // further (a device pixel ratio above the 2 the buffer is held to), filtered.
  updateSampling(w, h) {
    const dpr = window.devicePixelRatio || 1;
    let exact = this.renderer.getPixelRatio() === dpr;
    if (exact) {
      const box = this.canvas.getBoundingClientRect();
      const bw = Math.floor(w * dpr), bh = Math.floor(h * dpr); // the buffer, as three sizes it
      exact = Math.abs(box.width * dpr - bw) < 1 && Math.abs(box.height * dpr - bh) < 1;
    }
    const rendering = exact ? 'pixelated' : '';
    if (this.canvas.style.imageRendering !== rendering) this.canvas.style.imageRendering = rendering;
  }

  // --- views: as the renderer places them (render/camera.cpp) -------------------------------
  setView(name) {
    if (!VIEWS.includes(name) && name !== 'free') throw new Error(`unknown view ${name}`);
    if (name === 'free') {
      this.makeFree();
    } else {
      this.viewName = name;
      this.lastView = name;
      this.placeCamera();
    }
    this.updateViewButtons();
    this.dirty = true;
  }

  makeFree() {
    this.viewName = 'free';
    this.updateViewButtons();
  }

  updateViewButtons() {
    for (const [v, b] of Object.entries(this.viewButtons)) b.classList.toggle('rbp-on', v === this.viewName);
  }

  placeCamera() {
    const aspect = this.width / this.height;
    const target = this.framing.center;
    const r = this.framing.radius;
    const fov = 30 * DEG;
    const narrow = aspect >= 1 ? fov : 2 * Math.atan(Math.tan(fov / 2) * aspect);
    const ortho = (direction, across, upwards) => {
      const o = this.orthographic;
      const halfW = 1.1 * Math.max(across, upwards * aspect);
      o.left = -halfW;
      o.right = halfW;
      o.top = halfW / aspect;
      o.bottom = -halfW / aspect;
      o.near = 0.1 * r;
      o.far = 40 * r;
      o.zoom = 1;
      o.updateProjectionMatrix();
      o.position.copy(target).addScaledVector(direction, 20 * r);
      o.lookAt(target);
      this.useCamera(o);
      this.activeControls().target.copy(target);
    };
    const halfHeight = this.body.halfExtent[2];
    const sinE = Math.sin(ELEVATION), cosE = Math.cos(ELEVATION);
    switch (this.viewName) {
      case 'above': {
        // Straight down with +y to the right and +x down the screen: the eye a hair towards
        // +x, so that looking at the target with z up turns the picture that way (and orbiting
        // from there is smooth).
        const tilt = 1e-4;
        ortho(new Vector3(Math.sin(tilt), 0, Math.cos(tilt)), r, r);
        break;
      }
      case 'front':
        ortho(new Vector3(0, -cosE, sinE), r, halfHeight + r * sinE);
        break;
      case 'side':
        ortho(new Vector3(cosE, 0, sinE), r, halfHeight + r * sinE);
        break;
      case 'oblique': {
        const distance = (1.1 * r) / Math.sin(narrow / 2);
        const p = this.perspective;
        p.fov = 30;
        p.aspect = aspect;
        p.zoom = 1;
        p.near = 0.02 * distance;
        p.far = 40 * distance;
        p.updateProjectionMatrix();
        p.position.copy(target).addScaledVector(new Vector3(0.75, -0.55, 0.55).normalize(), distance);
        p.lookAt(target);
        this.useCamera(p);
        this.activeControls().target.copy(target);
        break;
      }
      case 'follow':
        this.placeChase();
        break;
      default:
        break;
    }
  }

  // Follow: beside the body across its long axis, 25° above, moving and turning with it.
  placeChase() {
    const aspect = this.width / this.height;
    const fov = 30 * DEG;
    const narrow = aspect >= 1 ? fov : 2 * Math.atan(Math.tan(fov / 2) * aspect);
    const elevation = 25 * DEG;
    const q = this.points.quaternion;
    const axis = new Vector3(0, 1, 0).applyQuaternion(q); // the long axis, world
    let hx = axis.x, hy = axis.y;
    const norm = Math.hypot(hx, hy);
    if (norm > 1e-6) { hx /= norm; hy /= norm; } else { hx = 0; hy = 1; }
    const middle = this.points.position.clone();
    middle.z += this.body.middleHeight;
    const framed = this.body.frame > 0 ? 0.5 * this.body.frame : this.body.reach;
    const distance = (1.1 * framed) / Math.sin(narrow / 2);
    const direction = new Vector3(-hy * Math.cos(elevation), hx * Math.cos(elevation), Math.sin(elevation));
    const p = this.perspective;
    p.fov = 30;
    p.aspect = aspect;
    p.zoom = 1;
    p.near = 0.02 * distance;
    p.far = 40 * distance;
    p.updateProjectionMatrix();
    p.position.copy(middle).addScaledVector(direction, distance);
    p.lookAt(middle);
    if (this.camera !== p) this.useCamera(p);
    this.activeControls().target.copy(middle);
  }

  // --- time ----------------------------------------------------------------------------------
  // The sample interval [i, i + 1] holding t, and how far along it t is.
  locate(t) {
    const ts = this.run.t;
    const n = this.n;
    if (n === 1 || t <= ts[0]) return [0, 0];
    if (t >= ts[n - 1]) return [n - 2, 1];
    let lo = 0, hi = n - 1; // ts[lo] <= t < ts[hi]
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= t) lo = mid; else hi = mid;
    }
    return [lo, (t - ts[lo]) / (ts[hi] - ts[lo])];
  }

  // s between samples i and j = i + 1, a of the way along: the cubic through s[i] and s[j]
  // with the slopes of the central differences there (one-sided at the ends).
  cubic(s, i, j, a) {
    if (j === i) return s[i];
    const ts = this.run.t;
    const last = this.n - 1;
    const slope = (k) => {
      const lo = Math.max(0, k - 1), hi = Math.min(last, k + 1);
      return (s[hi] - s[lo]) / (ts[hi] - ts[lo]);
    };
    const h = ts[j] - ts[i];
    const a2 = a * a, a3 = a2 * a;
    return (2 * a3 - 3 * a2 + 1) * s[i] + (a3 - 2 * a2 + a) * h * slope(i) +
      (3 * a2 - 2 * a3) * s[j] + (a3 - a2) * h * slope(j);
  }

  // The pose at time t; the read-outs too, or (hold) at the next animation frame, the one that
  // shows the picture of this pose (drawn after the current frame: loop()).
  applyTime(t, hold) {
    const run = this.run;
    t = Math.min(this.tEnd, Math.max(this.t0, t));
    this.time = t;
    const [i, a] = this.locate(t);
    const j = Math.min(i + 1, this.n - 1);
    const lerp = (s) => s[i] + (s[j] - s[i]) * a;
    this.points.position.set(lerp(run.x), lerp(run.y), lerp(run.z));
    // three's Quaternion is (x, y, z, w); the data is scalar first.
    this.qa.set(run.qx[i], run.qy[i], run.qz[i], run.qw[i]);
    this.qb.set(run.qx[j], run.qy[j], run.qz[j], run.qw[j]);
    this.points.quaternion.slerpQuaternions(this.qa, this.qb, a);
    this.points.updateMatrixWorld(true);
    // The spin by a cubic between the samples (Hermite, each sample's slope from its
    // neighbours): n curves through a reversal, where the straight line between poses 10 ms
    // apart read +0.04 rad/s at Kane & Levinson's (a teacher's trial, the Reversal button).
    this.spinNow = this.cubic(run.spin, i, j, a);
    // The floor's contact shadow follows the body.
    const u = this.floorMaterial.uniforms;
    u.shadowCenter.value.set(this.points.position.x, this.points.position.y);
    const axis = this.axis.set(0, 1, 0).applyQuaternion(this.points.quaternion);
    const norm = Math.hypot(axis.x, axis.y);
    if (norm > 1e-6) u.shadowAxis.value.set(axis.x / norm, axis.y / norm); else u.shadowAxis.value.set(0, 1);
    // Its quad: local x across the body's long axis, y along it.
    const along = u.shadowAxis.value;
    this.shadow.position.set(this.points.position.x, this.points.position.y, 0);
    this.shadow.rotation.set(0, 0, Math.atan2(-along.x, along.y));
    if (this.viewName === 'follow') this.placeChase();
    this.heldReadouts = !!hold;
    if (!hold) this.updateReadouts();
    this.dirty = true;
  }

  setTime(t, renderNow) {
    if (!Number.isFinite(t)) return;
    this.applyTime(t);
    if (renderNow) this.render();
  }

  // One sample interval back or forward, from the sample at or next to the current time.
  step(direction) {
    this.pause();
    const ts = this.run.t;
    // A time within a twentieth of a sample interval of a sample counts as that sample: paused
    // at 1.4999 s, → went to 1.50, the same picture and read-out, and the key seemed dead.
    const interval = this.n > 1 ? (ts[this.n - 1] - ts[0]) / (this.n - 1) : 0;
    const eps = Math.max(1e-9 * Math.max(1, Math.abs(this.tEnd)), 0.05 * interval);
    let [i, a] = this.locate(this.time);
    if (this.time >= this.tEnd) { i = this.n - 1; a = 0; }
    let k;
    if (direction > 0) {
      k = i + 1;
      while (k < this.n - 1 && ts[k] <= this.time + eps) k++;
    } else {
      k = a > 0 && ts[i] < this.time - eps ? i : i - 1;
    }
    k = Math.max(0, Math.min(this.n - 1, k));
    this.setTime(ts[k], false);
  }

  play() {
    if (this.playing) return;
    if (this.time >= this.tEnd) this.applyTime(this.t0); // at the end: from the start again
    this.playing = true;
    this.playStartedAt = null;
    this.updatePlayButton();
  }

  // Stops where the player is seen to be. Playback applies each pose a frame before it shows it
  // (loop: the picture is drawn after the frame, the read-outs held for the next); paused in
  // between, the pose applied and not yet shown would appear at the next frame, one frame on
  // from the moment paused at. It is taken back instead: time returns to the read-outs' time,
  // and that pose is drawn now, before the next frame, which shows it.
  pause() {
    if (!this.playing) return;
    this.playing = false;
    if (this.heldReadouts) {
      this.applyTime(this.shownTime);
      this.render();
    }
    this.updatePlayButton();
  }

  toggle() {
    if (this.playing) this.pause(); else this.play();
  }

  // Paused at the next reversal after the time shown (a hair after one counts as at it), or the
  // first after the last.
  gotoReversal() {
    const reversals = this.run.reversals || [];
    if (!reversals.length) return;
    this.pause();
    const eps = 1e-9 * Math.max(1, Math.abs(this.tEnd));
    const next = reversals.find((r) => r > this.time + eps);
    this.setTime(Math.min(this.tEnd, Math.max(this.t0, next === undefined ? reversals[0] : next)), false);
  }

  toEnd(end) {
    this.pause();
    this.setTime(end ? this.tEnd : this.t0, false);
  }

  toggleFullScreen() {
    if (document.fullscreenElement) {
      if (document.exitFullscreen) document.exitFullscreen();
    } else if (this.root.requestFullscreen) {
      this.root.requestFullscreen().catch(() => {});
    }
  }

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
  }

  updatePlayButton() {
    this.playButton.textContent = this.playing ? '❚❚ Pause' : '▶ Play';
    this.playButton.classList.toggle('rbp-on', this.playing);
  }

  // --- read-outs and the n(t) plot ------------------------------------------------------------
  // The read-outs, the slider and the plot's cursor at the current time; each element is written
  // only when what it shows changes (a write costs the page a style, layout and paint pass).
  updateReadouts() {
    const t = this.time;
    this.shownTime = t; // (pause goes back to it)
    const spin = Math.abs(this.spinNow) < 0.005 ? 0 : this.spinNow;
    const signed = (spin >= 0 ? '+' : '-') + Math.abs(spin).toFixed(2);
    this.show(this.readTime, `t = ${t.toFixed(2).padStart(6)} s`);
    this.show(this.readSpin, `spin n = ${signed.padStart(6)} rad/s`);
    this.show(this.readSense, spin > 0.05 ? '(counter-clockwise)' : spin < -0.05 ? '(clockwise)' : '\u00a0');
    if (document.activeElement !== this.slider || !this.sliderDragging) this.slider.value = String(t);
    this.moveCursor();
  }

  show(element, text) {
    if (element.rbText !== text) {
      element.textContent = text;
      element.rbText = text;
    }
  }

  plotLayout() {
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    if (this.layout && this.layout.dpr === dpr) return this.layout;
    const w = 270, h = 130;
    this.plot.width = Math.round(w * dpr);
    this.plot.height = Math.round(h * dpr);
    this.plotDrawn = null;
    let m = 0;
    for (const v of this.run.spin) m = Math.max(m, Math.abs(v));
    m = m > 0 ? 1.1 * m : 1;
    const box = { left: 34, right: w - 8, top: 8, bottom: h - 20 };
    const span = this.tEnd - this.t0 || 1;
    this.layout = {
      dpr, w, h, m, box,
      x: (t) => box.left + ((t - this.t0) / span) * (box.right - box.left),
      y: (n) => box.top + ((m - n) / (2 * m)) * (box.bottom - box.top),
      tAt: (px) => this.t0 + ((px - box.left) / (box.right - box.left)) * span,
    };
    return this.layout;
  }

  // The cursor at the current time: a line across the plot and a dot on the curve, moved (CSS
  // transforms, whole 0.1 px) over the plot drawn once. The plot's border is 1 px.
  moveCursor() {
    const L = this.plotLayout();
    if (!this.plotDrawn) this.drawPlot();
    const x = Math.round(10 * (1 + L.x(this.time))) / 10;
    const y = Math.round(10 * (1 + L.y(this.spinNow))) / 10;
    if (x === this.cursorX && y === this.cursorY) return;
    if (this.cursorX === undefined) {
      // Below the forecast's label, which it would cover near the reversal (a teacher's trial);
      // see-through, so that the reversal's orange line under it stays orange.
      const top = L.box.top + (this.forecast ? FORECAST_LABEL_HEIGHT : 0);
      this.cursorLine.style.top = `${1 + top}px`;
      this.cursorLine.style.height = `${L.box.bottom - top}px`;
    }
    this.cursorX = x;
    this.cursorY = y;
    this.cursorLine.style.transform = `translate(${x - 0.75}px,0)`;
    this.cursorDot.style.transform = `translate(${x - 3}px,${y - 3}px)`;
  }

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
    // Reversals: dashed orange lines.
    g.strokeStyle = '#e08a00';
    g.setLineDash([3, 3]);
    for (const tr of this.run.reversals || []) {
      g.beginPath();
      g.moveTo(L.x(tr), box.top);
      g.lineTo(L.x(tr), box.bottom);
      g.stroke();
    }
    g.setLineDash([]);
    // The averaged theory's forecast of the first reversal: a thin violet line, labelled.
    if (this.forecast) {
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
    }
    g.strokeStyle = '#2a2a2a';
    g.lineWidth = 1.3;
    g.beginPath();
    const { t, spin } = this.run;
    const every = Math.max(1, Math.floor(this.n / 600));
    for (let i = 0; i < this.n; i += every) {
      if (i === 0) g.moveTo(L.x(t[i]), L.y(spin[i])); else g.lineTo(L.x(t[i]), L.y(spin[i]));
    }
    g.lineTo(L.x(t[this.n - 1]), L.y(spin[this.n - 1]));
    g.stroke();
    g.fillStyle = '#e08a00';
    for (const tr of this.run.reversals || []) {
      g.beginPath();
      g.arc(L.x(tr), L.y(0), 3, 0, 2 * Math.PI);
      g.fill();
    }
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
    this.plotDrawn = true;
  }

  // --- events ----------------------------------------------------------------------------------
  bindEvents() {
    this.root.addEventListener('keydown', (e) => this.onKey(e));
    this.canvas.addEventListener('pointerdown', () => this.root.focus({ preventScroll: true }));
    this.slider.addEventListener('pointerdown', () => { this.sliderDragging = true; });
    window.addEventListener('pointerup', () => { this.sliderDragging = false; });
    const seek = (e) => {
      const rect = this.plot.getBoundingClientRect();
      this.setTime(this.plotLayout().tAt(e.clientX - rect.left), false);
    };
    this.plot.addEventListener('pointerdown', (e) => {
      this.plotDragging = true;
      this.plot.setPointerCapture(e.pointerId);
      seek(e);
    });
    this.plot.addEventListener('pointermove', (e) => { if (this.plotDragging) seek(e); });
    this.plot.addEventListener('pointerup', () => { this.plotDragging = false; });
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
  }

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
    } else if (e.key === 'f' || e.key === 'F') {
      this.toggleFullScreen();
    } else {
      return false;
    }
    e.preventDefault();
    e.stopPropagation();
    return true;
  }

  // --- drawing ---------------------------------------------------------------------------------
  // The floor's fade, for the camera as it is: along the floor away from an orthographic camera
  // that looks nearly level (front, side: the floor goes into the background below the top of
  // the frame, as the renderer's horizon), with distance from the target otherwise.
  updateFloorFade() {
    const u = this.floorMaterial.uniforms;
    const target = this.activeControls().target;
    u.center.value.set(target.x, target.y);
    const forward = this.camera.getWorldDirection(this.forward);
    const elevation = Math.asin(Math.max(-1, Math.min(1, -forward.z)));
    const level = this.camera.isOrthographicCamera && elevation > 1 * DEG && elevation < 30 * DEG;
    if (level) {
      const halfH = this.camera.top / this.camera.zoom;
      const far = (0.8 * halfH + target.z * Math.cos(elevation)) / Math.sin(elevation);
      u.depthDirection.value.set(forward.x, forward.y).normalize();
      u.fogFar.value = far;
      u.fogNear.value = Math.min(this.framing.radius, 0.5 * far);
      u.tile.value = 4 * this.tile; // squares 4× deeper show as bands, not stripes
      this.show(this.readScale, this.scaleText.level);
    } else {
      u.fogFar.value = 0;
      u.fogNear.value = 0;
      u.tile.value = this.tile;
      this.show(this.readScale, this.scaleText.other);
      const reachOut = this.camera.isOrthographicCamera ? this.camera.top / this.camera.zoom : 0;
      u.fadeNear.value = Math.max(3 * this.size, 1.5 * reachOut);
      u.fadeFar.value = Math.max(12 * this.size, 6 * reachOut);
    }
    // The floor's programs follow the mode (three keeps both once compiled).
    if (!!this.floorMaterial.defines.FOG !== level) {
      for (const m of [this.floorMaterial, this.floorNearMaterial, this.shadowMaterial]) {
        if (level) m.defines.FOG = 1; else delete m.defines.FOG;
        m.needsUpdate = true;
      }
      this.floor.geometry = level ? this.floorGeometries.fog : this.floorGeometries.fade;
    }
  }

  // The floor's depth for the points' shader to hide what is below the floor by, so that the
  // floor is drawn without depth (testing and writing the depth of most of the canvas's pixels
  // cost SwiftShader about a fifteenth of a follow frame). On a plane the window depth is
  // affine in the window's x and y: from clip = M (x, y, 0, 1) with M = projection × view,
  // (cx, cy, cw) = K (x, y, 1) and cz = l (x, y, 1), so cz / cw = l K⁻¹ (x_ndc, y_ndc, 1). Where
  // that does not hold the floor keeps its depth as before (floorDepth then hides nothing): the
  // camera below the floor (it is not drawn from there) or in its plane, or the body not wholly
  // over the floor's mesh (beyond it there is no floor to hide anything).
  updateFloorDepth() {
    const u = this.floorMaterial.uniforms;
    const camera = this.camera;
    const forward = camera.getWorldDirection(this.forward);
    const above = camera.isOrthographicCamera ? forward.z < -1e-6 : camera.position.z > 0;
    const body = this.points.position;
    const reach = this.body.reach;
    let over;
    if (this.floorMaterial.defines.FOG) {
      const d = u.depthDirection.value;
      const along = (body.x - u.center.value.x) * d.x + (body.y - u.center.value.y) * d.y;
      over = along + reach < u.fogFar.value;
    } else {
      const r = Math.hypot(body.x - u.center.value.x, body.y - u.center.value.y);
      over = r + reach < u.fadeFar.value * Math.cos(Math.PI / FADE_SIDES);
    }
    const matrix = this.floorMatrix.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    const m = matrix.elements;
    // (column-major: row r of M is m[r], m[4 + r], m[8 + r], m[12 + r])
    const k = this.floorRows.set(m[0], m[4], m[12], m[1], m[5], m[13], m[3], m[7], m[15]);
    const det = k.determinant();
    const depth = this.pointsMaterial.uniforms.floorDepth.value;
    const analytic = this.shortcuts && above && over && Math.abs(det) > 1e-12;
    if (analytic) {
      const inv = k.invert().elements; // column-major
      const l = [m[2], m[6], m[14]];
      const c = [0, 1, 2].map((j) => l[0] * inv[3 * j] + l[1] * inv[3 * j + 1] +
                                     l[2] * inv[3 * j + 2]);
      // window: x_ndc = 2 x / W - 1, y_ndc = 2 y / H - 1, depth = (z_ndc + 1) / 2
      const W = this.bufferSize.x, H = this.bufferSize.y;
      depth.set(c[0] / W, c[1] / H, 0.5 * (1 + c[2] - c[0] - c[1]));
    } else {
      depth.set(0, 0, 2);
    }
    for (const material of [this.floorMaterial, this.floorNearMaterial]) {
      material.depthTest = !analytic;
      material.depthWrite = !analytic;
    }
  }

  // The contact shadow's program: the shadow alone multiplying the floor when the floor under
  // its whole quad is NEAR (inside the fade's first ring, whose chords fall short of fadeNear by
  // cos(π / FADE_SIDES), or before fogNear), else the floor's formula with the shadow.
  chooseShadow() {
    const u = this.floorMaterial.uniforms;
    const center = u.shadowCenter.value, axis = u.shadowAxis.value, half = u.shadowHalf.value;
    const fog = !!this.floorMaterial.defines.FOG;
    const d = u.depthDirection.value;
    let near = this.shortcuts;
    for (let c = 0; c < 4; c++) {
      const across = (c & 1 ? SHADOW_REACH : -SHADOW_REACH) * half.x;
      const along = (c & 2 ? SHADOW_REACH : -SHADOW_REACH) * half.y;
      const x = center.x + across * axis.y + along * axis.x - u.center.value.x;
      const y = center.y - across * axis.x + along * axis.y - u.center.value.y;
      if (fog ? x * d.x + y * d.y > u.fogNear.value
              : Math.hypot(x, y) > u.fadeNear.value * Math.cos(Math.PI / FADE_SIDES)) near = false;
    }
    this.shadow.material = near ? this.shadowOverMaterial : this.shadowMaterial;
  }

  // Draws the picture. Software WebGL pays for every pixel drawn, and the floor alone covers
  // most of the canvas: while the camera stays (playing or stepping in a fixed view) only the
  // part where the body and its shadow were and now are changes, so only that part is cleared
  // and drawn again (a scissor; the canvas keeps the rest, preserveDrawingBuffer).
  render() {
    const started = performance.now();
    this.updateFloorFade();
    this.camera.updateMatrixWorld();
    this.updateFloorDepth();
    this.chooseShadow();
    const rect = this.changedRect();
    const renderer = this.renderer;
    if (rect) {
      renderer.setScissor(rect[0], rect[1], rect[2], rect[3]);
      renderer.setScissorTest(true);
    }
    renderer.render(this.scene, this.camera);
    if (rect) renderer.setScissorTest(false);
    this.partialFrames += rect ? 1 : 0;
    this.drawnFrames += 1;
    this.renderTimes.push(performance.now() - started);
    if (this.renderTimes.length > 60) this.renderTimes.shift();
    this.dirty = false;
  }

  // The part of the canvas to draw again, [x, y, width, height] in CSS pixels from its bottom
  // left corner, or null for all of it: the camera, the canvas or the floor's fade changed since
  // the last frame drawn, or the body cannot be bounded on the screen.
  changedRect() {
    const key = this.drawnKey;
    const m = this.camera.matrixWorld.elements;
    const pm = this.camera.projectionMatrix.elements;
    const target = this.activeControls().target;
    let same = this.drawnCamera === this.camera && !this.redrawAll && !this.alwaysAll;
    const put = (i, v) => {
      if (key[i] !== v) { same = false; key[i] = v; }
    };
    for (let i = 0; i < 16; i++) { put(i, m[i]); put(16 + i, pm[i]); }
    put(32, this.width); put(33, this.height); put(34, target.x); put(35, target.y);
    this.drawnCamera = this.camera;
    this.redrawAll = false;
    const now = this.bodyRect();
    const before = this.bodyDrawnAt;
    this.bodyDrawnAt = now;
    if (!same || !now || !before) return null;
    const x0 = Math.max(0, Math.floor(Math.min(now[0], before[0])));
    const y0 = Math.max(0, Math.floor(Math.min(now[1], before[1])));
    const x1 = Math.min(this.width, Math.ceil(Math.max(now[2], before[2])));
    const y1 = Math.min(this.height, Math.ceil(Math.max(now[3], before[3])));
    if (x1 <= x0 || y1 <= y0) return [0, 0, 0, 0]; // off the canvas, then and now
    if ((x1 - x0) * (y1 - y0) > 0.7 * this.width * this.height) return null;
    return [x0, this.height - y1, x1 - x0, y1 - y0];
  }

  // Where the body and its contact shadow are on the canvas: [x0, y0, x1, y1], CSS pixels from
  // the top left, padded for the spheres' smallest size and edges; null when some corner of
  // them is behind the camera or beyond its range.
  bodyRect() {
    const v = this.scratch;
    const b = this.body;
    const box = [Infinity, Infinity, -Infinity, -Infinity];
    const add = () => {
      v.project(this.camera);
      if (!(v.z >= -1 && v.z <= 1)) return false;
      const x = ((v.x + 1) / 2) * this.width;
      const y = ((1 - v.y) / 2) * this.height;
      if (x < box[0]) box[0] = x;
      if (y < box[1]) box[1] = y;
      if (x > box[2]) box[2] = x;
      if (y > box[3]) box[3] = y;
      return true;
    };
    const matrix = this.points.matrixWorld;
    for (let c = 0; c < 8; c++) {
      v.set(c & 1 ? b.high[0] : b.low[0], c & 2 ? b.high[1] : b.low[1], c & 4 ? b.high[2] : b.low[2]);
      v.applyMatrix4(matrix);
      if (!add()) return null;
    }
    // The shadow fades out at 1.15 of the footprint's half extents (FLOOR_FRAGMENT).
    const u = this.floorMaterial.uniforms;
    const center = u.shadowCenter.value, axis = u.shadowAxis.value, half = u.shadowHalf.value;
    for (let c = 0; c < 4; c++) {
      const across = (c & 1 ? SHADOW_REACH : -SHADOW_REACH) * half.x;
      const along = (c & 2 ? SHADOW_REACH : -SHADOW_REACH) * half.y;
      v.set(center.x + across * axis.y + along * axis.x, center.y - across * axis.x + along * axis.y, 0);
      if (!add()) return null;
    }
    const pad = 6;
    return [box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad];
  }

  // Each animation frame moves the playback on and asks for a picture, drawn after the frame
  // (drawAfterFrame). Chromium, compositing a WebGL canvas on the CPU, reads the canvas back while
  // it commits a frame, waiting on its main thread for every drawing command sent before: a
  // picture drawn in the frame's own callback is drawn and read back on the frame's critical
  // path. Drawn in a task after the frame's commit, it is drawn while the main thread waits for
  // the next frame, and that frame reads back a finished picture. The picture is shown one frame
  // later than it would be; the read-outs of a pose reached in playback are written at that same
  // frame (applyTime's hold), so that the two agree.
  loop(now) {
    requestAnimationFrame(this.loop);
    if (this.heldReadouts) {
      this.heldReadouts = false;
      this.updateReadouts();
    }
    // (A ResizeObserver follows the stage's size where there is one: no layout read per frame.)
    if (!this.resizeObserved && !this.fixedSize && this.stage.clientWidth &&
        Math.round(this.stage.clientWidth) !== this.width) this.resize();
    if (this.playing) {
      if (this.lastTick != null) {
        const next = this.time + ((now - this.lastTick) / 1000) * this.speed;
        if (next >= this.tEnd) {
          // Stopped at the end, not paused: the end is the pose to stop at, shown next frame.
          this.applyTime(this.tEnd, true);
          this.playing = false;
          this.updatePlayButton();
        } else {
          this.applyTime(next, true);
        }
      }
      this.lastTick = now;
    } else {
      this.lastTick = null;
    }
    if (this.dirty && this.visible) {
      if (this.afterFrame) {
        if (!this.drawQueued) {
          this.drawQueued = true;
          this.afterFrame.port2.postMessage(0);
        }
      } else {
        this.render();
      }
      if (this.lastFrameAt != null) {
        this.frameTimes.push(now - this.lastFrameAt);
        if (this.frameTimes.length > 60) this.frameTimes.shift();
      }
      this.lastFrameAt = now;
    } else {
      this.lastFrameAt = null; // an idle frame breaks the run of drawn frames
    }
  }

  // The picture asked for by the last animation frame, drawn in a task of its own (a message to
  // ourselves: it runs once the frame has been committed) and waited for.
  drawAfterFrame() {
    this.drawQueued = false;
    if (!this.dirty || !this.visible) return;
    this.render();
    // Wait for it here (finish() does not: Chromium sends the commands, SwiftShader draws only
    // when something reads the picture), not in the next frame's read-back.
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, this.pixel);
  }

  // --- the test hook -----------------------------------------------------------------------------
  hook() {
    const self = this;
    const mean = (a) => (a.length ? a.reduce((s, v) => s + v, 0) / a.length : NaN);
    return {
      id: this.run.id,
      setTime(t) { self.setTime(+t, true); return self.time; },
      time: () => self.time,
      range: () => [self.t0, self.tEnd],
      playing: () => self.playing,
      play() { self.play(); },
      pause() { self.pause(); },
      toggle() { self.toggle(); },
      step(direction) { self.step(direction); self.render(); return self.time; },
      setSpeed(s) { self.setSpeed(+s); },
      speed: () => self.speed,
      setView(name) { self.setView(name); self.render(); },
      view: () => self.viewName,
      // [w, x, y, z] of the body as drawn now (the mesh's own quaternion).
      quaternion: () => {
        const q = self.points.quaternion;
        return [q.w, q.x, q.y, q.z];
      },
      position: () => self.points.position.toArray(),
      spin: () => self.spinNow,
      cameraPosition: () => self.camera.position.toArray(),
      cameraTarget: () => self.activeControls().target.toArray(),
      // Where world point p (m) shows on the canvas: CSS pixels from its top left corner.
      project(p) {
        const v = new Vector3(p[0], p[1], p[2]).project(self.camera);
        return [((v.x + 1) / 2) * self.width, ((1 - v.y) / 2) * self.height];
      },
      // Mean interval between consecutive drawn animation frames (ms), over the last 60 of
      // them (while playing: every frame is drawn).
      frameMs: () => mean(self.frameTimes),
      // Mean CPU time of a render call (ms): what the script spends, the GPU not waited for.
      renderMs: () => mean(self.renderTimes),
      // Draws n frames one after another, each read back (so finished), and returns the mean
      // ms per frame: what one frame costs on this machine's WebGL.
      benchmark(n) {
        const gl = self.renderer.getContext();
        const pixel = new Uint8Array(4);
        const count = Math.max(1, n | 0);
        const start = performance.now();
        for (let i = 0; i < count; i++) {
          self.applyTime(self.t0 + ((self.tEnd - self.t0) * i) / count);
          self.render();
          gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        }
        return (performance.now() - start) / count;
      },
      // Fixes the canvas's size in CSS pixels (null: back to the column's width).
      setSize(w, h) {
        if (w && h) {
          self.fixedSize = [Math.round(w), Math.round(h)];
          self.stage.classList.add('rbp-fixed');
          self.stage.style.width = `${self.fixedSize[0]}px`;
          self.stage.style.height = `${self.fixedSize[1]}px`;
        } else {
          self.fixedSize = null;
          self.stage.classList.remove('rbp-fixed');
          self.stage.style.width = '';
          self.stage.style.height = '';
        }
        self.width = null;
        self.resize();
        self.render();
      },
      canvas: () => self.canvas,
      render() { self.render(); },
      // Draws the whole picture again (not only the part that changed).
      renderAll() { self.redrawAll = true; self.render(); },
      // Every frame drawn whole (true) or only its changed part (false, the default).
      setDrawAll(on) { self.alwaysAll = !!on; self.redrawAll = true; self.dirty = true; },
      // The floor drawn without depth, its depth taken by the points' shader, and the contact
      // shadow alone multiplying the floor, where they may be (true, the default), or never
      // (false: the floor's depth and the floor's formula with the shadow, to compare with).
      setShortcuts(on) { self.shortcuts = !!on; self.redrawAll = true; self.dirty = true; },
      // [frames drawn in part, frames drawn] since the player was built.
      drawCounts: () => [self.partialFrames, self.drawnFrames],
      // The forecast first reversal marked on the n(t) plot (s), or null; and where its line
      // is, in the plot canvas's pixels.
      forecast: () => (self.forecast ? self.forecast.time : null),
      forecastX: () => (self.forecast ? Math.round(self.plotLayout().x(self.forecast.time)) * self.plotLayout().dpr : null),
    };
  }
}

// A length as the renderer's read-out gives it (render/overlay.cpp lengthText): "2 cm", "5 mm",
// "1 m", the unit that makes it at least 1.
function lengthText(metres) {
  const m = metres * (1 + 1e-6);
  const fmt = (v) => String(Number(v.toPrecision(6)));
  if (m >= 1) return `${fmt(metres)} m`;
  if (m >= 0.01) return `${fmt(metres * 100)} cm`;
  return `${fmt(metres * 1000)} mm`;
}

function formatStep(t) {
  if (t.length < 2) return 'one sample';
  const dt = (t[t.length - 1] - t[0]) / (t.length - 1);
  return `${+dt.toPrecision(3)} s`;
}

// ---------------------------------------------------------------------------------------------
// Building the page's players.

function showProblem(element, text) {
  element.textContent = '';
  const note = el('div', 'rbp-missing', text);
  element.appendChild(note);
  element.rbPlayerError = text;
}

function initPlayers(root) {
  injectStyle();
  const runs = window.RATTLEBACK_RUNS || {};
  const elements = (root || document).querySelectorAll('.rb-player');
  for (const element of elements) {
    if (element.dataset.rbBuilt) continue;
    element.dataset.rbBuilt = '1';
    const id = element.getAttribute('data-run') || '';
    const run = Object.prototype.hasOwnProperty.call(runs, id) ? runs[id] : undefined;
    if (!run) {
      showProblem(element, `3D player: no data for run “${id}” (its ${id}.player.js did not load).`);
      continue;
    }
    const problem = problemWith(run);
    if (problem) {
      showProblem(element, `3D player: the data of run “${id}” cannot be played (${problem}).`);
      continue;
    }
    try {
      const player = new Player(element, run);
      element.rbPlayer = player.hook();
      players.push(player);
    } catch (e) {
      showProblem(element, `3D player: cannot show run “${id}” here (${(e && e.message) || e}).` +
        ' WebGL may be unavailable in this browser.');
      if (window.console) console.warn('rattleback player:', e);
    }
  }
}

// With one player on the page, its keys work without focusing it first.
function onDocumentKey(e) {
  if (players.length !== 1) return;
  const target = e.target;
  if (target && target !== document.body && target !== document.documentElement) {
    if (target.closest && target.closest('.rbp')) return; // the player's own handler ran
    const tag = target.tagName;
    if (tag === 'INPUT' || tag === 'TEXTAREA' || tag === 'SELECT' || tag === 'BUTTON' ||
        target.isContentEditable) return;
  }
  players[0].onKey(e);
}

function start() {
  initPlayers(document);
  if (!start.keysBound) {
    document.addEventListener('keydown', onDocumentKey);
    start.keysBound = true;
  }
}

window.RattlebackPlayer = { init: initPlayers, players };
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
