// The form's entry point: the steps of a balancing job, which one is shown,
// the browser's Back/Forward between them (each step is a history entry:
// `#session=ID&step=runs`, `#step=setup`, `#machine=ID`), reopening a stored
// session from the address, and work kept across a reload (keep.js).
// Beside it: page/ (elements, self-checking inputs, numbers), job/ (state,
// storage, API, token), steps/ (a module per step or page, and their parts),
// answer/ (a solve's answer in words and pictures), plots/.

import { $, $$, replace, h } from "./page/dom.js";
import { api, unwrapSession } from "./job/api.js";
import { state, onChange, resetJob, loadSession } from "./job/state.js";
import { keep, keepNow, kept, forget } from "./job/keep.js";
import { renderSetup } from "./steps/setup.js";
import { renderRuns, newDraft, firstEmptyField } from "./steps/runs.js";
import { renderSolve } from "./steps/solve.js";
import { renderReport } from "./steps/report.js";
import { renderSessions } from "./steps/sessions.js";
import { renderMachines } from "./steps/machines.js";
import { renderDecay } from "./steps/decay.js";
import { renderResidual } from "./steps/residual.js";

const STEPS = ["setup", "runs", "solve", "report", "sessions", "machines", "decay", "residual"];
let current = "setup";

/** The address of a step of the job shown now. */
function hashFor(step) {
  if (step === "machines" && state.machineId) return `#machine=${encodeURIComponent(state.machineId)}`;
  if (state.id) return `#session=${encodeURIComponent(state.id)}&step=${step}`;
  return `#step=${step}`;
}

