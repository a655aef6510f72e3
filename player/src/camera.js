// The player's cameras: a perspective one (oblique, follow) and an orthographic one (above,
// front, side) placed as the renderer places its own, by the renderer's table of views
// (util/picture.hpp) that comes with each run's data; orbit controls make any view free.
import { OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

const DEG = Math.PI / 180;
const UP = new Vector3(0, 0, 1);
// The perspective camera's near and far planes, as fractions of its distance: wider than the
// renderer's (0.05, 8), for the free camera's orbits and zooms from there.
const PERSPECTIVE_NEAR = 0.02;
const PERSPECTIVE_FAR = 40;

// The narrower of the two angles of a perspective field of view at this aspect.
function narrowAngle(fov, aspect) {
  return aspect >= 1 ? fov : 2 * Math.atan(Math.tan(fov / 2) * aspect);
}

// From the target towards the eye (unit): the preset's direction, raised by its elevation where
// it has one. Straight down (above) the eye stands a hair towards the screen's down, so that
// looking at the target with z up (the orbit controls' up) turns the picture the preset's way
// up, and orbiting from there is smooth.
function towardEye(preset) {
  const [x, y, z] = preset.toward_eye;
  if (preset.elevation_deg !== 0) {
    const e = preset.elevation_deg * DEG;
    return new Vector3(x * Math.cos(e), y * Math.cos(e), Math.sin(e));
  }
  const toward = new Vector3(x, y, z).normalize();
  if (Math.hypot(toward.x, toward.y) > 1e-6) return toward;
  const tilt = 1e-4;
  const [ux, uy] = preset.up;
  return toward
    .multiplyScalar(Math.cos(tilt))
    .add(new Vector3(-ux * Math.sin(tilt), -uy * Math.sin(tilt), 0));
}

export const cameraMethods = {
  // Cameras, z up: a perspective one (oblique, follow) and an orthographic one (above, front,
  // side), each with its own orbit controls; any drag or zoom makes the view "free".
  buildCameras() {
    this.perspective = new PerspectiveCamera(30, 16 / 9, 0.01, 100);
    this.orthographic = new OrthographicCamera(-1, 1, 1, -1, 0.01, 100);
    this.controls = {};
    for (const camera of [this.perspective, this.orthographic]) {
      camera.up.copy(UP);
      const controls = new OrbitControls(camera, this.canvas);
      controls.enabled = false;
      controls.enableDamping = false;
      controls.zoomToCursor = false;
      // Never under the floor, nor inside the body or so far off that it vanishes.
      controls.maxPolarAngle = 88 * DEG;
      if (camera.isPerspectiveCamera) {
        controls.minDistance = 1.2 * this.body.reach;
        controls.maxDistance = 40 * this.framing.radius;
      }
      let interacting = false;
      controls.addEventListener('start', () => {
        interacting = true;
      });
      controls.addEventListener('end', () => {
        interacting = false;
      });
      controls.addEventListener('change', () => {
        if (interacting && this.viewName !== 'free') this.makeFree();
        this.dirty = true;
      });
      this.controls[camera.type] = controls;
    }
  },

  activeControls() {
    return this.controls[this.camera.type];
  },

  useCamera(camera) {
    this.camera = camera;
    for (const c of Object.values(this.controls)) c.enabled = false;
    this.activeControls().enabled = true;
  },

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
  },

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
      const bw = Math.floor(w * dpr),
        bh = Math.floor(h * dpr); // the buffer, as three sizes it
      exact = Math.abs(box.width * dpr - bw) < 1 && Math.abs(box.height * dpr - bh) < 1;
    }
    const rendering = exact ? 'pixelated' : '';
    if (this.canvas.style.imageRendering !== rendering) this.canvas.style.imageRendering = rendering;
  },

  setView(name) {
    if (!this.views[name] && name !== 'free') throw new Error(`unknown view ${name}`);
    if (name === 'free') {
      this.makeFree();
    } else {
      this.viewName = name;
      this.lastView = name;
      this.placeCamera();
    }
    this.updateViewButtons();
    this.dirty = true;
  },

  makeFree() {
    this.viewName = 'free';
    this.updateViewButtons();
  },

  updateViewButtons() {
    for (const [v, b] of Object.entries(this.viewButtons)) b.classList.toggle('rbp-on', v === this.viewName);
  },

  // A fixed view as the renderer places it (render/camera.cpp, by the table that came with the
  // run: util/picture.hpp).
  placeCamera() {
    const preset = this.views[this.viewName];
    if (!preset) return; // free: where the pointer left it
    if (this.viewName === 'follow') this.placeChase();
    else if (preset.projection === 'perspective') this.placePerspective(preset);
    else this.placeOrthographic(preset);
  },

  // The sphere framed in the narrower of the field's two angles, with the preset's margin.
  placePerspective(preset) {
    const aspect = this.width / this.height;
    const target = this.framing.center;
    const fov = preset.fov_deg * DEG;
    const distance = (preset.margin * this.framing.radius) / Math.sin(narrowAngle(fov, aspect) / 2);
    const p = this.perspective;
    this.fitPerspective(preset, aspect, distance);
    p.position.copy(target).addScaledVector(new Vector3(...preset.toward_eye).normalize(), distance);
    p.lookAt(target);
    this.useCamera(p);
    this.activeControls().target.copy(target);
  },

  // The perspective camera's projection at this distance from what it looks at.
  fitPerspective(preset, aspect, distance) {
    const p = this.perspective;
    p.fov = preset.fov_deg;
    p.aspect = aspect;
    p.zoom = 1;
    p.near = PERSPECTIVE_NEAR * distance;
    p.far = PERSPECTIVE_FAR * distance;
    p.updateProjectionMatrix();
  },

  // The visible half extents (across the screen, up the screen) hold the framed sphere across,
  // and up the screen the sphere (above) or the body's height plus r·sin e (front and side,
  // which look down by e), with the preset's margin, at the canvas's aspect.
  placeOrthographic(preset) {
    const aspect = this.width / this.height;
    const target = this.framing.center;
    const r = this.framing.radius;
    const e = preset.elevation_deg * DEG;
    const upwards = preset.elevation_deg === 0 ? r : this.body.halfExtent[2] + r * Math.sin(e);
    const halfW = preset.margin * Math.max(r, upwards * aspect);
    const o = this.orthographic;
    o.left = -halfW;
    o.right = halfW;
    o.top = halfW / aspect;
    o.bottom = -halfW / aspect;
    o.near = preset.near_r * r;
    o.far = preset.far_r * r;
    o.zoom = 1;
    o.updateProjectionMatrix();
    o.position.copy(target).addScaledVector(towardEye(preset), preset.eye_r * r);
    o.lookAt(target);
    this.useCamera(o);
    this.activeControls().target.copy(target);
  },

  // Follow: beside the body across its long axis, the preset's elevation above, moving and
  // turning with it.
  placeChase() {
    const preset = this.views.follow;
    const aspect = this.width / this.height;
    const narrow = narrowAngle(preset.fov_deg * DEG, aspect);
    const elevation = preset.elevation_deg * DEG;
    const q = this.points.quaternion;
    const axis = new Vector3(0, 1, 0).applyQuaternion(q); // the long axis, world
    let hx = axis.x,
      hy = axis.y;
    const norm = Math.hypot(hx, hy);
    if (norm > 1e-6) {
      hx /= norm;
      hy /= norm;
    } else {
      hx = 0;
      hy = 1;
    }
    const middle = this.points.position.clone();
    middle.z += this.body.middleHeight;
    const framed = this.body.frame > 0 ? 0.5 * this.body.frame : this.body.reach;
    const distance = (preset.margin * framed) / Math.sin(narrow / 2);
    const direction = new Vector3(-hy * Math.cos(elevation), hx * Math.cos(elevation), Math.sin(elevation));
    const p = this.perspective;
    this.fitPerspective(preset, aspect, distance);
    p.position.copy(middle).addScaledVector(direction, distance);
    p.lookAt(middle);
    if (this.camera !== p) this.useCamera(p);
    this.activeControls().target.copy(middle);
  },
};
