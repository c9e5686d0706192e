// Residual-unbalance check (API 617 / API 684 test-stand acceptance): the
// trial weight placed in turn at equally spaced angles, the 1X reading at
// each, by `POST /api/v1/residual-unbalance`. Positions are pasted a line
// each ("angle amplitude phase", the phase optional), as a spreadsheet copies
// them; the answer is the service's, with its 95 % interval, API's own
// worksheet figure beside it and its warnings in its words. Nothing is stored.

import { h, replace, $ } from "../page/dom.js";
import { numberInput, selectInput, textInput, mark, clearMarks, banner, sendAndShow } from "../page/fields.js";
import { parseNumber, fmt, fmtAngle, isHeading } from "../page/num.js";
import { api } from "../job/api.js";
import { keepPage, keptPage, forgetPage } from "../job/keep.js";

const PHASES = [["lag", "lag (the analyser's default)"], ["lead", "lead"]];
const DIRECTIONS = [["against_rotation", "against rotation"], ["with_rotation", "with rotation"]];

const EMPTY = {
  plane: "", speed_rpm: null, journal_load_kg: null, mass_g: null, radius_mm: null,
  phase: "lag", angle_direction: "against_rotation", readings: "", answer: null,
};

// What was typed (and the answer to it), kept while other steps are visited
// and across a reload (keep.js), until "Start over".
const typed = keptPage("residual", EMPTY);
if (!PHASES.some(([v]) => v === typed.phase)) typed.phase = EMPTY.phase;
if (!DIRECTIONS.some(([v]) => v === typed.angle_direction)) typed.angle_direction = EMPTY.angle_direction;
const keepTyped = () => keepPage("residual", typed);

/**
 * The positions of pasted text, a line each: trial angle, amplitude and
 * optionally phase, separated by tabs, spaces or ";" (decimal commas as in
 * the runs grid), or by ", " between numbers; a degree sign after an angle
 * or phase (30°) as a spreadsheet formats it, and a heading line over the
 * columns ("Angle  Amplitude  Phase"), are passed over. `{ readings }` or
 * `{ error }` naming the line.
 */
export function parsePositions(text) {
  const lines = String(text || "").split(/\r?\n/).map((l, k) => ({ k: k + 1, line: l.trim() })).filter((l) => l.line !== "");
  if (lines.length && isHeading(lines[0].line)) lines.shift();
  if (!lines.length) return { error: "paste a line per trial position: angle, amplitude and (optionally) phase" };
  const readings = [];
  for (const { k, line } of lines) {
    const tokens = line.split(/[\s;]+|,\s+/).filter((x) => x !== "");
    if (tokens.length < 2 || tokens.length > 3) {
      return { error: `line ${k} (${line}): angle and amplitude, then the phase if measured` };
    }
    const values = [];
    for (const [i, token] of tokens.entries()) {
      const r = parseNumber(i === 1 ? token : token.replace(/\s*°$/, ""));
      if (r.error) return { error: `line ${k} (${token}): ${r.error}` };
      values.push(r.value);
    }
    const reading = { angle_deg: values[0], amplitude: values[1] };
    if (values.length === 3) reading.phase_deg = values[2];
    readings.push(reading);
  }
  return { readings };
}

function answerTable(a) {
  const dir = (a.conventions && a.conventions.angle_direction) === "with_rotation" ? "with rotation" : "against rotation";
  const u = a.uncertainty || {};
  const interval = (pair, f) => (Array.isArray(pair) ? `${f(pair[0])} to ${f(pair[1])}` : "–");
  const gmm = (x) => `${fmt(x, 0)} g·mm`;
  const angleUndetermined = Array.isArray(u.residual_angle_deg) && u.residual_angle_deg[0] === 0 && u.residual_angle_deg[1] === 360;
  const rows = [
    ["verdict", "Verdict", a.pass ? `Pass: residual ${fmt(100 * a.ratio, 0)} % of the allowable` : `Fail: residual ${fmt(100 * a.ratio, 0)} % of the allowable`],
    ["residual", "Residual unbalance", `${gmm(a.residual_unbalance_gmm)} (95 %: ${interval(u.residual_unbalance_gmm, (x) => fmt(x, 0))} g·mm)`],
    ["angle", `Where it is (heavy spot), ° ${dir} from the trial's 0°`, angleUndetermined
      ? `${fmtAngle(a.residual_angle_deg)} (undetermined)`
      : `${fmtAngle(a.residual_angle_deg)} (95 %: ${interval(u.residual_angle_deg, (x) => fmtAngle(x))})`],
    ["allowable", "Allowable, API 6350·W/N", gmm(a.allowable_gmm)],
    ["trial", "Trial unbalance", `${gmm(a.trial_unbalance_gmm)} (${fmt(a.trial_ratio, 1)} × allowable; API asks 1 to 2)`],
    ["method", "Fit", a.method === "circle_fit"
      ? `circle through ${a.positions} positions (amplitudes and phases)`
      : `amplitudes of ${a.positions} positions (no phases)`],
  ];
  if (a.alternative_residual_gmm !== undefined && a.alternative_residual_gmm !== null) {
    rows.push(["alternative", "The other residual the amplitudes allow", gmm(a.alternative_residual_gmm)]);
  }
  if (a.worksheet) {
    rows.push(["worksheet", "API worksheet (trial · Y/Z)", `${gmm(a.worksheet.residual_unbalance_gmm)}, ${a.worksheet.pass ? "pass" : "fail"}`]);
  }
  return h("table", { class: "residual-answer" },
    h("tbody", {}, rows.map(([cls, label, value]) => h("tr", { class: cls }, h("th", { scope: "row" }, label), h("td", {}, value)))));
}

