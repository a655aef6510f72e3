// The test hook (element.rbPlayer): what the browser tests and bench/player_speed.py read and
// drive.
import { Vector3 } from 'three';
import { runLabel } from './spins.js';

export const hookMethods = {
  hook() {
    const self = this;
    const mean = (a) => (a.length ? a.reduce((s, v) => s + v, 0) / a.length : NaN);
    return {
      id: this.run.id,
      setTime(t) {
        self.setTime(+t, true);
        return self.time;
      },
      time: () => self.time,
      range: () => [self.t0, self.tEnd],
      playing: () => self.playing,
      play() {
        self.play();
      },
      pause() {
        self.pause();
      },
      toggle() {
        self.toggle();
      },
      step(direction) {
        self.step(direction);
        self.render();
        return self.time;
      },
      setSpeed(s) {
        self.setSpeed(+s);
      },
      speed: () => self.speed,
      setView(name) {
        self.setView(name);
        self.render();
      },
      view: () => self.viewName,
      // [w, x, y, z] of the body as drawn now (the mesh's own quaternion).
      quaternion: () => {
        const q = self.points.quaternion;
        return [q.w, q.x, q.y, q.z];
      },
      position: () => self.points.position.toArray(),
      // What the last picture drew of the body: its surface ('triangles', `faces` of them) or
      // its 'points', and three.js's own count of the points and triangles that picture drew
      // (the floor's and the shadow's triangles among them).
      drawn: () => {
        const info = self.renderer.info.render;
        const faces = self.triangles ? self.triangles.geometry.getAttribute('position').count / 3 : 0;
        return {
          body: faces ? 'triangles' : 'points',
          faces,
          points: info.points,
          triangles: info.triangles,
        };
      },
      spin: () => self.spinNow,
      // The spin cue as drawn now: its sense (+1 counter-clockwise, −1 clockwise, 0 none), its
      // colour, and the reversal label's text ('' when hidden).
      cue: () => ({
        sense: self.cueSense,
        color: self.cueSense ? self.cueLine.getAttribute('stroke') : '',
        label: self.reversalLabel.hidden ? '' : self.reversalLabel.textContent,
      }),
      present(on) {
        self.setPresent(on);
        self.render();
      },
      presenting: () => !!self.presenting,
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
      render() {
        self.render();
      },
      // Draws the whole picture again (not only the part that changed).
      renderAll() {
        self.redrawAll = true;
        self.render();
      },
      // Every frame drawn whole (true) or only its changed part (false, the default).
      setDrawAll(on) {
        self.alwaysAll = !!on;
        self.redrawAll = true;
        self.dirty = true;
      },
      // The floor drawn without depth, its depth taken by the points' shader, and the contact
      // shadow alone multiplying the floor, where they may be (true, the default), or never
      // (false: the floor's depth and the floor's formula with the shadow, to compare with).
      setShortcuts(on) {
        self.shortcuts = !!on;
        self.redrawAll = true;
        self.dirty = true;
      },
      // [frames drawn in part, frames drawn] since the player was built.
      drawCounts: () => [self.partialFrames, self.drawnFrames],
      // The runs played, each as its button says it ("−5 rad/s: reverses at 2.37 s"), the one
      // played (its index), its reversals (s), and switching: by index, or as S does.
      runs: () => self.runs.map(runLabel),
      runIndex: () => self.runIndex,
      reversals: () => (self.run.reversals || []).slice(),
      selectRun(k) {
        self.selectRun(+k);
        return self.runIndex;
      },
      spinButtons: () => (self.spinButtons || []).slice(),
      // The forecast first reversal marked on the n(t) plot (s), or null; and where its line
      // is, in the plot canvas's pixels.
      forecast: () => (self.forecast ? self.forecast.time : null),
      forecastX: () =>
        self.forecast ? Math.round(self.plotLayout().x(self.forecast.time)) * self.plotLayout().dpr : null,
    };
  },
};
