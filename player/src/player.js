// The report page's interactive player of a simulated rattleback run (three.js).
//
// The page holds, for each run, <div class="rb-player" data-run="ID"></div> and a classic
// script ID.player.js that stores the run in window.RATTLEBACK_RUNS[ID] (see README.md beside
// this folder's package.json for the fields); this script, loaded last, builds a player in each
// such element. Its modules (one job each: scene, floor, camera, timeline, plot, controls, draw,
// hook, cue, present, spins) are bundled with three.js into one classic script (build.sh): no module imports, no
// fetch, nothing from the network, so the page works from file://.
//
// Frames: world z is up and the floor is the plane z = 0, as in the data; the body's points are
// in its own frame about the centre of mass, posed each frame by the run's position (linear
// between samples) and attitude (slerp between samples). A "frame" of the step buttons and
// arrow keys is one sample interval of the data. Playback stops at the end of the run (play
// again starts it over).
import { Matrix3, Matrix4, Quaternion, Vector2, Vector3 } from 'three';
import { el, injectStyle } from './style.js';
import { forecastOf, problemWith, runsOf, viewsOf } from './data.js';
import { sceneMethods } from './scene.js';
import { floorMethods } from './floor.js';
import { cameraMethods } from './camera.js';
import { timelineMethods } from './timeline.js';
import { plotMethods } from './plot.js';
import { controlsMethods } from './controls.js';
import { drawMethods } from './draw.js';
import { hookMethods } from './hook.js';
import { cueMethods } from './cue.js';
import { presentMethods } from './present.js';
import { spinsMethods } from './spins.js';

const players = [];

// One player: its state is here, its jobs in the modules mixed in below.
class Player {
  constructor(container, run) {
    this.container = container;
    // The runs it plays: the data's own, and the body spun the other way where the data
    // carries it (spins.js); the one played is this.run.
    this.runs = runsOf(run);
    this.ownForecast = forecastOf(container, run.t[0], run.t[run.t.length - 1]);
    this.useRun(0);
    this.time = this.t0;
    this.playing = false;
    this.speed = 1;
    this.views = viewsOf(run);
    this.viewNames = run.views.map((v) => v.name);
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
    this.qa = new Quaternion();
    this.qb = new Quaternion();
    this.buildDom();
    this.buildScene();
    this.buildCue();
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
}

Object.assign(
  Player.prototype,
  sceneMethods,
  floorMethods,
  cameraMethods,
  timelineMethods,
  plotMethods,
  controlsMethods,
  drawMethods,
  hookMethods,
  cueMethods,
  presentMethods,
  spinsMethods,
);

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
      showProblem(
        element,
        `3D player: cannot show run “${id}” here (${(e && e.message) || e}).` +
          ' WebGL may be unavailable in this browser.',
      );
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
    if (
      tag === 'INPUT' ||
      tag === 'TEXTAREA' ||
      tag === 'SELECT' ||
      tag === 'BUTTON' ||
      target.isContentEditable
    )
      return;
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
