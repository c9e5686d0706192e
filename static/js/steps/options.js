// The service's solve options in the form: what to minimise, mass limits per
// plane, sensors and speeds left out, the readings' noise, which run the rotor
// is corrected from (a trim), stored coefficients, and the kit fit.

import { h } from "../page/dom.js";
import { numberInput } from "../page/fields.js";
import { fmt, commonUnit, unitLabel } from "../page/num.js";
import { state } from "../job/state.js";

/** Stored runs whose state a trim can start from: every run with weights. */
export function runsWithWeights() {
  return state.runs.filter((r) => r.stored && r.weights.length > 0);
}

/**
 * What each stored run with weights is, "trial" or "check": its `purpose`,
 * which the form stores with every run. A run stored without one
 * (by another client, or before the form stored it) is guessed from the
 * order and the name: a check run is recorded once every plane has
 * had its trial (every run, in a trim job) or is named "check…", except that
 * one named "trial…" stays a trial (a second trial in a tried plane).
 */
export function runKinds() {
  const planes = state.setup.planes.map((p) => p.id);
  const tried = new Set();
  const out = new Map();
  for (const r of runsWithWeights()) {
    const after = !!state.setup.trim || planes.every((p) => tried.has(p));
    r.weights.forEach((w) => tried.add(w.plane));
    const guess = /^check/i.test(r.id) || (after && !/^trial/i.test(r.id)) ? "check" : "trial";
    out.set(r.id, r.purpose === "trial" || r.purpose === "check" ? r.purpose : guess);
  }
  return out;
}

/** Check runs, whatever they are named (see runKinds). */
export function checkRuns() {
  const kinds = runKinds();
  return runsWithWeights().filter((r) => kinds.get(r.id) === "check");
}

/** Trial runs so far, whatever they are named (see runKinds). */
export function trialCount() {
  const kinds = runKinds();
  return runsWithWeights().filter((r) => kinds.get(r.id) === "trial").length;
}

/** The run a trim starts from by default: the last check run, if one is stored after the trials. */
export function defaultFromRun() {
  const checks = checkRuns();
  return checks.length ? checks[checks.length - 1].id : null;
}

/** The options as the service takes them. */
export function solveOptions() {
  const o = state.options;
  const out = { objective: o.objective };
  if (o.drop) out.drop_dependent_planes = true;
  const limits = Object.entries(o.maxMass || {}).filter(([p, v]) => v && state.setup.planes.some((x) => x.id === p));
  if (limits.length) out.max_mass_g = Object.fromEntries(limits);
  const sensors = state.setup.sensors.map((x) => x.id).filter((id) => !(o.leaveSensors || []).includes(id));
  if (sensors.length < state.setup.sensors.length && sensors.length) out.sensors = sensors;
  const speeds = state.setup.speeds.filter((x) => !(o.leaveSpeeds || []).includes(x));
  if (speeds.length < state.setup.speeds.length && speeds.length) out.speeds_rpm = speeds;
  if (o.ampNoise) out.amplitude_noise_pct = o.ampNoise;
  if (o.phaseNoise) out.phase_noise_deg = o.phaseNoise;
  const from = o.fromRun === undefined || o.fromRun === null ? defaultFromRun() : o.fromRun;
  if (from && state.runs.some((r) => r.id === from)) out.from_run = from;
  // A trim job is solved with its coefficients (the session's `trim`).
  const trim = state.setup.trim;
  if (trim && trim.coefficients_from) out.coefficients_from = trim.coefficients_from;
  else if (trim && trim.influence_coefficients) out.influence_coefficients = trim.influence_coefficients;
  if (o.discrete !== false && state.setup.planes.some((p) => p.kit && p.kit.masses_g && p.kit.masses_g.length) &&
      state.setup.planes.every((p) => p.kit && p.kit.masses_g && p.kit.masses_g.length)) out.discrete = true;
  return out;
}

/** The units the set-up's sensors read in, each once, in sensor order. */
export function sensorUnits() {
  return [...new Set(state.setup.sensors.map((x) => x.unit).filter(Boolean))];
}

/**
 * The acceptable vibration: one figure when every sensor reads in one unit;
 * one per unit when they mix, since one figure cannot be both 50 µm and
 * 50 mils.
 */
