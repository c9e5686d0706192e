// Step 1, the set-up: name, machine, conventions (with the picture), planes,
// sensors and speeds. Fixed once the session is stored (the API has no way to
// change a stored set-up; export, edit and import to start a changed copy).

import { h, replace, $ } from "../page/dom.js";
import { numberInput, textInput, selectInput, validateAll, mark, clearMarks, banner } from "../page/fields.js";
import { parseSpeeds, UNITS, SPEEDS_RULE, DECIMAL_RULE, check } from "../page/num.js";
import { conventionsPicture } from "./picture.js";
import { state, setupLocked, trimWords } from "../job/state.js";
import { api } from "../job/api.js";

/** ISO 21940-11 grades offered, and none (no rotor data). */
export const GRADE_CHOICES = [["", "none"], ...["G0.4", "G1", "G2.5", "G6.3", "G16", "G40"].map((g) => [g, g])];

const PHASES = [
  ["lag", "Phase lag (most analysers)"],
  ["lead", "Phase lead"],
];
const DIRECTIONS = [
  ["against_rotation", "Against rotation"],
  ["with_rotation", "With rotation"],
];

function planeRow(plane, i, locked, rerender) {
  return h(
    "tr",
    {},
    h("td", {}, textInput({ field: `planes[${i}].id`, value: plane.id, required: true, label: `Plane ${i + 1} name`, placeholder: "e.g. A", disabled: locked, size: 10, maxlength: 64, onValue: (v) => (plane.id = v) })),
    h("td", {}, numberInput({ field: `planes[${i}].radius_mm`, kind: "radius", value: plane.radius_mm, required: false, label: `Plane ${i + 1} radius, mm`, disabled: locked, onValue: (v) => (plane.radius_mm = v) })),
    h("td", {}, numberInput({ field: `planes[${i}].positions`, kind: "positions", value: plane.positions, required: false, label: `Plane ${i + 1} fixed places`, placeholder: "free", disabled: locked, size: 5, onValue: (v) => (plane.positions = v) })),
    h("td", {}, listInput({ field: `planes[${i}].places_deg`, kind: "angle", value: plane.places_deg, label: `Plane ${i + 1} places at, degrees`, placeholder: "e.g. 0 40 100", disabled: locked, size: 16, onValue: (v) => (plane.places_deg = v) })),
    h("td", {}, listInput({ field: `planes[${i}].kit.masses_g`, kind: "mass", value: plane.kit && plane.kit.masses_g, label: `Plane ${i + 1} kit weights, g`, placeholder: "e.g. 5 10 20", disabled: locked, size: 10, onValue: (v) => (plane.kit = v ? { masses_g: v, max_per_place: (plane.kit && plane.kit.max_per_place) || 2 } : null) })),
    h("td", {}, locked || state.setup.planes.length < 2 ? "" : h("button", { type: "button", class: "small", "aria-label": `Remove plane ${i + 1}`, onclick: () => { state.setup.planes.splice(i, 1); rerender(); } }, "Remove")),
  );
}

function sensorRow(sensor, i, locked, rerender) {
  return h(
    "tr",
    {},
    h("td", {}, textInput({ field: `sensors[${i}].id`, value: sensor.id, required: true, label: `Sensor ${i + 1} name`, placeholder: "e.g. 1H", disabled: locked, size: 10, maxlength: 64, onValue: (v) => (sensor.id = v) })),
    h("td", {}, selectInput({ field: `sensors[${i}].unit`, value: sensor.unit, choices: Object.entries(UNITS), label: `Sensor ${i + 1} unit`, disabled: locked, onValue: (v) => (sensor.unit = v) })),
    h("td", {}, textInput({ field: `sensors[${i}].label`, value: sensor.label, label: `Sensor ${i + 1} position`, placeholder: "e.g. DE bearing, horizontal", disabled: locked, size: 22, onValue: (v) => (sensor.label = v) })),
    h("td", {}, locked || state.setup.sensors.length < 2 ? "" : h("button", { type: "button", class: "small", "aria-label": `Remove sensor ${i + 1}`, onclick: () => { state.setup.sensors.splice(i, 1); rerender(); } }, "Remove")),
  );
}

/**
 * A list of numbers typed in one field ("0 40 100" or "0; 40; 100"), each
 * checked by the rule of `kind`; `onValue` gets the list, or null when empty.
 */
function listInput({ field, kind, value, label, placeholder, disabled, onValue, size = 12 }) {
  const input = h("input", { type: "text", class: "list", dataset: { field }, "aria-label": label, placeholder, disabled, size, value: Array.isArray(value) ? value.join(" ") : "", autocomplete: "off" });
  const validate = () => {
    const text = input.value.trim();
    if (text === "") { mark(input, ""); onValue(null); return true; }
    if (/\d,\d/.test(text)) { mark(input, "separate the numbers with spaces or “;”, decimals with a point"); return false; }
    const out = [];
    for (const part of text.split(/[\s;,]+/).filter(Boolean)) {
      const r = check(part, kind);
      if (r.error) { mark(input, `${part}: ${r.error}`); return false; }
      out.push(r.value);
    }
    mark(input, "");
    onValue(out);
    return true;
  };
  input.addEventListener("input", validate);
  input.validateNow = validate;
  return h("span", { class: "field text-field" }, input, h("span", { class: "msg", role: "alert" }));
}

