// Machines: the list, and a machine's page — its jobs over time (vibration
// before and after, with a small trend plot), its stored coefficient versions,
// a new job with the set-up of its last one, and a trim job from its stored
// coefficients that needs only a reference run.

import { h, s, replace, $ } from "../page/dom.js";
import { banner, textInput, numberInput, selectInput, markServerError, clearMarks } from "../page/fields.js";
import { checkRotor, GRADE_CHOICES } from "./setup.js";
import { fmt, storedAt, unitLabel } from "../page/num.js";
import { pagedList } from "../page/paged.js";
import { api, unwrapSession } from "../job/api.js";
import { state, setupOf, emptySetup } from "../job/state.js";
import { plainWarning } from "../answer/words.js";

/**
 * A machine's name, or "" when it has none. A machine is stored without a
 * name when none is typed; one stored earlier with its id as its name has
 * none either (not the id twice).
 */
const nameOf = (m) => (m.name && m.name.trim() !== m.id ? m.name : "");

/**
 * Each job's date on the trend's axis: the day; below it the time when another
 * job shares the day (with seconds when they share the minute too).
 */
export function jobDates(stamps) {
  const at = stamps.map((t) => String(t || ""));
  const shared = (i, n) => at.filter((t) => t.slice(0, n) === at[i].slice(0, n)).length > 1;
  return at.map((t, i) => [t.slice(0, 10), shared(i, 10) ? t.slice(11, shared(i, 16) ? 19 : 16) : ""]);
}

/** ", µm pk-pk" when every job on the trend reads in that one unit, else "". */
function trendUnit(jobs, units) {
  const all = new Set(jobs.map((j) => units.get(j.id)));
  const [one] = [...all];
  return all.size === 1 && one && one !== "mixed units" ? `, ${one}` : "";
}

/** Before and after per job, oldest first, as two lines over the jobs' dates. */
function trend(sessions, units) {
  const jobs = sessions.filter((x) => x.summary).sort((a, b) => String(a.created_at).localeCompare(String(b.created_at)));
  if (jobs.length === 0) return h("p", { class: "hint" }, "No solved job yet: the trend starts with the first.");
  const W = 360;
  const H = 150;
  // Scaled to the largest of both lines: a job can be predicted worse after
  // than before (a min-max or bounded answer), and its point stays inside.
  const top = Math.max(...jobs.flatMap((j) => [j.summary.rms_before, j.summary.rms_after]).filter(Number.isFinite), 1e-9);
  const x = (i) => (jobs.length === 1 ? W / 2 : 40 + (i * (W - 80)) / (jobs.length - 1));
  const y = (v) => 10 + (1 - v / top) * (H - 60);
  const line = (key, colour) => [
    s("path", { d: jobs.map((j, i) => `${i ? "L" : "M"}${x(i).toFixed(1)},${y(j.summary[key]).toFixed(1)}`).join(" "), stroke: colour, class: "series" }),
    jobs.map((j, i) => s("circle", { cx: x(i), cy: y(j.summary[key]), r: 3, fill: colour })),
  ];
  // At most five dates fit under 360 units: the first, the last and evenly between.
  const shown = new Set(jobs.length <= 5 ? jobs.keys() : [0, 1, 2, 3, 4].map((k) => Math.round((k * (jobs.length - 1)) / 4)));
  const dates = jobDates(jobs.map((j) => j.created_at));
  return h("figure", { class: "trend-fig" },
    h("figcaption", {}, `RMS vibration per job${trendUnit(jobs, units)}: before (blue) and predicted after (green)`),
    s("svg", { viewBox: `0 0 ${W} ${H}`, class: "trend", role: "img", "aria-label": "Vibration per job over time" },
      s("line", { x1: 25, x2: W - 10, y1: y(0), y2: y(0), class: "grid" }),
      s("text", { x: 2, y: y(top) + 4, class: "tick" }, fmt(top, 0)),
      s("text", { x: 2, y: y(0) + 4, class: "tick" }, "0"),
      dates.map(([day, time], i) => (!shown.has(i) ? "" : s("text", { x: x(i), y: y(0) + 16, class: "tick date", "text-anchor": "middle" },
        s("tspan", { x: x(i) }, day), time ? s("tspan", { x: x(i), dy: 11 }, time) : ""))),
      s("text", { x: W / 2, y: H - 3, class: "axis-title", "text-anchor": "middle" }, "job, by the date it was stored (UTC)"),
      line("rms_before", "#1d4ed8"), line("rms_after", "#15803d")));
}