/** `{session, step, machine}` read from an address. */
function parseHash(hash) {
  const out = {};
  for (const part of hash.replace(/^#/, "").split("&")) {
    const [k, v] = part.split("=");
    if (k && v !== undefined) out[k] = decodeURIComponent(v);
  }
  return out;
}

/** Make `step` the visible one, keeping what it shows (and any marks in it). */
function reveal(step) {
  current = step;
  for (const name of STEPS) {
    $(`#step-${name}`).hidden = name !== step;
    const tab = $(`nav [data-step="${name}"]`);
    tab.classList.toggle("current", name === step);
    tab.setAttribute("aria-current", name === step ? "step" : "false");
  }
}

/** Show `step`, drawn afresh from the job's state; a new history entry unless `push` is false. */
function show(step, push = true) {
  if (!STEPS.includes(step)) step = "setup";
  reveal(step);
  const root = $(`#step-${step}`);
  if (step === "setup") renderSetup(root, () => show("runs"));
  if (step === "runs") {
    if (setupReady()) renderRuns(root, () => show("solve"));
    else replace(root, h("h2", {}, "2 · Runs"), h("p", { class: "note" }, "Finish the set-up first: a name, the speeds, and a name for every plane and sensor."), h("button", { type: "button", class: "primary", onclick: () => show("setup") }, "← Back to the set-up"));
  }
  if (step === "solve") renderSolve(root, (weights, fromRun) => { newDraft("check", weights, fromRun); show("runs"); });
  if (step === "sessions") renderSessions(root, (id) => mayLeave(id) && open(id), open);
  if (step === "decay") renderDecay(root);
  if (step === "residual") renderResidual(root);
  if (step === "machines") renderMachines(root, { openSession: (id) => mayLeave(id) && open(id), newJob: (setup, from) => mayLeave(null) && startJob(setup, from), showMachine });
  // The report is kept current so that printing from any step prints it.
  renderReport($("#step-report"));
  updateHeader();
  const hash = hashFor(step);
  if (push && location.hash !== hash) history.pushState({ step }, "", hash);
  else history.replaceState({ step }, "", hash);
  keepNow(step);
  window.scrollTo(0, 0);
  if (push) focusStep(step);
}

/**
 * Put the focus in the step just shown, where the technician goes on: the
 * first field still empty of the run being typed (the zero run's first cell,
 * a check run's first cell), a new job's name, else the step's heading.
 */
function focusStep(step) {
  const root = $(`#step-${step}`);
  if (root.contains(document.activeElement)) return;
  const name = $('[data-field="name"]:not(:disabled)', root);
  const target = step === "runs" ? firstEmptyField(root) : step === "setup" && name && name.value === "" ? name : null;
  if (target) return target.focus();
  const heading = $("h2", root);
  if (!heading) return;
  heading.tabIndex = -1;
  heading.focus({ preventScroll: true });
}

function showMachine(id) {
  state.machineId = id;
  show("machines");
}

/**
 * Whether the job shown may be left for another (`id`, or a new job for
 * null). A run typed and not stored, or a new job's set-up, lives only in this
 * page and its one local-storage slot: ask before dropping it.
 */
function mayLeave(id) {
  if (id !== null && id === state.id) return true;
  const d = state.draft;
  const typed = d && Array.isArray(d.cells) && d.cells.some((c) => c.amplitude !== null || c.phase_deg !== null);
  const unsaved = typed ? `The run “${d.id}” is typed but not stored.`
    : state.id === null && state.setup.name ? `The set-up of “${state.setup.name}” is not stored yet (it is stored with the zero run).` : "";
  if (!unsaved) return true;
  return window.confirm(`${unsaved} Leave it and open the other job? Cancel to go back to it.`);
}

/** Start a new job from a set-up (a machine's last one), optionally trimming from its stored coefficients. */
function startJob(setup, coefficientsFrom) {
  forget();
  resetJob();
  state.setup = setup;
  state.setup.trim = coefficientsFrom ? { coefficients_from: coefficientsFrom } : null;
  show("setup");
}

/** The grid needs speeds, planes and sensors with names; set-up's Next checks the rest. */
function setupReady() {
  const s = state.setup;
  return state.id !== null || (s.name !== "" && s.speeds.length > 0 && s.planes.every((p) => p.id) && s.sensors.every((x) => x.id));
}

function updateHeader() {
  replace($("#job-title"), state.setup.name ? state.setup.name : "New balancing job", state.id ? h("small", {}, " · stored") : "");
  $('nav [data-step="solve"]').disabled = state.id === null;
}

/** Open a stored session (or a new job with `null`) at `step`. */
async function open(id, step = "runs", push = true) {
  if (id === null) {
    forget();
    resetJob();
    return show("setup", push);
  }
  const saved = kept();
  resetJob();
  try {
    const { data, etag } = await api.getSessionTagged(id);
    loadSession(unwrapSession(data), data.id ?? id);
    state.etag = etag;
    // A run half-typed in this session before a reload comes back.
    if (saved && saved.id === state.id) {
      if (saved.draft) state.draft = saved.draft;
      if (saved.options) Object.assign(state.options, saved.options);
      if (saved.report) state.report = saved.report;
    }
    await loadLastSolution();
    show(step, push);
  } catch (err) {
    show("sessions", push);
    const root = $("#step-sessions");
    root.prepend(h("div", { class: "banner error", role: "alert" }, `Could not open the session: ${err.message}`));
  }
}

/** Show the last stored solution again if it was computed from the runs the session has now. */
async function loadLastSolution() {
  try {
    // The list is paged, oldest first: the last of the last page.
    let last = null;
    for (let offset = 0; ; offset += 100) {
      const page = await api.solutions(state.id, 100, offset);
      if (!Array.isArray(page) || !page.length) break;
      last = page[page.length - 1];
      if (page.length < 100) break;
    }
    if (!last || !last.solution) return;
    // A trim job stored before sessions recorded their `trim` is known by
    // the options of its last solve: stored (`coefficients_from`) or
    // supplied (`influence_coefficients`) coefficients, to solve with again.
    const o = last.options || {};
    const from = o.coefficients_from || last.solution.coefficients_from;
    if (!state.setup.trim && from && from.machine) state.setup.trim = { coefficients_from: { machine: from.machine } };
    else if (!state.setup.trim && Array.isArray(o.influence_coefficients) && o.influence_coefficients.length) state.setup.trim = { influence_coefficients: o.influence_coefficients };
    const used = (last.runs || []).map((r) => r.run_id).sort().join("\n");
    const now = state.runs.map((r) => r.id).sort().join("\n");
    if (used === now) {
      state.solution = last.solution;
      state.solutionDate = last.created_at || null;
    }
  } catch (err) {
    // No stored solution to show: the technician solves again.
  }
}

onChange(() => {
  renderReport($("#step-report"));
  updateHeader();
  if (current === "runs") renderRuns($("#step-runs"), () => show("solve"));
  keep(current);
});

document.addEventListener("fieldbal:reveal", (e) => reveal(e.detail));
document.addEventListener("fieldbal:show", (e) => show(e.detail));

for (const tab of $$("nav [data-step]")) {
  tab.addEventListener("click", () => {
    if (tab.dataset.step === "machines") state.machineId = null;
    show(tab.dataset.step);
  });
}

/** Back and Forward move between the steps (and the sessions and machines pages). */
window.addEventListener("popstate", () => {
  const at = parseHash(location.hash);
  if (at.machine) {
    state.machineId = at.machine;
    return show("machines", false);
  }
  if (at.session && at.session !== state.id) return open(at.session, at.step || "runs", false);
  show(at.step || "setup", false);
});

function start() {
  const at = parseHash(location.hash);
  if (at.session) return open(at.session, at.step || "runs", false);
  if (at.machine) {
    state.machineId = at.machine;
    return show("machines", false);
  }
  const saved = kept();
  if (saved && saved.id === null && saved.setup) {
    state.setup = saved.setup;
    state.draft = saved.draft || null;
    if (saved.options) Object.assign(state.options, saved.options);
    if (saved.report) state.report = saved.report;
    // Back to the job's own step; the sessions and machines pages are not work to come back to.
    const step = at.step || (["runs", "solve", "report"].includes(saved.step) ? saved.step : "setup");
    return show(step, false);
  }
  show(at.step || "setup", false);
}

start();
