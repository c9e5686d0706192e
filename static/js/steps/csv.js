// Readings from a CSV file into the run being typed. Two shapes are read:
//   a row per reading:  speed_rpm, sensor, amplitude, phase_deg [, run]
//   a column per run:   speed_rpm, sensor, <run> amplitude, <run> phase, …
// Separated by commas (decimals with a point) or by semicolons (decimals with
// a point or a comma, as spreadsheets with a decimal comma write them).

import { h, $ } from "../page/dom.js";
import { banner } from "../page/fields.js";
import { parseNumber, RULES } from "../page/num.js";
import { state, rows } from "../job/state.js";

export const CSV_SHAPES = "A CSV file of readings has a header row and one of two shapes: a row per reading (columns speed, sensor, amplitude, phase, and optionally run) or a column per run (speed, sensor, then “<run> amplitude” and “<run> phase” for each run, e.g. “zero amplitude”). Separate by commas, or by semicolons when decimals are written with a comma.";

/** Split CSV text into rows of fields (quotes as RFC 4180). */
function split(text, sep) {
  const out = [];
  let row = [];
  let field = "";
  let quoted = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { field += '"'; i++; } else if (c === '"') quoted = false; else field += c;
    } else if (c === '"') quoted = true;
    else if (c === sep) { row.push(field); field = ""; } else if (c === "\n" || c === "\r") {
      if (c === "\r" && text[i + 1] === "\n") i++;
      row.push(field);
      if (row.some((f) => f.trim() !== "")) out.push(row);
      row = [];
      field = "";
    } else field += c;
  }
  row.push(field);
  if (row.some((f) => f.trim() !== "")) out.push(row);
  return out;
}

const norm = (s) => s.trim().toLowerCase().replace(/[^a-z0-9]+/g, " ").trim();

function findColumn(header, names) {
  return header.findIndex((x) => names.includes(norm(x)));
}

/**
 * Readings of run `runName` from CSV text: `{ readings: [{speed, sensor,
 * amplitude, phase}], shape }` or `{ error }` in plain words.
 */
export function readingsFromCsv(text, runName) {
  const first = text.split(/\r?\n/, 1)[0] || "";
  const sep = first.includes(";") ? ";" : first.includes("\t") ? "\t" : ",";
  const table = split(text, sep);
  if (table.length < 2) return { error: "the file has no rows of readings under its header" };
  const header = table[0];
  const speedCol = findColumn(header, ["speed", "speed rpm", "rpm"]);
  const sensorCol = findColumn(header, ["sensor", "sensor id", "probe"]);
  if (speedCol < 0 || sensorCol < 0) return { error: "the first row must name the columns, with one called speed (or speed_rpm) and one called sensor" };
  const ampCol = findColumn(header, ["amplitude", "amp"]);
  const phaseCol = findColumn(header, ["phase", "phase deg"]);
  const runCol = findColumn(header, ["run", "run id"]);
  let pick;
  let shape;
  if (ampCol >= 0 && phaseCol >= 0) {
    shape = "a row per reading";
    const runs = runCol >= 0 ? [...new Set(table.slice(1).map((r) => (r[runCol] || "").trim()))] : [];
    const wanted = runs.length <= 1 ? null : runName;
    if (wanted !== null && !runs.includes(wanted)) return { error: `the file has runs ${runs.join(", ")} but none called “${runName}”: name the run as in the file` };
    pick = (r) => (wanted === null || (r[runCol] || "").trim() === wanted ? [r[ampCol], r[phaseCol]] : null);
  } else {
    shape = "a column per run";
    const pairs = [];
    header.forEach((name, i) => {
      const m = /^(.*?)[\s_:-]*(amplitude|amp)$/i.exec(name.trim());
      if (!m) return;
      const run = m[1].trim();
      const p = header.findIndex((x) => new RegExp(`^${run.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}[\\s_:-]*phase`, "i").test(x.trim()));
      if (p >= 0) pairs.push({ run, amp: i, phase: p });
    });
    if (!pairs.length) return { error: "no readings found: give columns amplitude and phase (a row per reading), or “<run> amplitude” and “<run> phase” (a column per run)" };
    const pair = pairs.length === 1 ? pairs[0] : pairs.find((p) => p.run === runName);
    if (!pair) return { error: `the file has runs ${pairs.map((p) => p.run).join(", ")} but none called “${runName}”: name the run as in the file` };
    pick = (r) => [r[pair.amp], r[pair.phase]];
  }
  const readings = [];
  for (let i = 1; i < table.length; i++) {
    const r = table[i];
    const values = pick(r);
    if (!values) continue;
    // A file separated by semicolons writes decimals with a comma: that is its rule, not an ambiguity.
    const num = (t) => parseNumber(sep === ";" ? String(t || "").replace(",", ".") : t);
    const speed = num(r[speedCol]);
    const amp = num(values[0]);
    const phase = num(values[1]);
    const line = i + 1;
    if (speed.error || speed.empty) return { error: `line ${line}: the speed is not a number` };
    if (amp.error || amp.empty || !RULES.amplitude.test(amp.value)) return { error: `line ${line}: the amplitude is not a number of 0 or more` };
    if (phase.error || phase.empty || !RULES.phase.test(phase.value)) return { error: `line ${line}: the phase must be a number from 0 to 360` };
    readings.push({ speed: speed.value, sensor: (r[sensorCol] || "").trim(), amplitude: amp.value, phase: phase.value });
  }
  return { readings, shape };
}

/** Put readings into the draft's cells; returns how many cells were filled and the rows not in the grid. */
export function fillDraft(d, readings) {
  let filled = 0;
  const unknown = [];
  for (const x of readings) {
    const i = rows().findIndex((row) => row.sensor === x.sensor && Math.abs(row.speed - x.speed) <= 0.01 * Math.max(row.speed, x.speed));
    if (i < 0) { unknown.push(`${x.sensor} at ${x.speed} rpm`); continue; }
    d.cells[i] = { amplitude: x.amplitude, phase_deg: x.phase };
    filled++;
  }
  return { filled, unknown };
}

/** The button that reads a CSV file into the run being typed. */
export function csvImportButton(root, rerender) {
  const file = h("input", { type: "file", accept: ".csv,text/csv", class: "csv-file", "aria-label": "Readings CSV file" });
  file.addEventListener("change", async () => {
    const f = file.files[0];
    const d = state.draft;
    if (!f || !d) return;
    const text = await f.text();
    // The same file may be chosen again (after renaming the run to the one in it).
    file.value = "";
    const r = readingsFromCsv(text, d.id);
    if (r.error) return banner(root, "error", `${f.name} was not read: ${r.error}. ${CSV_SHAPES}`);
    const { filled, unknown } = fillDraft(d, r.readings);
    rerender();
    const note = `${filled} of ${rows().length} readings read from ${f.name} (${r.shape}).` + (unknown.length ? ` Not in the grid, so left out: ${unknown.join(", ")}.` : "");
    banner(root, filled === rows().length ? "ok" : "error", note);
    $(".banner", root).classList.add("csv-result");
  });
  return h("label", { class: "button csv-import", title: CSV_SHAPES }, "Readings from a CSV file…", file);
}