async function setupOfLatest(machine) {
  const sessions = [...(machine.sessions || [])].sort((a, b) => String(b.created_at).localeCompare(String(a.created_at)));
  if (!sessions.length) {
    const setup = emptySetup();
    setup.machine = machine.id;
    if (machine.rotor) setup.rotor = machine.rotor;
    return setup;
  }
  const data = await api.getSession(sessions[0].id);
  const setup = setupOf(unwrapSession(data));
  setup.name = "";
  setup.machine = machine.id;
  // The new job is a trim job only if asked for (startJob): not because the last one was.
  setup.trim = null;
  if (!setup.rotor && machine.rotor) setup.rotor = machine.rotor;
  return setup;
}

/**
 * The warnings of the machine's latest coefficient version, which a trim job
 * from the stored coefficients uses: jobs whose coefficients disagree with
 * the others' (named by their job names), in plain words with the service's
 * own beside them.
 */
function poolWarnings(latest, sessions) {
  const warnings = (latest && latest.warnings) || [];
  if (!warnings.length) return "";
  const names = new Map(sessions.map((x) => [x.id, x.name || x.id]));
  const jobs = (message) => [...String(message || "").matchAll(/'([^']+)'/g)].map((m) => `“${names.get(m[1]) || m[1]}”`);
  return h("div", { class: "warnings pool-warnings", role: "alert" },
    h("h4", {}, `Coefficient version ${latest.version}: ${warnings.length === 1 ? "a warning" : `${warnings.length} warnings`}`),
    h("ul", {}, warnings.map((w) => {
      const named = jobs(w.message);
      const what = w.code === "coefficients_disagree"
        ? [`Job${named.length === 1 ? "" : "s"} ${named.join(" and ")} ${named.length === 1 ? "does" : "do"} not agree with the other jobs' coefficients by more than the readings' scatter explains: the rotor, its mounting or its speed may have changed, or a weight was typed wrong.`,
          "Check those jobs' weights and readings before a trim job uses these coefficients; a trim job's check run will show whether they still hold."]
        : [plainWarning(w).what, plainWarning(w).todo];
      return h("li", { dataset: { code: w.code } },
        what[0],
        what[1] ? h("div", { class: "advice" }, `What to do: ${what[1]}`) : "",
        h("details", { class: "said" }, h("summary", {}, "The service's own words"), h("p", { class: "said-text" }, w.message)));
    })));
}

/**
 * The unit of each solved job's vibration, as the service gives it beside the
 * job's summary: the one unit of the rows the summary covers, "mixed units"
 * when they are several, "" from a service that does not say.
 */
function jobUnits(sessions) {
  const unitOf = (x) => (x.unit ? unitLabel(x.unit) : (x.units || []).length > 1 ? "mixed units" : "");
  return new Map(sessions.filter((x) => x.summary).map((x) => [x.id, unitOf(x)]));
}

