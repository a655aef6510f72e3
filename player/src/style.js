// The player's style and elements. The style is injected once, so that the page needs no CSS of
// its own. The canvas's stage has square corners and clips nothing: with rounded corners
// (border-radius, overflow: hidden) Chromium composites the canvas through a masked layer of its
// own, which doubled the cost of each frame on software WebGL (bench/player_speed.py). Nothing
// over the canvas is quite opaque: Chromium's compositor leaves out an opaque canvas under an
// opaque box and, the canvas being drawn upside down, left out the box's mirror image instead,
// a blank box at the picture's bottom (the reversal label's, in present mode at 1920 × 1080).

// Present mode's picture fills the screen above its bar and views (110 px), whatever the screen's
// shape: kept at 16:9, a 4:3 projector's 1024 × 768 left a fifth of the screen blank under it.
// Its read-outs are a 28th of the screen's height, but no larger than 2.3 % of its
// width (which binds only on screens narrower than about 3:2: a 4:3 projector's 1024 × 768 had
// them reach 32 % down the picture); its reversal label stands at the picture's bottom left,
// free at any size (top right, the read-outs of a long sense had reached over it).
// Screens this high or higher show present mode's plot 1.7 times its size, lower ones 1.35 times
// where they are 16:10 or wider (at 1280 × 720 1.7 hid the spin cue's arrowhead; 1.35, with the
// picture the screen's whole width, keeps its tick labels 13 px, not 10; on a 4:3 screen even
// 1.35 covered the arrow's tail); plot.js draws it finer. Below, present mode's read-outs
// take four lines, not six (the spin's sense on the spin's line, the floor's scale left out):
// at 1280 × 720 the six reached down into the picture, over the body's far end.
const PRESENT_PLOT_SCALED = '(min-height:900px)';

export const STYLE = `
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
.rbp-spins{display:flex;flex-direction:column;align-items:stretch;gap:3px;margin:2px 0 6px}
.rbp .rbp-spun{text-align:left;font-size:12.5px}
.rbp.rbp-present .rbp-spun:not(.rbp-on){display:none}
.rbp.rbp-present .rbp-spun{font-size:max(18px,2.2vh)}
.rbp.rbp-present .rbp-spins .rbp-label{display:none}
.rbp-read{font:13px/1.5 ui-monospace,"DejaVu Sans Mono",Menlo,Consolas,monospace;white-space:pre}
.rbp-plotbox{position:relative;width:272px;margin-top:6px}
.rbp-plot{display:block;width:270px;height:130px;border:1px solid #c9ccd4;border-radius:3px;background:#fff;cursor:crosshair}
.rbp-cursor,.rbp-dot{position:absolute;left:0;top:0;background:#d0211a;pointer-events:none;will-change:transform}
.rbp-cursor{width:1.5px;opacity:.6}
.rbp-dot{width:6px;height:6px;border-radius:50%}
.rbp-help{font-size:13px;color:#555;margin-top:6px}
.rbp-reversal:disabled{opacity:.45;cursor:default}
.rbp:fullscreen{background:#fff;margin:0;padding:16px;box-sizing:border-box;overflow:auto;align-items:flex-start;flex-wrap:nowrap}
.rbp:fullscreen .rbp-main{flex:1 1 auto;min-width:0}
.rbp:fullscreen:not(.rbp-present){align-items:stretch}
.rbp:fullscreen:not(.rbp-present) .rbp-main{display:flex;flex-direction:column}
.rbp:fullscreen:not(.rbp-present) .rbp-stage{flex:1 1 0;width:100%;aspect-ratio:auto;min-height:0}
.rbp:fullscreen .rbp-side{flex:0 0 300px}
.rbp:fullscreen .rbp-read{font-size:20px}
.rbp-cue{position:absolute;left:0;top:0;width:100%;height:100%;pointer-events:none;overflow:visible}
.rbp-cue path{stroke-linecap:round;stroke-linejoin:round}
.rbp-reversal-label{position:absolute;top:8px;right:8px;background:rgba(240,228,66,.96);color:#141414;padding:2px 8px;font:600 15px/1.4 system-ui,sans-serif;pointer-events:none}
html.rbp-presenting{overflow:hidden}
.rbp.rbp-present{position:fixed;inset:0;z-index:1000;background:#fff;margin:0;padding:12px;box-sizing:border-box;flex-wrap:nowrap;overflow:hidden}
.rbp.rbp-present .rbp-main{flex:1 1 auto;min-width:0;display:flex;flex-direction:column;align-items:center}
.rbp.rbp-present .rbp-stage{width:100%;height:calc(100vh - 110px);aspect-ratio:auto;flex:none}
.rbp.rbp-present .rbp-bar,.rbp.rbp-present .rbp-views{width:100%}
.rbp.rbp-present .rbp-side{position:absolute;left:28px;top:24px;flex:none;width:auto;background:rgba(255,255,255,.82);padding:6px 14px;border-radius:4px;pointer-events:none;max-width:calc(100vw - 84px)}
.rbp.rbp-present .rbp-title{font-size:max(18px,min(max(26px,3.6vh),2.3vw))}
.rbp.rbp-present .rbp-read{font-size:max(18px,min(max(26px,3.6vh),2.3vw))}
.rbp.rbp-present .rbp-help{display:none}
.rbp.rbp-present .rbp-plotbox{position:fixed;right:24px;bottom:110px;margin:0;transform-origin:100% 100%;opacity:.94}
@media (min-aspect-ratio:16/10){.rbp.rbp-present .rbp-plotbox{transform:scale(1.35)}}
@media ${PRESENT_PLOT_SCALED}{.rbp.rbp-present .rbp-plotbox{transform:scale(1.7)}}
@media not all and ${PRESENT_PLOT_SCALED}{.rbp.rbp-present .rbp-scale{display:none}.rbp.rbp-present .rbp-spin,.rbp.rbp-present .rbp-sense{display:inline}.rbp.rbp-present .rbp-sense::before{content:'  '}}
.rbp.rbp-present .rbp-reversal-label{font-size:max(18px,min(3.4vh,2.4vw));top:auto;right:auto;bottom:16px;left:16px}
.rbp-missing{padding:10px 12px;border:1px dashed #c9a0a0;border-radius:4px;color:#7a2e2e;background:#fbf4f4;font:14px system-ui,sans-serif;margin:8px 0}
`;

export function injectStyle() {
  if (document.getElementById('rb-player-style')) return;
  const style = document.createElement('style');
  style.id = 'rb-player-style';
  style.textContent = STYLE;
  (document.head || document.documentElement).appendChild(style);
}

export function el(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}
