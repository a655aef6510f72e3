// The player's shaders (GLSL ES 3.0 through three's ShaderMaterial; colours are written as sRGB
// as they are).

// The body's points as sphere impostors: one GL point per sphere, sized to its projected radius
// (perspective and orthographic alike), shaded from the sprite's coordinates; a ported subset
// of the renderer's points.vert / points.frag. What is the same over a sprite reaches its
// pixels in one vec4 varying (SwiftShader sets up and interpolates each varying for every point
// and pixel: four cost the points 5–8 % more).
export const POINTS_VERTEX = /* glsl */ `
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

export const POINTS_FRAGMENT = /* glsl */ `
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
export const FLOOR_VERTEX = /* glsl */ `
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

export const FLOOR_FRAGMENT = /* glsl */ `
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
export const SHADOW_VERTEX = /* glsl */ `
varying vec2 vLocal;
void main() {
  vLocal = position.xy;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;

export const SHADOW_FRAGMENT = /* glsl */ `
uniform float shadowStrength;
varying vec2 vLocal;
void main() {
  float s = 1.0 - shadowStrength * (1.0 - smoothstep(0.55, 1.15, length(vLocal)));
  gl_FragColor = vec4(s, s, s, 1.0);
}`;

// The shadow's reach: it fades out at 1.15 of the footprint's half extents (FLOOR_FRAGMENT);
// its quad, and the part of the canvas redrawn for it, reach a little further.
export const SHADOW_REACH = 1.2;

// The body's closed surface as flat-shaded triangles, as the renderer draws it for a scene's
// video.surface: triangles (render's triangles.vert / triangles.frag): each corner carries its
// face's normal and colour, lit by the renderer's light, fixed in the world (its light_world),
// with the same ambient and fill, and no highlight. The normal is turned into the world here
// (the body's matrix is a rotation and a move), where the light is fixed.
export const TRIANGLES_VERTEX = /* glsl */ `
attribute float kind;  // 0 faces up (red), 1 faces down (blue)
uniform vec3 lightWorld;
varying vec3 vColor;
varying float vTowards;
void main() {
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  vTowards = dot(normalize(mat3(modelMatrix) * normal), lightWorld);
  vColor = kind < 0.5 ? vec3(0.86, 0.13, 0.10) : vec3(0.13, 0.32, 0.88);
}`;

export const TRIANGLES_FRAGMENT = /* glsl */ `
uniform vec3 floorDepth; // as POINTS_FRAGMENT's: the floor drawn without depth hides nothing
varying vec3 vColor;
varying float vTowards;
void main() {
  float floorZ = dot(floorDepth, vec3(gl_FragCoord.xy, 1.0));
  if (gl_FragCoord.z > floorZ && floorZ >= 0.0) discard;
  float diffuse = max(vTowards, 0.0);
  float fill = max(-vTowards, 0.0);
  gl_FragColor = vec4(vColor * (0.30 + 0.75 * diffuse + 0.35 * fill), 1.0);
}`;