async function machinePage(root, id, go) {
  replace(root, h("h2", {}, `Machine ${id}`), h("p", {}, "Loading…"));
  let m;
  try {
    m = await api.getMachine(id);
  } catch (err) {
    return replace(root, h("h2", {}, `Machine ${id}`), h("div", { class: "banner error", role: "alert" }, `Could not open the machine: ${err.message}`));
  }
  const sessions = [...(m.sessions || [])].sort((a, b) => String(a.created_at).localeCompare(String(b.created_at)));
  const coefficients = m.coefficients || [];
  const solved = sessions.filter((x) => x.summary).map((x) => x.id);
  // The latest version's warnings; the page is whole without them.
  const latest = coefficients.length ? await api.getCoefficients(id).catch(() => null) : null;
  const units = jobUnits(sessions);
  // The jobs a version was pooled from, by name (a deleted one by its id).
  const jobName = new Map(sessions.map((x) => [x.id, x.name || x.id]));
  const fromJobs = (ids) => `${ids.length}${ids.length ? `: ${ids.map((i) => `“${jobName.get(i) || i}”`).join(", ")}` : ""}`;
  const inUnit = (x, a, b) => `${fmt(a)}, ${fmt(b)}${units.get(x.id) ? ` ${units.get(x.id)}` : ""}`;
  replace(root,
    h("h2", {}, `Machine ${nameOf(m) || m.id}`, nameOf(m) ? h("small", {}, ` · ${m.id}`) : ""),
    m.rotor ? h("p", {}, `Rotor: ${fmt(m.rotor.mass_kg, 0)} kg, service speed ${fmt(m.rotor.service_speed_rpm, 0)} rpm${m.rotor.balance_grade ? `, balance grade ${m.rotor.balance_grade}` : ""}.`) : "",
    h("div", { class: "actions" },
      h("button", { type: "button", class: "primary new-job", onclick: async () => go.newJob(await setupOfLatest(m), null) }, "New job for this machine"),
      h("button", { type: "button", class: "trim-job", disabled: coefficients.length === 0, onclick: async () => go.newJob(await setupOfLatest(m), { machine: m.id }) }, "Trim job from the stored coefficients"),
      h("button", { type: "button", class: "pool", disabled: solved.length === 0, onclick: async () => {
        try {
          await api.poolCoefficients(m.id, solved);
          machinePage(root, id, go);
        } catch (err) {
          banner(root, "error", `The coefficients were not stored: ${err.message}`);
        }
      } }, "Store coefficients from the solved jobs")),
    h("h3", {}, "Jobs over time"),
    trend(sessions, units),
    h("div", { class: "scroll" }, h("table", { class: "sessions machine-jobs" },
      h("thead", {}, h("tr", {}, h("th", {}, "Job"), h("th", {}, "Stored"), h("th", {}, "Runs"), h("th", {}, "Vibration before: RMS, largest"), h("th", {}, "After (predicted): RMS, largest"))),
      h("tbody", {}, sessions.length === 0 ? h("tr", {}, h("td", { colspan: 5 }, "No jobs for this machine yet.")) : sessions.map((x) => h("tr", {},
        h("td", {}, h("button", { type: "button", class: "link open-session", onclick: () => go.openSession(x.id) }, x.name || x.id)),
        h("td", {}, storedAt(x.created_at)), h("td", {}, String(x.runs ?? "")),
        x.summary ? [h("td", { class: "before" }, inUnit(x, x.summary.rms_before, x.summary.max_before)), h("td", { class: "after" }, inUnit(x, x.summary.rms_after, x.summary.max_after))]
          : h("td", { colspan: 2 }, "not solved")))))),
    h("h3", {}, "Coefficient versions"),
    coefficients.length === 0 ? h("p", { class: "hint" }, "None stored yet. Solve a job with trial runs, then store the coefficients from it: later jobs can trim with only a reference run.")
      : h("table", { class: "coeff-versions" },
        h("thead", {}, h("tr", {}, h("th", {}, "Version"), h("th", {}, "Stored"), h("th", {}, "From jobs"))),
        h("tbody", {}, coefficients.map((c) => h("tr", {}, h("td", {}, String(c.version)), h("td", {}, storedAt(c.created_at)), h("td", { class: "from-jobs" }, fromJobs(c.sessions || [])))))),
    poolWarnings(latest, sessions),
  );
}

