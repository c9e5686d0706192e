// The form's entry point: the steps of a balancing job, which one is shown,
// and reopening a stored session from the address (`#session=ID`).

import { $, $$, replace, h } from "./dom.js";
import { api, unwrapSession } from "./api.js";
import { state, onChange, resetJob, loadSession } from "./state.js";
import { renderSetup } from "./setup.js";
import { renderRuns, newDraft } from "./runs.js";
import { renderSolve } from "./solve.js";
import { renderReport } from "./report.js";
import { renderSessions } from "./sessions.js";

const STEPS = ["setup", "runs", "solve", "report", "sessions"];
let current = "setup";

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

/** Show `step`, drawn afresh from the job's state. */
function show(step) {
  reveal(step);
  const root = $(`#step-${step}`);
  if (step === "setup") renderSetup(root, () => show("runs"));
  if (step === "runs") {
    if (setupReady()) renderRuns(root, () => show("solve"));
    else replace(root, h("h2", {}, "2 · Runs"), h("p", { class: "note" }, "Finish the set-up first: a name, the speeds, and a name for every plane and sensor."), h("button", { type: "button", class: "primary", onclick: () => show("setup") }, "← Back to the set-up"));
  }
  if (step === "solve") renderSolve(root, () => { newDraft("check", state.solution.corrections.map((c) => ({ plane: c.plane, mass_g: Number(c.mass_g.toFixed(1)), angle_deg: Number(c.angle_deg.toFixed(1)) }))); show("runs"); });
  if (step === "sessions") renderSessions(root, open, open);
  // The report is kept current so that printing from any step prints it.
  renderReport($("#step-report"));
  updateHeader();
  window.scrollTo(0, 0);
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

async function open(id) {
  resetJob();
  if (id === null) {
    history.replaceState(null, "", location.pathname);
    return show("setup");
  }
  try {
    const data = await api.getSession(id);
    loadSession(unwrapSession(data), data.id ?? id);
    await loadLastSolution();
    history.replaceState(null, "", `#session=${encodeURIComponent(state.id)}`);
    show("runs");
  } catch (err) {
    history.replaceState(null, "", location.pathname);
    show("sessions");
    const root = $("#step-sessions");
    root.prepend(h("div", { class: "banner error", role: "alert" }, `Could not open the session: ${err.message}`));
  }
}

/**
 * Show the last stored solution again, if it was computed from the runs the
 * session has now (a run corrected since then gives a new version; the stored
 * solution names run ids and versions, so a changed run set is caught here and
 * a re-solve is one click).
 */
async function loadLastSolution() {
  try {
    const stored = await api.solutions(state.id);
    const last = Array.isArray(stored) && stored.length ? stored[stored.length - 1] : null;
    if (!last || !last.solution) return;
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
});

document.addEventListener("fieldbal:reveal", (e) => reveal(e.detail));

for (const tab of $$("nav [data-step]")) tab.addEventListener("click", () => show(tab.dataset.step));

const match = /^#session=(.+)$/.exec(location.hash);
if (match) open(decodeURIComponent(match[1]));
else show("setup");
