// Present mode, for a classroom's projector: the player full screen, the picture as large as the
// screen allows and the time, the spin and its sense over it in large type, the n(t) plot scaled
// up in its bottom right corner (the help set aside). P (or the Present button) enters and leaves it, Esc leaves it; the keys are
// listed on the page beside the player. Where the browser refuses full screen (no user
// gesture: a headless test), the layout is the same in the window.
export const presentMethods = {
  togglePresent() {
    this.setPresent(!this.presenting);
  },

  setPresent(on) {
    on = !!on;
    if (on === !!this.presenting) return;
    this.presenting = on;
    this.root.classList.toggle('rbp-present', on);
    this.presentButton.classList.toggle('rbp-on', on);
    // The page under it does not scroll (in a window its scroll bar stood over the picture's
    // right edge).
    document.documentElement.classList.toggle('rbp-presenting', on);
    if (on && !document.fullscreenElement && this.root.requestFullscreen) {
      this.root.requestFullscreen().catch(() => {});
    } else if (!on && document.fullscreenElement === this.root && document.exitFullscreen) {
      document.exitFullscreen().catch(() => {});
    }
    this.redrawAll = true;
    this.dirty = true;
    this.moveCursor(); // the plot drawn again where present mode scales it up (plot.js)
  },

  // Full screen left (Esc, the browser's own way out): present mode ends with it.
  bindPresent() {
    document.addEventListener('fullscreenchange', () => {
      if (this.presenting && document.fullscreenElement !== this.root) {
        // (entered full screen, then left it; a refused request never gets here)
        if (this.presentFullScreen) this.setPresent(false);
      }
      this.presentFullScreen = document.fullscreenElement === this.root;
    });
  },
};