function newMachineForm(root, go) {
  const m = { id: "", name: "", mass: null, speed: null, grade: "" };
  return h("fieldset", { class: "new-machine" }, h("legend", {}, "New machine"),
    h("label", {}, "Id ", textInput({ field: "machine.id", value: "", required: true, label: "Machine id", placeholder: "e.g. ID-FAN-3", size: 14, maxlength: 64, onValue: (v) => (m.id = v) })),
    h("label", {}, "Name ", textInput({ field: "machine.name", value: "", label: "Machine name", size: 20, onValue: (v) => (m.name = v) })),
    h("label", {}, "Rotor mass, kg ", numberInput({ field: "machine.rotor.mass_kg", kind: "rotor_mass", value: null, required: false, label: "Rotor mass, kg", onValue: (v) => (m.mass = v) })),
    h("label", {}, "Service speed, rpm ", numberInput({ field: "machine.rotor.service_speed_rpm", kind: "speed", value: null, required: false, label: "Service speed, rpm", onValue: (v) => (m.speed = v) })),
    h("label", {}, "Balance grade ", selectInput({ field: "machine.rotor.balance_grade", value: "", choices: GRADE_CHOICES, label: "Balance grade", onValue: (v) => (m.grade = v) })),
    h("button", { type: "button", class: "create-machine", onclick: async () => {
      clearMarks(root);
      if (!m.id) return banner(root, "error", "Give the machine an id (the name on its plate, e.g. ID-FAN-3).");
      // No name typed: none stored (the id is not a name).
      const body = { id: m.id };
      if (m.name) body.name = m.name;
      // All three or none: the service requires the grade with mass and speed.
      const rotor = { mass_kg: m.mass, service_speed_rpm: m.speed, balance_grade: m.grade };
      if (!checkRotor(root, rotor, "machine.")) return banner(root, "error", "Give the rotor's mass, service speed and balance grade, or none of them. Nothing was stored.");
      if (m.mass) body.rotor = rotor;
      try {
        await api.createMachine(body);
        go.showMachine(m.id);
      } catch (err) {
        if (err.status !== 409 && markServerError(err, "machine.")) return banner(root, "error", "Not stored: the field is marked.");
        banner(root, "error", err.status === 409 ? `A machine called ${m.id} exists already.` : `Not stored: ${err.message}`);
      }
    } }, "Store machine"));
}

/** Machines listed at a time. */
const MACHINES_PAGE = 100;

/** The machines page: one machine when `state.machineId` is set, else the list. */
export async function renderMachines(root, go) {
  if (state.machineId) return machinePage(root, state.machineId, go);
  const list = h("tbody", {}, h("tr", {}, h("td", { colspan: 3 }, "Loading…")));
  const more = h("p", { class: "more" });
  replace(root, h("h2", {}, "Machines"), newMachineForm(root, go),
    h("div", { class: "scroll" }, h("table", { class: "sessions machines" },
      h("thead", {}, h("tr", {}, h("th", {}, "Machine"), h("th", {}, "Name"), h("th", {}, "Stored"))), list)),
    more);
  const row = (x) => h("tr", {},
    h("td", {}, h("button", { type: "button", class: "link open-machine", dataset: { id: x.id }, onclick: () => go.showMachine(x.id) }, x.id)),
    h("td", { class: nameOf(x) ? "name" : "name none" }, nameOf(x) || "–"), h("td", {}, storedAt(x.created_at)));
  // A page at a time (newest first), every machine reachable.
  await pagedList({
    root, list, more, row, pageSize: MACHINES_PAGE, columns: 3,
    what: "machines", shownAs: "machines", empty: "No machines yet.",
    fetchPage: async (limit, offset) => {
      const data = await api.listMachines(limit, offset);
      return { found: (data && data.machines) || [], total: data && data.total };
    },
  });
}
