// The player's time: the pose at any time between the samples (the position linear, the
// attitude slerped, the spin a cubic), playing, pausing, stepping a sample, the next reversal.
export const timelineMethods = {
  // The sample interval [i, i + 1] holding t, and how far along it t is.
  locate(t) {
    const ts = this.run.t;
    const n = this.n;
    if (n === 1 || t <= ts[0]) return [0, 0];
    if (t >= ts[n - 1]) return [n - 2, 1];
    let lo = 0,
      hi = n - 1; // ts[lo] <= t < ts[hi]
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= t) lo = mid;
      else hi = mid;
    }
    return [lo, (t - ts[lo]) / (ts[hi] - ts[lo])];
  },

  // s between samples i and j = i + 1, a of the way along: the cubic through s[i] and s[j]
  // with the slopes of the central differences there (one-sided at the ends).
  cubic(s, i, j, a) {
    if (j === i) return s[i];
    const ts = this.run.t;
    const last = this.n - 1;
    const slope = (k) => {
      const lo = Math.max(0, k - 1),
        hi = Math.min(last, k + 1);
      return (s[hi] - s[lo]) / (ts[hi] - ts[lo]);
    };
    const h = ts[j] - ts[i];
    const a2 = a * a,
      a3 = a2 * a;
    return (
      (2 * a3 - 3 * a2 + 1) * s[i] +
      (a3 - 2 * a2 + a) * h * slope(i) +
      (3 * a2 - 2 * a3) * s[j] +
      (a3 - a2) * h * slope(j)
    );
  },

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
    // apart read +0.04 rad/s at Kane & Levinson's reversal (the Reversal button's pose).
    this.spinNow = this.cubic(run.spin, i, j, a);
    // The floor's contact shadow follows the body.
    const u = this.floorMaterial.uniforms;
    u.shadowCenter.value.set(this.points.position.x, this.points.position.y);
    const axis = this.axis.set(0, 1, 0).applyQuaternion(this.points.quaternion);
    const norm = Math.hypot(axis.x, axis.y);
    if (norm > 1e-6) u.shadowAxis.value.set(axis.x / norm, axis.y / norm);
    else u.shadowAxis.value.set(0, 1);
    // Its quad: local x across the body's long axis, y along it.
    const along = u.shadowAxis.value;
    this.shadow.position.set(this.points.position.x, this.points.position.y, 0);
    this.shadow.rotation.set(0, 0, Math.atan2(-along.x, along.y));
    if (this.viewName === 'follow') this.placeChase();
    this.heldReadouts = !!hold;
    if (!hold) this.updateReadouts();
    this.dirty = true;
  },

  setTime(t, renderNow) {
    if (!Number.isFinite(t)) return;
    this.applyTime(t);
    if (renderNow) this.render();
  },

  // One sample interval back or forward, from the sample at or next to the current time.
  step(direction) {
    this.pause();
    const ts = this.run.t;
    // A time within a twentieth of a sample interval of a sample counts as that sample: paused
    // at 1.4999 s, → went to 1.50, the same picture and read-out, and the key seemed dead.
    const interval = this.n > 1 ? (ts[this.n - 1] - ts[0]) / (this.n - 1) : 0;
    const eps = Math.max(1e-9 * Math.max(1, Math.abs(this.tEnd)), 0.05 * interval);
    let [i, a] = this.locate(this.time);
    if (this.time >= this.tEnd) {
      i = this.n - 1;
      a = 0;
    }
    let k;
    if (direction > 0) {
      k = i + 1;
      while (k < this.n - 1 && ts[k] <= this.time + eps) k++;
    } else {
      k = a > 0 && ts[i] < this.time - eps ? i : i - 1;
    }
    k = Math.max(0, Math.min(this.n - 1, k));
    this.setTime(ts[k], false);
  },

  play() {
    if (this.playing) return;
    if (this.time >= this.tEnd) this.applyTime(this.t0); // at the end: from the start again
    this.playing = true;
    this.playStartedAt = null;
    this.updatePlayButton();
  },

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
  },

  toggle() {
    if (this.playing) this.pause();
    else this.play();
  },

  // Paused at the next reversal after the time shown (a hair after one counts as at it), or the
  // first after the last.
  gotoReversal() {
    const reversals = this.run.reversals || [];
    if (!reversals.length) return;
    this.pause();
    const eps = 1e-9 * Math.max(1, Math.abs(this.tEnd));
    const next = reversals.find((r) => r > this.time + eps);
    this.setTime(Math.min(this.tEnd, Math.max(this.t0, next === undefined ? reversals[0] : next)), false);
  },

  toEnd(end) {
    this.pause();
    this.setTime(end ? this.tEnd : this.t0, false);
  },
};
