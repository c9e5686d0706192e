// The job being worked on: the set-up, the runs (stored or being typed), the
// stored session's id and the last solution. Views read it and call `changed()`.

const listeners = [];

export const state = {
  id: null, // stored session id, null until the zero run is stored
  setup: emptySetup(),
  runs: [], // { id, weights, readings, stored }
  draft: null, // the run being typed or corrected (see runs.js), or null
  solution: null,
  solutionDate: null,
  options: defaultOptions(),
  etag: null, // the stored session's ETag as this page last read it (two tabs)
  report: emptyReport(), // the report's own fields: the reason and who balanced
};

export function emptyReport() {
  return { reason: "", by: "" };
}

/** Solve options as the form edits them (see solveOptions in options.js). */
export function defaultOptions() {
  // `limit`: the acceptable vibration when every sensor reads in one unit;
  // `limits`: one per unit when they mix (µm pk-pk beside mils pk-pk).
  return { objective: "least_squares", drop: false, maxMass: {}, limits: {}, leaveSensors: [], leaveSpeeds: [], ampNoise: null, phaseNoise: null, fromRun: null, discrete: true };
}

export function emptySetup() {
  return {
    name: "",
    machine: "",
    conventions: { phase: "lag", angle_direction: "against_rotation" },
    planes: [{ id: "", radius_mm: null, positions: null }],
    sensors: [{ id: "", unit: "um_pp", label: "" }],
    speeds: [],
    rotor: null,
    // A trim job: the coefficients it is solved with instead of trial runs,
    // `{coefficients_from}` or `{influence_coefficients}` (the session's `trim`).
    trim: null,
  };
}

export function onChange(fn) {
  listeners.push(fn);
}

export function changed() {
  for (const fn of listeners) fn(state);
}

/** Start over with an empty job. */
export function resetJob() {
  state.id = null;
  state.setup = emptySetup();
  state.runs = [];
  state.draft = null;
  state.solution = null;
  state.solutionDate = null;
  state.options = defaultOptions();
  state.etag = null;
  state.report = emptyReport();
}

/** The grid's rows in reading order: every speed, and every sensor at it. */
export function rows(setup = state.setup) {
  const out = [];
  for (const speed of setup.speeds) {
    for (const sensor of setup.sensors) out.push({ speed, sensor: sensor.id });
  }
  return out;
}

/** The reading of `run` for a row, paired by sensor and speed within 1 % as the contract says. */
export function readingFor(run, row) {
  return run.readings.find(
    (r) => r.sensor === row.sensor && Math.abs(r.speed_rpm - row.speed) <= 0.01 * Math.max(r.speed_rpm, row.speed),
  );
}

/** The set-up part of the wire session (no runs). */
export function setupJson(setup = state.setup) {
  const out = { name: setup.name };
  if (setup.machine) out.machine = setup.machine;
  out.conventions = { ...setup.conventions };
  out.planes = setup.planes.map((p) => {
    const plane = { id: p.id };
    if (p.radius_mm !== null && p.radius_mm !== undefined) plane.radius_mm = p.radius_mm;
    if (p.positions !== null && p.positions !== undefined) plane.positions = p.positions;
    if (Array.isArray(p.places_deg) && p.places_deg.length) plane.places_deg = p.places_deg;
    if (p.kit && Array.isArray(p.kit.masses_g) && p.kit.masses_g.length) plane.kit = { ...p.kit };
    return plane;
  });
  out.sensors = setup.sensors.map((x) => {
    const sensor = { id: x.id, unit: x.unit };
    if (x.label) sensor.label = x.label;
    return sensor;
  });
  if (setup.rotor && setup.rotor.mass_kg && setup.rotor.service_speed_rpm) {
    out.rotor = { mass_kg: setup.rotor.mass_kg, service_speed_rpm: setup.rotor.service_speed_rpm };
    if (setup.rotor.balance_grade) out.rotor.balance_grade = setup.rotor.balance_grade;
  }
  if (setup.runout && setup.runout.length) out.runout = setup.runout;
  // Stored with the session, so that the job reopened in another browser,
  // before it is solved, is still a trim job (it asked for trial runs).
  if (setup.trim) out.trim = JSON.parse(JSON.stringify(setup.trim));
  return out;
}

export function runJson(run) {
  const out = {
    id: run.id,
    weights: run.weights.map((w) => ({ plane: w.plane, mass_g: w.mass_g, angle_deg: w.angle_deg })),
    readings: run.readings.map((r) => {
      const reading = { speed_rpm: r.speed_rpm, sensor: r.sensor, amplitude: r.amplitude, phase_deg: r.phase_deg };
      if (r.samples) reading.samples = r.samples;
      return reading;
    }),
  };
  // "trial" or "check": what the run is, whatever the technician named it.
  if (run.purpose && run.weights.length) out.purpose = run.purpose;
  return out;
}

/** The whole session in the contract's shape, stored runs only unless `all`. */
export function sessionJson(all = false) {
  const session = setupJson();
  session.runs = state.runs.filter((r) => all || r.stored).map(runJson);
  return session;
}

/** The form's set-up of a wire session (speeds from its reference run). */
export function setupOf(session) {
  const speeds = [];
  const reference = session.runs.find((r) => r.weights.length === 0) || session.runs[0];
  for (const r of reference ? reference.readings : []) {
    if (!speeds.some((x) => Math.abs(x - r.speed_rpm) <= 0.01 * Math.max(x, r.speed_rpm))) speeds.push(r.speed_rpm);
  }
  return {
    name: session.name,
    machine: session.machine || "",
    conventions: {
      phase: (session.conventions && session.conventions.phase) || "lag",
      angle_direction: (session.conventions && session.conventions.angle_direction) || "against_rotation",
    },
    planes: session.planes.map((p) => ({ id: p.id, radius_mm: p.radius_mm ?? null, positions: p.positions ?? null, places_deg: p.places_deg, kit: p.kit })),
    sensors: session.sensors.map((x) => ({ id: x.id, unit: x.unit, label: x.label || "" })),
    speeds,
    rotor: session.rotor || null,
    runout: session.runout,
    trim: session.trim || null,
  };
}

/** Load a wire session (from the server or a file) into the job. */
export function loadSession(session, id) {
  state.id = id;
  state.setup = setupOf(session);
  state.runs = session.runs.map((r) => ({ ...runJson(r), stored: id !== null }));
  state.draft = null;
  state.solution = null;
}

/** The trim job's coefficients in words, or "" for a job with trial runs. */
export function trimWords(trim = state.setup.trim) {
  if (!trim) return "";
  if (trim.coefficients_from) return `the stored coefficients of machine ${trim.coefficients_from.machine}`;
  return `the ${trim.influence_coefficients.length} supplied influence coefficient${trim.influence_coefficients.length === 1 ? "" : "s"}`;
}

/** Planes that a stored run has already put a weight in: plane → the first such run's name. */
export function triedPlanes() {
  const out = new Map();
  for (const r of state.runs) if (r.stored) for (const w of r.weights) if (!out.has(w.plane)) out.set(w.plane, r.id);
  return out;
}

/** The reference (zero) run, if there is one. */
export function referenceRun() {
  return state.runs.find((r) => r.weights.length === 0 && r.stored) || null;
}

/** Whether the set-up can still change: only until the session is stored. */
export function setupLocked() {
  return state.id !== null;
}
