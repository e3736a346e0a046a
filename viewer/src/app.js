// The viewer: one replay at a time on the stage (with a catapult's flight
// and what its scene record draws: a grid's cells, items, a heat map),
// its time, and every panel kept in step with it. `renderFrame(t)` draws one
// moment deterministically (the follow camera's standard view), for videos
// and tests.
import { Vector2 } from 'three';
import { createStage } from './stage.js';
import { createBodies } from './bodies.js';
import { createTrail } from './trail_view.js';
import { createFlight } from './flight_view.js';
import { createRecordView } from './record_view.js';
import { showCellsLegend } from './cells_legend.js';
import { countersText, hasCounter, hasWorld, recordOf, sceneAt, scoredSpan } from './scene_record.js';
import { centreAt, throwOf, throwStatus } from './flight.js';
import { createCameraRig } from './camera_rig.js';
import { pointsOfInterest } from './interest.js';
import { createSparklines } from './sparklines.js';
import { createSignalsPanel } from './signals_panel.js';
import { createRunPanel } from './run_panel.js';
import { createPicker } from './picker.js';
import { createBrainPanel } from './brain_panel.js';
import { createPartHover } from './part_hover.js';
import { bestOf, lineageOf, memberOfReplay, membersById } from './lineage.js';
import { showInfo } from './info_panel.js';
import { createPlayer } from './player.js';
import { creatureRadius } from './follow.js';
import { comAt, distanceAt, duration } from './timeline.js';
import { fitness, metres, seconds } from './format.js';

/**
 * A viewer of the checked page data `data` ({replays, run}) in the page's
 * elements `ui` ({canvas, stage, hud, cells, info, picker, run, brain, signals, neurons, player};
 * brain may be missing: no genome and brain panel).
 */