/** Rotor data: for the ISO 21940-11 check and for sizing a trial weight. */
function rotorFields(setup, locked) {
  const r = setup.rotor || (setup.rotor = { mass_kg: null, service_speed_rpm: null, balance_grade: "" });
  return h("fieldset", { class: "rotor" }, h("legend", {}, "Rotor (optional: for the ISO 21940-11 check and the trial-weight size)"),
    h("label", {}, h("span", {}, "Mass, kg"), numberInput({ field: "rotor.mass_kg", kind: "rotor_mass", value: r.mass_kg, required: false, label: "Rotor mass, kg", disabled: locked, onValue: (v) => (r.mass_kg = v) })),
    h("label", {}, h("span", {}, "Service speed, rpm"), numberInput({ field: "rotor.service_speed_rpm", kind: "speed", value: r.service_speed_rpm, required: false, label: "Service speed, rpm", disabled: locked, onValue: (v) => (r.service_speed_rpm = v) })),
    h("label", {}, h("span", {}, "Balance grade"), selectInput({ field: "rotor.balance_grade", value: r.balance_grade || "", choices: GRADE_CHOICES, label: "Balance grade", disabled: locked, onValue: (v) => (r.balance_grade = v) })));
}

/**
 * The rotor is all three of mass, service speed and grade, or none: the
 * service refuses a rotor without its grade (missing_field), and the form
 * left out a rotor without its speed without a word. The missing ones are marked.
 */
export function checkRotor(root, rotor, prefix = "") {
  if (!rotor) return true;
  const parts = [
    ["mass_kg", rotor.mass_kg, "the rotor's mass, kg"],
    ["service_speed_rpm", rotor.service_speed_rpm, "the service speed, rpm"],
    ["balance_grade", rotor.balance_grade, "the balance grade"],
  ];
  const given = (v) => v !== null && v !== undefined && v !== "";
  if (!parts.some(([, v]) => given(v))) return true;
  let ok = true;
  for (const [key, v, words] of parts) {
    if (given(v)) continue;
    mark($(`[data-field="${prefix}rotor.${key}"]`, root), `${words}: needed with the rest of the rotor data (or leave all three empty)`);
    ok = false;
  }
  return ok;
}

/** Ids must be unique within planes and within sensors; mark the repeats. */
function checkUnique(root, list, kind) {
  const seen = new Set();
  let ok = true;
  list.forEach((item, i) => {
    if (!item.id) return;
    if (seen.has(item.id)) {
      mark($(`[data-field="${kind}[${i}].id"]`, root), "used twice");
      ok = false;
    }
    seen.add(item.id);
  });
  return ok;
}

/**
 * A trim job says so from its first step, naming whose coefficients it is
 * solved with: the machine's
 * stored ones and their version (the one the session names, or the latest,
 * asked of the service, as the solve will take), or the supplied ones.
 */
function trimNote(trim) {
  if (!trim) return "";
  const from = trim.coefficients_from;
  const say = (which) => `Trim job: solved with ${trimWords(trim)}${which}, instead of trial runs: a zero run is all it needs.`;
  if (!from || from.version) return h("p", { class: "note trim-note" }, say(from ? `, version ${from.version}` : ""));
  const note = h("p", { class: "note trim-note" }, say(", the latest version"));
  api.getMachine(from.machine).then((m) => {
    const versions = (m.coefficients || []).map((c) => c.version).filter(Number.isFinite);
    if (versions.length) note.textContent = say(`, version ${Math.max(...versions)} (the latest)`);
  }, () => {});
  return note;
}

