// The stage every replay plays on: renderer, sky, ground with a metre grid,
// and a sun whose shadow box follows the creature. The world is z-up, as in
// the simulation.
import {
  AmbientLight, CanvasTexture, Color, DirectionalLight, Fog, HemisphereLight, Mesh,
  MeshStandardMaterial, PCFShadowMap, PlaneGeometry, RepeatWrapping, Scene, SRGBColorSpace,
  WebGLRenderer,
} from 'three';
import { viewScale } from './follow.js';

const SKY = 0xcad9e6;
const GROUND_SIZE = 400; // m
const TILE = 5; // m: one tile of the grid texture, 5 x 5 cells of 1 m
/**
 * The ground's render order: before anything else, so what lies on it (a
 * recorded grid's cells, record_view.js) can be drawn right after it.
 */
export const GROUND_ORDER = -2;

// The grid is painted into the ground's texture rather than drawn as lines
// above it: lines a millimetre above the plane flicker with software GL's
// depth precision, and a mipmapped texture does not shimmer at the horizon.
function gridTexture(renderer) {
  const px = 512, cell = px / TILE;
  const c = document.createElement('canvas');
  c.width = c.height = px;
  const g = c.getContext('2d');
  g.fillStyle = '#d3d5d8';
  g.fillRect(0, 0, px, px);
  g.fillStyle = '#adb2b7';
  for (let k = 1; k < TILE; ++k) {
    g.fillRect(k * cell - 1, 0, 2, px);
    g.fillRect(0, k * cell - 1, px, 2);
  }
  // every 5 m a stronger line, on the tile's edges
  g.fillStyle = '#858c94';
  g.fillRect(0, 0, 3, px); g.fillRect(px - 3, 0, 3, px);
  g.fillRect(0, 0, px, 3); g.fillRect(0, px - 3, px, 3);
  const tex = new CanvasTexture(c);
  tex.colorSpace = SRGBColorSpace;
  tex.wrapS = tex.wrapT = RepeatWrapping;
  tex.repeat.set(GROUND_SIZE / TILE, GROUND_SIZE / TILE);
  tex.anisotropy = renderer.capabilities.getMaxAnisotropy();
  return tex;
}

/** Direction the sunlight comes from (towards the sun), z up. */
const SUN_DIR = [0.45, -0.35, 1.0];

/** Builds renderer and scene on `canvas`. */
export function createStage(canvas) {
  // the renderer keeps its drawing buffer, so a page or a test can read pixels
  const renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.outputColorSpace = SRGBColorSpace;
  renderer.shadowMap.enabled = true;
  renderer.shadowMap.type = PCFShadowMap;

  const scene = new Scene();
  scene.background = new Color(SKY);
  scene.fog = new Fog(SKY, 30, 120);

  // ground: a large plane with a grid of 1 m cells and a darker line every 5 m
  // (the origin on a 5 m line)
  const ground = new Mesh(
    new PlaneGeometry(GROUND_SIZE, GROUND_SIZE),
    new MeshStandardMaterial({ map: gridTexture(renderer), roughness: 0.95, metalness: 0 }),
  );
  ground.receiveShadow = true;
  ground.renderOrder = GROUND_ORDER;
  scene.add(ground);

  // light: sky and ground bounce, a little ambient, and a shadow-casting sun
  scene.add(new HemisphereLight(0xf4f7ff, 0x8a8478, 1.6));
  scene.add(new AmbientLight(0xffffff, 0.25));
  const sun = new DirectionalLight(0xffffff, 2.2);
  sun.castShadow = true;
  sun.shadow.mapSize.set(2048, 2048);
  sun.shadow.bias = -0.0004;
  sun.shadow.normalBias = 0.01;
  scene.add(sun, sun.target);

  return {
    renderer, scene, sun,
    /**
     * Sizes the fog and the ground for a creature of `radius` (m): as built
     * for one of a metre or two, scaled by viewScale(radius) beyond; the
     * grid's cells stay 1 m.
     */
    fit(radius) {
      const k = viewScale(radius);
      scene.fog.near = 30 * k;
      scene.fog.far = 120 * k;
      ground.scale.set(k, k, 1);
      ground.material.map.repeat.set((GROUND_SIZE * k) / TILE, (GROUND_SIZE * k) / TILE);
    },
    /** Centres the sun's shadow box of half-width `radius` (m) on point p. */
    focus(p, radius) {
      const d = Math.max(radius, 1) * 6;
      const n = Math.hypot(...SUN_DIR);
      sun.position.set(p[0] + (SUN_DIR[0] / n) * d, p[1] + (SUN_DIR[1] / n) * d, (SUN_DIR[2] / n) * d);
      sun.target.position.set(p[0], p[1], 0);
      const cam = sun.shadow.camera;
      const half = Math.max(radius * 2.5, 1.5);
      cam.left = -half; cam.right = half; cam.top = half; cam.bottom = -half;
      cam.near = 0.1; cam.far = d * 2;
      cam.updateProjectionMatrix();
    },
  };
}
