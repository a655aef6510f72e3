// Drawing the picture: only the part of the canvas that changed where the camera stayed, each
// picture drawn after its animation frame, and the playback moved on each frame.
import { SHADOW_REACH } from './shaders.js';

export const drawMethods = {
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
    this.updateCue();
    this.partialFrames += rect ? 1 : 0;
    this.drawnFrames += 1;
    this.renderTimes.push(performance.now() - started);
    if (this.renderTimes.length > 60) this.renderTimes.shift();
    this.dirty = false;
  },

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
      if (key[i] !== v) {
        same = false;
        key[i] = v;
      }
    };
    for (let i = 0; i < 16; i++) {
      put(i, m[i]);
      put(16 + i, pm[i]);
    }
    put(32, this.width);
    put(33, this.height);
    put(34, target.x);
    put(35, target.y);
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
  },

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
    const center = u.shadowCenter.value,
      axis = u.shadowAxis.value,
      half = u.shadowHalf.value;
    for (let c = 0; c < 4; c++) {
      const across = (c & 1 ? SHADOW_REACH : -SHADOW_REACH) * half.x;
      const along = (c & 2 ? SHADOW_REACH : -SHADOW_REACH) * half.y;
      v.set(center.x + across * axis.y + along * axis.x, center.y - across * axis.x + along * axis.y, 0);
      if (!add()) return null;
    }
    const pad = 6;
    return [box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad];
  },

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
    if (
      !this.resizeObserved &&
      !this.fixedSize &&
      this.stage.clientWidth &&
      Math.round(this.stage.clientWidth) !== this.width
    )
      this.resize();
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
  },

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
  },
};