/** Render the set-up step into `root`; `next` is called when it checks out. */
export function renderSetup(root, next) {
  const locked = setupLocked();
  const setup = state.setup;
  const rerender = () => renderSetup(root, next);
  // Enter in a field goes on, as Enter stores a run in the grid.
  root.onkeydown = (e) => {
    if (e.key !== "Enter" || !e.target.matches("input")) return;
    e.preventDefault();
    $("button.next", root)?.click();
  };
  const picture = h("div", { class: "picture-slot" }, conventionsPicture(setup.conventions));
  const redrawPicture = () => replace(picture, conventionsPicture(setup.conventions));
  const speeds = h("input", {
    type: "text",
    dataset: { field: "speeds" },
    "aria-label": "Speeds, rpm",
    placeholder: "e.g. 1480 or 1480 2950",
    disabled: locked,
    size: 24,
    value: setup.speeds.join(" "),
  });
  const checkSpeeds = (showRequired) => {
    const r = parseSpeeds(speeds.value);
    mark(speeds, r.error && (showRequired || speeds.value.trim() !== "") ? r.error : "");
    if (!r.error) setup.speeds = r.value;
    return !r.error;
  };
  speeds.addEventListener("input", () => checkSpeeds(false));
  speeds.validateNow = () => checkSpeeds(true);

  replace(
    root,
    h("h2", {}, "1 · Set-up"),
    trimNote(setup.trim),
    locked ? h("p", { class: "note" }, "This set-up is stored with the session and can no longer change. To change it, export the session as JSON, edit it and import it as a new session.") : "",
    h(
      "fieldset",
      { class: "job" },
      h("legend", {}, "Job"),
      h("label", {}, h("span", {}, "Name"), textInput({ field: "name", value: setup.name, required: true, label: "Session name", placeholder: "e.g. ID fan 3, coupling end", disabled: locked, size: 32, onValue: (v) => (setup.name = v) })),
      h("label", {}, h("span", {}, "Machine"), textInput({ field: "machine", value: setup.machine, label: "Machine", placeholder: "e.g. ID-FAN-3", disabled: locked, size: 20, maxlength: 64, onValue: (v) => (setup.machine = v) })),
      h("label", {}, h("span", {}, "Speeds, rpm"), h("span", { class: "field" }, speeds, h("span", { class: "msg", role: "alert" }), h("span", { class: "hint rule" }, SPEEDS_RULE))),
      h("p", { class: "hint rule decimal-rule" }, DECIMAL_RULE),
    ),
    h(
      "fieldset",
      { class: "conventions" },
      h("legend", {}, "Conventions — the analyser's, not ours"),
      h(
        "div",
        { class: "conv-choices" },
        h("label", {}, h("span", {}, "Phase"), selectInput({ field: "conventions.phase", value: setup.conventions.phase, choices: PHASES, label: "Phase convention", disabled: locked, onValue: (v) => { setup.conventions.phase = v; redrawPicture(); } })),
        h("label", {}, h("span", {}, "Weight angles"), selectInput({ field: "conventions.angle_direction", value: setup.conventions.angle_direction, choices: DIRECTIONS, label: "Weight angle direction", disabled: locked, onValue: (v) => { setup.conventions.angle_direction = v; redrawPicture(); } })),
      ),
      picture,
    ),
    h(
      "fieldset",
      { class: "planes" },
      h("legend", {}, "Correction planes"),
      h("div", { class: "scroll" }, h("table", { class: "edit" },
        h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Radius, mm"), h("th", {}, "Fixed places"), h("th", {}, "or places at, ° from the mark"), h("th", {}, "Kit weights, g"), h("th", {}))),
        h("tbody", {}, setup.planes.map((p, i) => planeRow(p, i, locked, rerender))),
      )),
      locked ? "" : h("button", { type: "button", class: "add-plane", onclick: () => { setup.planes.push({ id: "", radius_mm: null, positions: null }); rerender(); $(`[data-field="planes[${setup.planes.length - 1}].id"]`, root).focus(); } }, "+ Add plane"),
      h("p", { class: "hint" }, "Fixed places: the number of equally spaced holes or blades where weights can go (place 0 at the mark, the next ones numbered the way the weight angles are counted), or their angles from the mark, counted like the weight angles, when they are not equally spaced. Leave empty for a free angle. Kit: the weight sizes at hand (at most two stacked at a place); the answer then says which to bolt where."),
    ),
    h(
      "fieldset",
      { class: "sensors" },
      h("legend", {}, "Sensors"),
      h("div", { class: "scroll" }, h("table", { class: "edit" },
        h("thead", {}, h("tr", {}, h("th", {}, "Sensor"), h("th", {}, "Unit"), h("th", {}, "Where"), h("th", {}))),
        h("tbody", {}, setup.sensors.map((x, i) => sensorRow(x, i, locked, rerender))),
      )),
      locked ? "" : h("button", { type: "button", class: "add-sensor", onclick: () => { setup.sensors.push({ id: "", unit: setup.sensors[setup.sensors.length - 1].unit, label: "" }); rerender(); $(`[data-field="sensors[${setup.sensors.length - 1}].id"]`, root).focus(); } }, "+ Add sensor"),
    ),
    rotorFields(setup, locked),
    h(
      "div",
      { class: "actions" },
      h("button", {
        type: "button",
        class: "primary next",
        onclick: () => {
          if (locked) return next();
          clearMarks(root);
          const ok = validateAll(root) && checkUnique(root, setup.planes, "planes") && checkUnique(root, setup.sensors, "sensors") && checkRotor(root, setup.rotor);
          if (ok) next();
          else banner(root, "error", "Some fields need attention; they are marked in red.");
        },
      }, locked ? "Go to the runs →" : "Next: zero run →"),
    ),
  );
}