export function createViewer(ui, data) {
  const stage = createStage(ui.canvas);
  const rig = createCameraRig(ui.canvas);
  const s = { index: -1, entry: null, t: 0, T: 0, playing: false, speed: 1, joints: false, trail: true, flight: true, field: true, radius: 1, throw: null, record: null };
  let bodies = null, trail = null, flight = null, world = null, sparks = null, signals = null, brain = null, renderMode = false;
  // the genome and brain panel's tab, kept from one creature to the next
  // once chosen (null: the panel's choice)
  let brainTab = null;
  // the scene is drawn only when something changed: software GL is slow, and
  // a paused page should cost nothing
  let dirty = true;
  rig.controls.addEventListener('change', () => (dirty = true));
  // a part under the pointer in the scene highlights its gene (brain_panel.js)
  const hover = createPartHover(ui.canvas, () => rig.camera, () => (bodies ? bodies.parts : []), (part) => brain?.focusPart(part));

  // panels: choice of creature, the run, the player bar. In a run, the
  // creature shown is a member, chosen as a generation's best (`gen`) or from
  // the lineage of the last one chosen so (`anchor`).
  const run = data.run;
  const byId = run ? membersById(run) : null;
  const pick = { gen: null, anchor: null, member: null };
  const showGeneration = (gen) => {
    const g = run.generations.find((x) => x.gen === gen);
    const m = g && byId.get(g.best_id);
    if (m && m.replay_index !== null) show(m, gen, m.id);
  };
  const showMember = (id) => {
    const m = byId.get(id);
    if (!m || m.replay_index === null) return;
    // still in the listed lineage: the list stays; else it becomes its own
    const inLine = lineageOf(byId, pick.anchor).includes(m);
    const gens = bestOf(run, m.id);
    show(m, gens.includes(pick.gen) ? pick.gen : gens[0] ?? null, inLine ? pick.anchor : m.id);
  };
  function show(member, gen, anchor) {
    Object.assign(pick, { member, gen, anchor });
    load(member.replay_index);
  }
  const picker = createPicker(ui.picker, data, { replay: (i) => load(i), generation: showGeneration, member: showMember });
  const runPanel = run ? createRunPanel(ui.run, run, showGeneration) : null;
  const player = createPlayer(ui.player, {
    togglePlay: () => setPlaying(!s.playing),
    seek: (t) => { setPlaying(false); setTime(t); },
    speed: (x) => (s.speed = x),
    camera: () => { rig.setMode(rig.next); setTime(s.t); },
    joints: (on) => { s.joints = on; bodies.showJoints(on); dirty = true; },
    trail: (on) => { s.trail = on; trail.object.visible = on; dirty = true; },
    flight: (on) => showFlight(on),
    field: (on) => showField(on),
  });

  function showFlight(on) {
    s.flight = on;
    if (flight) flight.object.visible = on;
    player.setFlight(on);
    dirty = true;
  }

  function showField(on) {
    s.field = on;
    world?.showField(on);
    player.setFieldOn(on);
    dirty = true;
  }

  /** Shows replay i from its start. */
  function load(i) {
    const entry = data.replays[i];
    // the record's view first: its carried item rides on a part
    if (world) {
      stage.scene.remove(world.group);
      world.dispose();
      world = null;
    }
    if (bodies) {
      stage.scene.remove(bodies.group, trail.object);
      bodies.dispose();
      trail.dispose();
    }
    if (flight) {
      stage.scene.remove(flight.object);
      flight.dispose();
      flight = null;
    }
    s.index = i;
    s.entry = entry;
    s.T = duration(entry.replay.frames);
    s.radius = creatureRadius(entry.replay);
    stage.fit(s.radius);
    s.throw = throwOf(entry.replay);
    bodies = createBodies(entry.replay);
    bodies.showJoints(s.joints);
    trail = createTrail(entry.replay.frames, s.radius);
    trail.object.visible = s.trail;
    stage.scene.add(bodies.group, trail.object);
    // a catapult: its projectile's flight, the release on the scrub bar
    if (s.throw) {
      flight = createFlight(entry.replay, s.radius);
      flight.object.visible = s.flight;
      stage.scene.add(flight.object);
    }
    player.setThrow(s.throw !== null, s.throw?.release ?? null, s.T);
    // what the scene record draws on the ground and on the parts, its legend
    s.record = recordOf(entry.replay);
    player.setSpan(scoredSpan(s.record, s.T), s.T);
    // the distance the task counts, when it records one (its counter), is the one shown
    s.taskDistance = hasCounter(s.record, 'distance');
    if (s.record.points.length || s.record.props.length || hasWorld(s.record)) {
      world = createRecordView(s.record, entry.replay, bodies);
      world.showField(s.field);
      stage.scene.add(world.group);
    }
    player.setField(world?.fieldName ?? null);
    showCellsLegend(ui.cells, s.record);
    // the camera frames the record's lights and targets with the creature
    rig.reset(entry.replay.frames, s.radius, s.throw ? s.throw.projectile : -1, pointsOfInterest(s.record));
    sparks?.dispose();
    signals?.dispose();
    signals = createSignalsPanel(ui.signals, entry.replay);
    sparks = createSparklines(ui.neurons, entry.replay);
    // the genome and brain: a highlight there lights the parts up here
    brain = ui.brain ? createBrainPanel(ui.brain, entry, brainTab, {
      highlight: (h) => { bodies.highlight(h ? h.parts : null); dirty = true; },
      tab: (key) => (brainTab = key),
    }) : null;
    hover.reset();
    if (run) {
      // a replay chosen by index (a script) names its member here
      if (pick.member?.replay_index !== i) {
        const m = memberOfReplay(run, i);
        Object.assign(pick, { member: m, gen: bestOf(run, m.id)[0] ?? null, anchor: m.id });
      }
      const lineage = lineageOf(byId, pick.anchor);
      showInfo(ui.info, entry, {
        member: pick.member, best: run.best_id, bestOf: bestOf(run, pick.member.id),
        score: run.evaluation_score ?? 'mean', halfStep: run.evaluation_half_step ?? false,
        quarterStep: run.evaluation_quarter_step ?? false,
      });
      picker.setCurrent({ index: i, gen: pick.gen, anchor: pick.anchor, lineage, member: pick.member });
      runPanel.setCurrent(pick.member, lineage);
    } else {
      showInfo(ui.info, entry);
      picker.setCurrent({ index: i });
    }
    setTime(0);
  }

  /** Moves everything to time t (clamped to the replay). */
  function setTime(t) {
    const frames = s.entry.replay.frames;
    s.t = Math.min(Math.max(t, 0), s.T);
    bodies.setTime(s.t);
    trail.setTime(s.t);
    flight?.setTime(s.t);
    world?.setTime(s.t);
    rig.track(s.t);
    stage.focus(rig.targetAt(s.t), s.radius);
    sparks.setTime(s.t);
    signals.setTime(s.t);
    brain?.setTime(s.t);
    const res = s.entry.replay.result ?? {};
    // how far: the task's distance (a counter, below), a catapult's
    // projectile's since its release, or, for a task that counts no distance
    // (or a replay made before tasks recorded it), how far the centre of mass
    // moved from its start: not called distance, which the panel gives as the task's
    const far = s.throw ? throwStatus(frames, s.throw, s.t)
      : s.taskDistance ? '' : `moved ${metres(distanceAt(frames, s.t))}`;
    // and the record's counters at this moment (a river crossing's level, score, deaths)
    const counters = countersText(sceneAt(s.record, s.t).counters);
    ui.hud.textContent = `${s.entry.label}   t ${seconds(s.t)}` + (far ? `   ${far}` : '') +
      (typeof res.fitness === 'number' ? `   fitness ${fitness(res.fitness)}` : '') + (counters ? `   ${counters}` : '');
    player.show({ t: s.t, duration: s.T, playing: s.playing, speed: s.speed, mode: rig.mode });
    dirty = true;
  }

  function setPlaying(on) {
    s.playing = on;
    if (on && s.t >= s.T) s.t = 0;
    player.show({ t: s.t, duration: s.T, playing: s.playing, speed: s.speed, mode: rig.mode });
  }

  // the canvas follows its box's size
  function fit() {
    const w = ui.stage.clientWidth, h = ui.stage.clientHeight;
    const size = stage.renderer.getSize(new Vector2());
    if (w > 0 && h > 0 && (size.x !== w || size.y !== h)) {
      stage.renderer.setPixelRatio(renderMode ? 1 : window.devicePixelRatio || 1);
      stage.renderer.setSize(w, h, false);
      rig.resize(w, h);
      dirty = true;
    }
  }

  function draw() {
    fit();
    stage.renderer.render(stage.scene, rig.camera);
    dirty = false;
  }

  // the animation loop: advance time while playing (looping at the end), and
  // draw when anything changed
  let last = null;
  function tick(now) {
    if (!renderMode) {
      if (s.playing && last !== null) {
        let t = s.t + ((now - last) / 1000) * s.speed;
        if (t > s.T) t = 0;
        setTime(t);
      }
      hover.update();
      fit();
      if (dirty) draw();
    }
    last = now;
    requestAnimationFrame(tick);
  }

  // keys: space plays, arrows step a frame, c camera, j joints, t trail, f a
  // catapult's flight, h a recorded field's heat map
  window.addEventListener('keydown', (ev) => {
    // not while the user types or picks from a list
    const t = ev.target;
    if (t instanceof HTMLSelectElement || (t instanceof HTMLInputElement && t.type !== 'range' && t.type !== 'checkbox')) return;
    const dt = s.entry.replay.frames[1] ? s.entry.replay.frames[1].t - s.entry.replay.frames[0].t : 1 / 30;
    if (ev.key === ' ') setPlaying(!s.playing);
    else if (ev.key === 'ArrowRight') { setPlaying(false); setTime(s.t + dt); }
    else if (ev.key === 'ArrowLeft') { setPlaying(false); setTime(s.t - dt); }
    else if (ev.key === 'c') { rig.setMode(rig.next); setTime(s.t); }
    else if (ev.key === 'j') { s.joints = !s.joints; bodies.showJoints(s.joints); player.setJoints(s.joints); dirty = true; }
    else if (ev.key === 't') { s.trail = !s.trail; trail.object.visible = s.trail; player.setTrail(s.trail); dirty = true; }
    else if (ev.key === 'f' && flight) showFlight(!s.flight);
    else if (ev.key === 'h' && world?.fieldName) showField(!s.field);
    else return;
    ev.preventDefault();
  });

  // a run's page opens on its overall best
  if (run) showMember(run.best_id);
  else load(0);
  requestAnimationFrame(tick);

  /**
   * The present moment: time, replay, root part's and centre of mass's
   * positions; the replay's fitness; in a run, the individual shown, the
   * generation it is shown as the best of (null for none), whose lineage is
   * listed, the fitness the run stored for it and how many evaluations that
   * is the mean of (the replay is the first); for a catapult, the
   * projectile's centre and whether its flight is drawn; what the scene
   * record draws (record_view.js's state(), or null) and its counters
   * ([name, value, unit]) at this moment; the genome and brain panel's
   * (brain_panel.js's state(), or null).
   */
  function state() {
    const p = bodies.parts[0].position;
    const frames = s.entry.replay.frames;
    return {
      t: s.t, replayIndex: s.index, playing: s.playing, camera: rig.mode,
      individual: run ? pick.member.id : null, generation: run ? pick.gen : null, anchor: run ? pick.anchor : null,
      fitness: s.entry.replay.result.fitness ?? null, storedFitness: run ? pick.member.fitness : null,
      evaluations: run ? pick.member.evaluations ?? 1 : null,
      root: [p.x, p.y, p.z], com: comAt(frames, s.t), sparklines: sparks.rows, signals: signals.rows,
      projectile: s.throw ? centreAt(frames, s.throw.projectile, s.t) : null,
      flight: flight ? flight.drawn && s.flight : false,
      scene: world ? world.state() : null,
      counters: sceneAt(s.record, s.t).counters,
      brain: brain ? brain.state() : null,
    };
  }

  // what a script (the renderer, a test) may ask of the page
  return {
    state,
    get duration() { return s.T; },
    get replayIndex() { return s.index; },
    replayCount: data.replays.length,
    select(i) { load(i); draw(); },
    play() { setPlaying(true); },
    pause() { setPlaying(false); },
    /** Video mode: only the scene and a line of text; the loop stops drawing. */
    setRenderMode(on) {
      renderMode = on;
      document.body.classList.toggle('render-mode', on);
      if (on) setPlaying(false);
    },
    /** Draws time t now, in the standard follow view (orbit view if chosen). */
    renderFrame(t) {
      setPlaying(false);
      setTime(t);
      if (rig.mode !== 'orbit') rig.standardFollow(s.t);
      draw();
      return state();
    },
    /** Sets the camera: "follow", "projectile" (a catapult's) or "orbit". */
    setCamera(mode) { rig.setMode(mode); setTime(s.t); draw(); },
  };
}
