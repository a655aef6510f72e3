// The floor under the body: a checker fading into the background (with distance from the
// target, or along the floor in the level orthographic views), its contact shadow, and the
// floor's depth for the points' shader.
import {
  CustomBlending,
  Mesh,
  OneFactor,
  PlaneGeometry,
  ShaderMaterial,
  SrcColorFactor,
  Vector2,
  Vector3,
  ZeroFactor,
  BufferAttribute,
  BufferGeometry,
} from 'three';
import { FLOOR_FRAGMENT, FLOOR_VERTEX, SHADOW_FRAGMENT, SHADOW_REACH, SHADOW_VERTEX } from './shaders.js';
import { lengthText } from './data.js';

const DEG = Math.PI / 180;
export const BACKGROUND = [0.93, 0.94, 0.96]; // the renderer's kBackground (sRGB)

// The floor's meshes, in the parameters FLOOR_VERTEX places them by. Rings: the centre and
// FADE_RINGS + 1 rings from fadeNear to fadeFar, FADE_SIDES around (the polygon's chords fall
// short of the circle by 0.2 %); rows: one nearest the camera and FOG_ROWS + 1 from fogNear to
// fogFar, each two vertices across. Each mesh has two groups: up to where the fade or fog
// begins (the disc inside the first ring, the rows up to fogNear: drawn NEAR) and beyond.
export const FADE_SIDES = 48;
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
    const a = 2 * k,
      b = 2 * k + 2; // this row's left vertex, the next row's
    index.push(a, a + 1, b + 1, a, b + 1, b);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(position), 3));
  geometry.setIndex(index);
  geometry.addGroup(0, 6, 0);
  geometry.addGroup(6, index.length - 6, 1);
  return geometry;
}

// The checker's square: a fifth of the body's size (its half length, or half the frame's),
// rounded down to 1, 2 or 5 times a power of ten, so that bodies are compared by their squares.
function tileOf(size) {
  const raw = size / 5;
  const decade = Math.pow(10, Math.floor(Math.log10(raw)));
  return raw / decade < 2 ? decade : raw / decade < 5 ? 2 * decade : 5 * decade;
}

export const floorMethods = {
  // FOG's band reaches as far as the floor did when it was a plane over the body's whole
  // wander (every run's: the floor is built once) and far enough beyond it to fade out.
  floorReach(size) {
    let x0 = Infinity,
      x1 = -Infinity,
      y0 = Infinity,
      y1 = -Infinity;
    for (const run of this.runs)
      for (let i = 0; i < run.t.length; i++) {
        x0 = Math.min(x0, run.x[i]);
        x1 = Math.max(x1, run.x[i]);
        y0 = Math.min(y0, run.y[i]);
        y1 = Math.max(y1, run.y[i]);
      }
    const margin = 14 * size + 20 * this.framing.radius;
    return Math.hypot(x1 - x0 + 2 * margin, y1 - y0 + 2 * margin);
  },

  // The floor: a checker of squares by the body's size, fading out.
  buildFloor() {
    const body = this.body;
    const size = body.frame > 0 ? 0.5 * body.frame : Math.max(...body.halfExtent);
    const reach = this.floorReach(size);
    this.floorGeometries = { fade: fadeRings(), fog: fogRows() };
    this.tile = tileOf(size);
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
    this.floorUniforms = floorUniforms;
  },

  // The contact shadow: a quad over the floor around the body (placed in applyTime), drawn
  // after the floor with the floor's formula and the shadow (same uniforms), before the body.
  buildShadow() {
    const body = this.body;
    const floorUniforms = this.floorUniforms;
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
  },

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
        if (level) m.defines.FOG = 1;
        else delete m.defines.FOG;
        m.needsUpdate = true;
      }
      this.floor.geometry = level ? this.floorGeometries.fog : this.floorGeometries.fade;
    }
  },

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
      const c = [0, 1, 2].map((j) => l[0] * inv[3 * j] + l[1] * inv[3 * j + 1] + l[2] * inv[3 * j + 2]);
      // window: x_ndc = 2 x / W - 1, y_ndc = 2 y / H - 1, depth = (z_ndc + 1) / 2
      const W = this.bufferSize.x,
        H = this.bufferSize.y;
      depth.set(c[0] / W, c[1] / H, 0.5 * (1 + c[2] - c[0] - c[1]));
    } else {
      depth.set(0, 0, 2);
    }
    for (const material of [this.floorMaterial, this.floorNearMaterial]) {
      material.depthTest = !analytic;
      material.depthWrite = !analytic;
    }
  },

  // The contact shadow's program: the shadow alone multiplying the floor when the floor under
  // its whole quad is NEAR (inside the fade's first ring, whose chords fall short of fadeNear by
  // cos(π / FADE_SIDES), or before fogNear), else the floor's formula with the shadow.
  chooseShadow() {
    const u = this.floorMaterial.uniforms;
    const center = u.shadowCenter.value,
      axis = u.shadowAxis.value,
      half = u.shadowHalf.value;
    const fog = !!this.floorMaterial.defines.FOG;
    const d = u.depthDirection.value;
    let near = this.shortcuts;
    for (let c = 0; c < 4; c++) {
      const across = (c & 1 ? SHADOW_REACH : -SHADOW_REACH) * half.x;
      const along = (c & 2 ? SHADOW_REACH : -SHADOW_REACH) * half.y;
      const x = center.x + across * axis.y + along * axis.x - u.center.value.x;
      const y = center.y - across * axis.x + along * axis.y - u.center.value.y;
      if (
        fog
          ? x * d.x + y * d.y > u.fogNear.value
          : Math.hypot(x, y) > u.fadeNear.value * Math.cos(Math.PI / FADE_SIDES)
      )
        near = false;
    }
    this.shadow.material = near ? this.shadowOverMaterial : this.shadowMaterial;
  },
};