function answerView(a) {
  const warnings = Array.isArray(a.warnings) ? a.warnings : [];
  return h("div", { class: `residual-result ${a.pass ? "pass" : "fail"}`, role: "status" },
    h("h3", {}, a.plane ? `Answer, plane ${a.plane}` : "Answer"),
    answerTable(a),
    warnings.length
      ? h("div", { class: "warnings residual-warnings", role: "alert" },
        h("ul", {}, warnings.map((w) => h("li", { dataset: { code: w.code || "" } }, `⚠ ${w.message || w.code}`))))
      : null);
}

/** Draw the residual-unbalance page in `root`. */
export function renderResidual(root) {
  const readings = h("textarea", {
    rows: 13, cols: 28, spellcheck: "false", autocomplete: "off",
    dataset: { field: "readings" }, "aria-label": "Readings, a line per trial position",
    placeholder: "0 2.45 335.7\n30 2.59 356.3\n60 2.62 15.5\n…",
    oninput: () => { typed.readings = readings.value; mark(readings, ""); },
  });
  readings.value = typed.readings;
  const result = h("div", { class: "residual-out" }, keptAnswer());
  const run = h("button", { type: "submit", class: "primary check-residual" }, "Check");
  const again = h("button", { type: "button", class: "start-over", onclick: () => startOver() }, "Start over");
  const num = (field, kind, label, placeholder, key) => h("label", {}, h("span", {}, label),
    numberInput({ field, kind, value: typed[key], label, placeholder, size: 9, onValue: (v) => { typed[key] = v; } }));
  const form = h("form", { class: "decay-form residual-form", novalidate: true, onsubmit: (e) => { e.preventDefault(); check(); } },
    h("div", { class: "decay-fields" },
      h("label", {}, h("span", {}, "Readings: a line per trial position — the trial weight's angle, the 1X amplitude (any one unit), and its phase if measured; pasted from a spreadsheet or separated by spaces"),
        h("span", { class: "field readings-field" }, readings, h("span", { class: "msg", role: "alert" }))),
      h("div", { class: "decay-side" },
        h("label", {}, h("span", {}, "Plane (optional)"),
          textInput({ field: "plane", value: typed.plane, label: "Plane", size: 9, maxlength: 64, onValue: (v) => { typed.plane = v; } })),
        num("speed_rpm", "speed", "Speed, rpm (API's N)", "9000", "speed_rpm"),
        num("journal_load_kg", "load", "Static load on the nearest journal, kg (API's W)", "530.7", "journal_load_kg"),
        num("trial.mass_g", "mass", "Trial weight, g", "3", "mass_g"),
        num("trial.radius_mm", "radius", "Trial weight radius, mm", "150", "radius_mm"),
        h("label", {}, h("span", {}, "Phase convention"),
          selectInput({ field: "conventions.phase", value: typed.phase, choices: PHASES, label: "Phase convention", onValue: (v) => { typed.phase = v; } })),
        h("label", {}, h("span", {}, "Trial angles counted"),
          selectInput({ field: "conventions.angle_direction", value: typed.angle_direction, choices: DIRECTIONS, label: "Trial angle direction", onValue: (v) => { typed.angle_direction = v; } })),
        h("div", { class: "actions decay-actions" }, run, again))),
  );
  // Each field updates `typed` first (its own listener); the form hears it after.
  form.addEventListener("input", keepTyped);
  form.addEventListener("change", keepTyped);

  async function check() {
    clearMarks(root);
    mark(readings, "");
    banner(root, "error", "");
    for (const f of ["speed_rpm", "journal_load_kg", "trial.mass_g", "trial.radius_mm"]) {
      const input = $(`[data-field="${f}"]`, root);
      if (!input.validateNow()) return input.focus();
    }
    const parsed = parsePositions(readings.value);
    if (parsed.error) {
      mark(readings, parsed.error);
      return readings.focus();
    }
    const body = {
      speed_rpm: typed.speed_rpm,
      trial: { mass_g: typed.mass_g, radius_mm: typed.radius_mm },
      journal_load_kg: typed.journal_load_kg,
      readings: parsed.readings,
      conventions: { phase: typed.phase, angle_direction: typed.angle_direction },
    };
    if (typed.plane) body.plane = typed.plane;
    await sendAndShow({ root, run, result, typed, send: () => api.residualUnbalance(body), view: answerView });
    keepTyped();
  }

  /** The answer kept with the input; none if it cannot be drawn (kept by another version of the form). */
  function keptAnswer() {
    if (!typed.answer) return null;
    try {
      return answerView(typed.answer);
    } catch (e) {
      typed.answer = null;
      return null;
    }
  }

  /** Empty the page for another test, once the technician says so when something is typed. */
  function startOver() {
    const any = typed.readings.trim() !== "" || typed.plane !== "" || [typed.speed_rpm, typed.journal_load_kg, typed.mass_g, typed.radius_mm].some((v) => v !== null) || typed.answer;
    if (any && !window.confirm("Empty this page: the readings, the plane, speed, load and trial weight, and the answer? Cancel to keep them.")) return;
    Object.assign(typed, EMPTY);
    forgetPage("residual");
    renderResidual(root);
    $('[data-field="readings"]', root).focus();
  }

  replace(root,
    h("h2", {}, "Residual-unbalance check (API 617 / API 684)"),
    h("p", { class: "note" }, "The test-stand acceptance test: a known trial weight placed in turn at 4 or more equally spaced angles (API asks 6 or 12; the first may be repeated at the end), the 1X reading at each. The service fits all positions exactly and compares the residual with API's allowable 6350·W/N g·mm (4W/N oz·in). Nothing is stored."),
    form,
    result);
}
