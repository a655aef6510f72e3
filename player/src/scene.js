// The player's three.js scene: the renderer on an opaque WebGL 2 context, the body's points as
// sphere impostors (or its surface as triangles, where its scene draws it so), then the floor,
// its shadow and the cameras (floor.js, camera.js).
import {
  Color,
  DoubleSide,
  Mesh,
  Points,
  SRGBColorSpace,
  Scene,
  ShaderMaterial,
  Vector3,
  WebGLRenderer,
} from 'three';
import { POINTS_FRAGMENT, POINTS_VERTEX, TRIANGLES_FRAGMENT, TRIANGLES_VERTEX } from './shaders.js';
import { bodyGeometry, triangleGeometry } from './data.js';
import { BACKGROUND } from './floor.js';

export const sceneMethods = {
  buildScene() {
    const run = this.run;
    this.buildRenderer();
    this.scene = new Scene();
    this.scene.background = new Color().setRGB(...BACKGROUND, SRGBColorSpace);
    const body = bodyGeometry(run);
    this.body = body;
    this.framing = {
      center: new Vector3(run.x[0], run.y[0], run.z[0]),
      radius: 1.25 * (body.frame > 0 ? 0.5 * body.frame : body.reach),
    };
    this.buildPoints();
    this.buildTriangles();
    this.buildFloor();
    this.buildShadow();
    this.buildCameras();
    this.camera = this.perspective;
    this.resize();
  },

  buildRenderer() {
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
  },

  // The body's points as sphere impostors (shaders.js), lit as the renderer lights them.
  buildPoints() {
    const body = this.body;
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
  },

  // The body's surface as flat-shaded triangles where the data has them (triangleGeometry): a
  // child of the points, which stay the object that is moved, framed and shadowed by (their
  // extents are the body's); only their material is hidden. (Their spheres reach a radius
  // beyond the surface: the shadow and the framing are the video's, which takes them too.)
  buildTriangles() {
    const geometry = triangleGeometry(this.run);
    this.triangles = null;
    if (!geometry) return;
    const material = new ShaderMaterial({
      vertexShader: TRIANGLES_VERTEX,
      fragmentShader: TRIANGLES_FRAGMENT,
      uniforms: {
        lightWorld: { value: new Vector3(0.3, -0.6, 1.0).normalize() },
        floorDepth: this.pointsMaterial.uniforms.floorDepth, // the same, set each frame
      },
      // A face wound inwards in a mesh body's file is drawn all the same (the video draws it).
      side: DoubleSide,
    });
    this.triangles = new Mesh(geometry, material);
    this.triangles.frustumCulled = false;
    this.points.add(this.triangles);
    this.pointsMaterial.visible = false;
  },
};