function limitFields(o) {
  const units = sensorUnits();
  if (units.length <= 1) {
    return h("label", {}, h("span", {}, `Acceptable vibration (largest reading, ${commonUnit(state.setup.sensors) || "sensor units"})`), numberInput({ field: "options.limit", kind: "limit", value: o.limit ?? null, required: false, label: "Acceptable vibration", placeholder: "none", onValue: (v) => (o.limit = v) }));
  }
  o.limits = o.limits || {};
  return h("div", { class: "limits vibration" }, h("span", {}, "Acceptable vibration (largest reading), for the sensors in each unit"),
    h("div", { class: "pair" }, units.map((u) => h("label", {}, `${unitLabel(u)} `, numberInput({ field: `options.limit.${u}`, kind: "limit", value: o.limits[u] ?? null, required: false, label: `Acceptable vibration, ${unitLabel(u)}`, placeholder: "none", size: 5, onValue: (v) => (o.limits[u] = v) })))));
}

function tickList(title, items, chosen, cls) {
  return h("fieldset", { class: `leave ${cls}` }, h("legend", {}, title),
    items.map(([value, text]) => h("label", { class: "tick" },
      h("input", { type: "checkbox", value: String(value), checked: chosen.includes(value), onchange: (e) => {
        const at = chosen.indexOf(value);
        if (e.target.checked && at < 0) chosen.push(value);
        if (!e.target.checked && at >= 0) chosen.splice(at, 1);
      } }), ` ${text}`)));
}

/** The options panel of the corrections step. */
export function optionsPanel() {
  const o = state.options;
  o.maxMass = o.maxMass || {};
  o.leaveSensors = o.leaveSensors || [];
  o.leaveSpeeds = o.leaveSpeeds || [];
  const withWeights = runsWithWeights();
  const from = o.fromRun === undefined || o.fromRun === null ? defaultFromRun() : o.fromRun;
  return h("details", { class: "options", open: o.open || undefined, ontoggle: (e) => (o.open = e.target.open) },
    h("summary", {}, "Options: what to minimise, limits, what to leave out, noise"),
    h("div", { class: "option-grid" },
      h("label", {}, h("span", {}, "Minimise"), h("select", { class: "objective", onchange: (e) => (o.objective = e.target.value) },
        h("option", { value: "least_squares", selected: o.objective === "least_squares" }, "the sum of squares (usual)"),
        h("option", { value: "min_max", selected: o.objective === "min_max" }, "the largest vibration"))),
      withWeights.length ? h("label", {}, h("span", {}, "Correct the rotor as it is in"), h("select", { class: "from-run", onchange: (e) => (o.fromRun = e.target.value) },
        // A trim job had no trial weights to take off.
        h("option", { value: "", selected: !from }, state.setup.trim ? "the zero run (as found)" : "the zero run (all trial weights off)"),
        withWeights.map((r) => h("option", { value: r.id, selected: from === r.id }, `run “${r.id}” (its weights stay on)`)))) : "",
      limitFields(o),
      h("label", { class: "tick" }, h("input", { type: "checkbox", class: "drop", checked: !!o.drop, onchange: (e) => (o.drop = e.target.checked) }), " leave out planes the sensors cannot tell apart"),
      h("div", { class: "noise" },
        h("span", {}, "Reading repeatability (for the 95 % figures)"),
        h("div", { class: "pair" },
          h("label", {}, "amplitude, % ", numberInput({ field: "options.amplitude_noise_pct", kind: "noise", value: o.ampNoise, required: false, label: "Amplitude repeatability, %", placeholder: "2", size: 4, onValue: (v) => (o.ampNoise = v) })),
          h("label", {}, "phase, ° ", numberInput({ field: "options.phase_noise_deg", kind: "noise", value: o.phaseNoise, required: false, label: "Phase repeatability, degrees", placeholder: "2", size: 4, onValue: (v) => (o.phaseNoise = v) })))),
      h("div", { class: "limits" }, h("span", {}, "Largest correction mass per plane, g"),
        h("div", { class: "pair" }, state.setup.planes.map((p) => h("label", {}, `${p.id} `, numberInput({ field: `options.max_mass_g.${p.id}`, kind: "mass", value: o.maxMass[p.id] ?? null, required: false, label: `Mass limit, plane ${p.id}, g`, placeholder: "none", size: 5, onValue: (v) => (o.maxMass[p.id] = v) }))))),
    ),
    tickList("Leave out sensors", state.setup.sensors.map((x) => [x.id, x.id]), o.leaveSensors, "sensors"),
    state.setup.speeds.length > 1 ? tickList("Leave out speeds", state.setup.speeds.map((x) => [x, `${fmt(x, 0)} rpm`]), o.leaveSpeeds, "speeds") : "",
  );
}
