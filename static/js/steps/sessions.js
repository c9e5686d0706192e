// The stored sessions: the list to reopen, import and export as JSON, and the
// readings and results as CSV.

import { h, replace, download, fileStem } from "../page/dom.js";
import { banner } from "../page/fields.js";
import { storedAt, fmtReading } from "../page/num.js";
import { pagedList } from "../page/paged.js";
import { api } from "../job/api.js";
import { state, sessionJson, rows, readingFor } from "../job/state.js";
import { weightsText } from "./runs.js";

/** Sessions listed at a time (the service's default page). */
const SESSIONS_PAGE = 50;

/** The list endpoint is paged; take the items whatever the wrapper is called. */
function items(data) {
  if (Array.isArray(data)) return data;
  for (const key of ["items", "sessions", "data", "results"]) if (data && Array.isArray(data[key])) return data[key];
  return [];
}

/** A CSV field: quoted, and guarded against spreadsheet formulas. */
function csvField(v) {
  let t = v === null || v === undefined ? "" : String(v);
  if (/^[=+\-@\t\r]/.test(t) && !/^-?\d/.test(t)) t = `'${t}`;
  return `"${t.replace(/"/g, '""')}"`;
}

function csv(rowsOut) {
  return rowsOut.map((r) => r.map(csvField).join(",")).join("\r\n") + "\r\n";
}

export function readingsCsv() {
  const out = [["run", `weights (angles ${state.setup.conventions.angle_direction})`, "speed_rpm", "sensor", "unit", "amplitude", `phase_deg (${state.setup.conventions.phase})`]];
  const units = new Map(state.setup.sensors.map((x) => [x.id, x.unit]));
  for (const run of state.runs.filter((r) => r.stored)) {
    for (const row of rows()) {
      const r = readingFor(run, row);
      // The weights as stored (12.345 g at 123.45°), not as the grid rounds them.
      if (r) out.push([run.id, weightsText(run.weights, fmtReading), r.speed_rpm, r.sensor, units.get(r.sensor), r.amplitude, r.phase_deg]);
    }
  }
  return csv(out);
}

/**
 * The solution as CSV: corrections (and their bias-corrected estimates),
 * the predicted residual per sensor and speed with its unit and the phases'
 * convention, and every warning in the service's words ("code: message", in
 * the column `note`). After `note`, a trim's `from_run` (the run whose state
 * the corrections add to, and whose readings are the residual's "before")
 * and each correction's `total` (the one weight per plane that replaces
 * every weight in it).
 */
export function resultsCsv() {
  const sol = state.solution;
  const conventions = sol.conventions || state.setup.conventions;
  const from = sol.from_run ?? "";
  const out = [["kind", "plane_or_sensor", "speed_rpm", "mass_g", `angle_deg (${conventions.angle_direction})`, "unbalance_gmm", "mass_95_lo", "mass_95_hi", "amplitude_before", "amplitude_after", "amplitude_95", `phase_deg (${conventions.phase})`, "unit", "note",
    "from_run", "total_mass_g", `total_angle_deg (${conventions.angle_direction})`]];
  for (const c of sol.corrections) {
    const u = c.uncertainty;
    const t = c.total;
    out.push(["correction", c.plane, "", c.mass_g, c.angle_deg, c.unbalance_gmm ?? "", u ? u.mass_g[0] : "", u ? u.mass_g[1] : "", "", "", "", "", "", "", from, t ? t.mass_g : "", t ? t.angle_deg : ""]);
    // The errors-in-variables estimate C* beside it (method.md 8.11), when the
    // noise is stated or measured: a row of its own, in the same columns.
    const b = u && u.bias_corrected;
    if (b) out.push(["bias_corrected", c.plane, "", b.mass_g, b.angle_deg, "", "", "", "", "", "", "", "", "", from, "", ""]);
  }
  for (const r of sol.predicted_residual) {
    out.push(["residual", r.sensor, r.speed_rpm, "", "", "", "", "", r.amplitude_before, r.amplitude, r.amplitude_95 ?? "", r.phase_deg, r.unit ?? "", "", from, "", ""]);
  }
  for (const w of sol.warnings || []) {
    out.push(["warning", w.plane ?? "", "", "", "", "", "", "", "", "", "", "", "", `${w.code}: ${w.message}`, "", "", ""]);
  }
  return csv(out);
}

/** Render the sessions page; `open(id)` reopens one, `imported(id)` after an import. */
export async function renderSessions(root, open, imported) {
  const list = h("tbody", {}, h("tr", {}, h("td", { colspan: 4 }, "Loading…")));
  const more = h("p", { class: "more" });
  const file = h("input", { type: "file", accept: "application/json,.json", class: "import-file", "aria-label": "Session JSON file" });
  file.addEventListener("change", async () => {
    const f = file.files[0];
    if (!f) return;
    let data;
    try {
      data = JSON.parse(await f.text());
    } catch (e) {
      return banner(root, "error", `${f.name} is not JSON: ${e.message}`);
    }
    const session = data && data.session ? data.session : data;
    try {
      const created = await api.createSession(session);
      imported(created.id);
    } catch (err) {
      banner(root, "error", `Not imported: ${err.message}${err.field ? ` (at ${err.field})` : ""}`);
    }
  });
  const current = state.runs.some((r) => r.stored);
  replace(root,
    h("h2", {}, "Sessions"),
    h("div", { class: "actions" },
      h("button", { type: "button", class: "new-session", onclick: () => open(null) }, "+ New session"),
      h("label", { class: "button" }, "Import JSON…", file),
      h("button", { type: "button", class: "export-json", disabled: !current, onclick: () => download(`${fileStem(state.setup.name)}.json`, JSON.stringify(sessionJson(), null, 1), "application/json") }, "Export this session (JSON)"),
      h("button", { type: "button", class: "export-readings", disabled: !current, onclick: () => download(`${fileStem(state.setup.name)}-readings.csv`, readingsCsv(), "text/csv") }, "Readings (CSV)"),
      h("button", { type: "button", class: "export-results", disabled: !state.solution, onclick: () => download(`${fileStem(state.setup.name)}-results.csv`, resultsCsv(), "text/csv") }, "Results (CSV)"),
    ),
    h("div", { class: "scroll" }, h("table", { class: "sessions" },
      h("thead", {}, h("tr", {}, h("th", {}, "Name"), h("th", {}, "Machine"), h("th", {}, "Stored"), h("th", {}))),
      list)),
    more,
  );
  const row = (x) => h("tr", {},
    h("td", {}, h("button", { type: "button", class: "link open-session", dataset: { id: x.id }, onclick: () => open(x.id) }, x.name ?? x.id)),
    h("td", {}, x.machine ?? ""),
    h("td", {}, storedAt(x.created_at), x.runs !== undefined ? h("small", {}, ` · ${x.runs} run${x.runs === 1 ? "" : "s"}`) : ""),
    h("td", {}, h("button", { type: "button", class: "small delete", onclick: async () => {
      if (!window.confirm(`Delete the stored session “${x.name ?? x.id}”?`)) return;
      try { await api.deleteSession(x.id); renderSessions(root, open, imported); } catch (err) { banner(root, "error", err.message); }
    } }, "Delete")));
  // The service lists a page at a time (newest first), every session reachable.
  await pagedList({
    root, list, more, row, pageSize: SESSIONS_PAGE, columns: 4,
    what: "sessions", shownAs: "stored sessions", empty: "No stored sessions yet.",
    fetchPage: async (limit, offset) => {
      const data = await api.listSessions(limit, offset);
      return { found: items(data), total: data && data.total };
    },
  });
}
