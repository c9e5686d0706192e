// Step 2, the runs: a grid with a row per speed × sensor and an amplitude and a
// phase per run. One run at a time is typed (a new one, or a stored one being
// corrected); Tab walks its cells in reading order. Storing the zero run
// creates the session; each trial run is then appended, a corrected run is PUT.

import { h, replace, $ } from "../page/dom.js";
import { numberInput, textInput, selectInput, validateAll, clearMarks, markServerError, banner, mark, keepFocus } from "../page/fields.js";
import { fmt, fmtReading, unitLabel, DECIMAL_RULE } from "../page/num.js";
import { api, ApiError, unwrapSession } from "../job/api.js";
import { keepNow } from "../job/keep.js";
import { state, rows, readingFor, setupJson, setupOf, runJson, referenceRun, changed, loadSession, triedPlanes, trimWords } from "../job/state.js";
import { csvImportButton, CSV_SHAPES } from "./csv.js";
import { retrialQuestion, ask, suggestionBox } from "./trial.js";
import { trialCount, runKinds } from "./options.js";

/** What the last stored run is: "trial", "check", or undefined for the zero run. */
function lastKind() {
  const last = state.runs[state.runs.length - 1];
  return last && last.stored ? runKinds().get(last.id) : undefined;
}

/** What a run with weights can be (its `purpose`). */
const PURPOSES = [
  ["trial", "a trial run"],
  ["check", "a check run"],
];

function angleWords() {
  return state.setup.conventions.angle_direction === "with_rotation" ? "with rotation" : "against rotation";
}

export function weightsText(weights, num = (x) => fmt(x)) {
  if (weights.length === 0) return "no weights (as found)";
  return weights.map((w) => `${w.plane}: ${num(w.mass_g)} g at ${num(w.angle_deg)}°`).join(", ");
}

/** The last stored run with weights: the one whose weights may still be on the rotor. */
function previousTrial() {
  const trials = state.runs.filter((r) => r.stored && r.weights.length > 0);
  return trials.length ? trials[trials.length - 1] : null;
}

/** A run name not used yet: `base`, then `base 2`, `base 3`, … */
function freeName(base) {
  const taken = new Set(state.runs.map((r) => r.id));
  if (!taken.has(base)) return base;
  for (let n = 2; ; n++) if (!taken.has(`${base} ${n}`)) return `${base} ${n}`;
}

/** "trial n", or the next number free when a run (a check run renamed) has that name. */
function trialName(n) {
  const taken = new Set(state.runs.map((r) => r.id));
  while (taken.has(`trial ${n}`)) n++;
  return `trial ${n}`;
}

/**
 * Start typing a new run: the zero run first, then trial runs (check runs in
 * a trim job, which needs no trials). A check run lists every weight on the
 * rotor (`weights`, relative to the zero run); `fromRun` names the run whose
 * state it was trimmed from. The run is stored with its kind as `purpose`.
 */
export function newDraft(kind = state.setup.trim ? "check" : "trial", weights = null, fromRun = null) {
  const isZero = !referenceRun();
  const trials = trialCount();
  const planes = state.setup.planes;
  const ownWeights = isZero
    ? []
    : weights || [{ plane: planes[Math.min(trials, planes.length - 1)].id, mass_g: null, angle_deg: null }];
  state.draft = {
    index: null,
    id: isZero ? "zero" : kind === "check" ? freeName("check") : trialName(trials + 1),
    zero: isZero,
    check: kind === "check" && !isZero,
    fromRun,
    weights: ownWeights.map((w) => ({ ...w })),
    carry: false,
    rows: rows(),
    cells: rows().map(() => ({ amplitude: null, phase_deg: null })),
  };
}

/** Correct a stored run: its values go back into the inputs; its ETag guards the PUT. */
async function editDraft(index) {
  const run = state.runs[index];
  let etag = null;
  try {
    if (state.id) etag = (await api.getRunTagged(state.id, run.id)).etag;
  } catch (err) {
    etag = null;
  }
  state.draft = {
    index,
    etag,
    id: run.id,
    zero: run.weights.length === 0,
    // Corrected, the run stays what it is (its purpose is stored again).
    check: runKinds().get(run.id) === "check",
    weights: run.weights.map((w) => ({ ...w })),
    carry: false,
    rows: rows(),
    cells: rows().map((row) => {
      const r = readingFor(run, row);
      // Repeated samples stay with a reading whose mean is not retyped.
      return r ? { amplitude: r.amplitude, phase_deg: r.phase_deg, samples: r.samples, mean: [r.amplitude, r.phase_deg] } : { amplitude: null, phase_deg: null };
    }),
  };
}

function draftRun() {
  const d = state.draft;
  const prev = previousTrial();
  const carried = d.carry && prev ? prev.weights : [];
  const run = {
    id: d.id,
    weights: [...carried, ...d.weights].map((w) => ({ plane: w.plane, mass_g: w.mass_g, angle_deg: w.angle_deg })),
    readings: rows().map((row, i) => {
      const c = d.cells[i];
      const reading = { speed_rpm: row.speed, sensor: row.sensor, amplitude: c.amplitude, phase_deg: c.phase_deg };
      if (c.samples && c.mean[0] === c.amplitude && c.mean[1] === c.phase_deg) reading.samples = c.samples;
      return reading;
    }),
  };
  // What the run is, kept with it whatever it is named (the zero run is neither).
  if (!d.zero) run.purpose = d.check ? "check" : "trial";
  return run;
}

/** Position of the draft among the runs, for field paths like `runs[2].readings[5].phase_deg`. */
function draftPosition() {
  return state.draft.index === null ? state.runs.length : state.draft.index;
}

/** The words for a change made elsewhere, and a way to see it without losing the typed run. */
function conflict(root, rerender) {
  banner(root, "error", "This session was changed in another tab or on another computer since this page read it (a run was added or corrected there). Nothing was stored from here, and the run you typed is kept. Load the stored session to see the change, check your run against it, then store it again.");
  const b = $(".banner", root);
  b.append(" ", h("button", { type: "button", class: "reload-session", onclick: () => reloadStored(root, rerender) }, "Load the stored session"));
}

/** Read the stored session again, keeping the run being typed. */
async function reloadStored(root, rerender) {
  const draft = state.draft;
  try {
    const { data, etag } = await api.getSessionTagged(state.id);
    const id = state.id;
    loadSession(data.session && typeof data.session === "object" ? data.session : data, id);
    state.etag = etag;
    state.draft = draft;
    if (draft && draft.index !== null) {
      const at = state.runs.findIndex((r) => r.id === draft.id);
      draft.index = at >= 0 ? at : null;
      draft.etag = null;
    }
    rerender();
    changed();
  } catch (err) {
    banner(root, "error", err.message);
  }
}

/** One spelling of a value, its keys sorted: equal spellings are the same value. */
function spelling(value) {
  if (Array.isArray(value)) return `[${value.map(spelling).join(",")}]`;
  if (value && typeof value === "object") return `{${Object.keys(value).sort().map((k) => `${JSON.stringify(k)}:${spelling(value[k])}`).join(",")}}`;
  return JSON.stringify(value);
}

/** A run as the service keeps it, spelled one way: two runs are the same when these are equal. */
const runKey = (run) => spelling(runJson(run));

/** Whether two lists of runs are the same runs, in the same order. */
function sameRuns(a, b) {
  return a.length === b.length && a.every((r, i) => runKey(r) === runKey(b[i]));
}

/**
 * Whether the run sent by a Store whose answer was lost (`sent`) is stored
 * as sent, and nothing else changed since this page read the session: the
 * service took the write, then the answer (or the read after it) was lost.
 */
function sentRunLanded(storedRuns, sent) {
  const others = (runs) => runs.filter((r) => r.id !== sent.id);
  const known = state.runs.filter((r) => r.stored);
  return storedRuns.some((r) => runKey(r) === runKey(sent)) && sameRuns(others(storedRuns), others(known));
}

/**
 * The session a create whose answer was lost stored, or null: among the
 * newest sessions, one with this job's name and set-up and the sent zero run
 * alone. Store again would otherwise store the job twice.
 */
async function createdBefore(sent) {
  const data = await api.listSessions(50, 0);
  const listed = (data && data.sessions) || [];
  const setup = spelling(setupJson());
  for (const x of listed.filter((x) => x.name === state.setup.name && x.runs === 1)) {
    const session = unwrapSession(await api.getSession(x.id));
    const runs = session.runs || [];
    if (runs.length === 1 && runKey(runs[0]) === runKey(sent) && spelling(setupJson(setupOf(session))) === setup) return x.id;
  }
  return null;
}

/** The run is stored: the draft goes, and the page goes on to what comes next. */
function stored(root, words) {
  state.draft = null;
  state.solution = null;
  changed();
  if (words) banner(root, "ok", words);
  // On to what comes next: another trial while a plane is untried, else Solve.
  ($("button.go-solve:not(:disabled)", root) || $("button.add-trial", root))?.focus();
}

async function store(root, rerender) {
  const d = state.draft;
  clearMarks(root);
  banner(root, "error", "");
  if (!validateAll(root)) return banner(root, "error", "Some cells need attention; they are marked in red. Nothing was sent.");
  const run = draftRun();
  const k = draftPosition();
  if (!d.zero && run.weights.length === 0) return banner(root, "error", "A trial run needs at least one weight. Add the trial weight, or tick that the earlier trial weights are still on.");
  // The run a Store whose answer was lost sent may be stored under this name
  // (the page reloaded since): that is this run, looked at below, not a clash.
  const mine = (r) => d.sent && state.id !== null && runKey(r) === runKey(d.sent);
  if (state.runs.some((r, i) => r.id === run.id && i !== d.index && !mine(r))) {
    return mark($(`[data-field="runs[${k}].id"]`, root), "another run already has this name");
  }
  const question = retrialQuestion(run, d);
  if (question) {
    return ask(root, question, () => { d.confirmedRetrial = true; store(root, rerender); }, () => $(`[data-field="runs[${k}].weights[0].plane"]`, root)?.focus());
  }
  // Whether the service has taken the run: a failure after it (reading the
  // session's tag back) did not leave the run unstored.
  let written = false;
  try {
    const before = state.id === null && d.sent ? await createdBefore(d.sent) : null;
    if (before !== null) {
      // The last Store created the job and only its answer was lost.
      state.id = before;
      history.replaceState({ step: "runs" }, "", `#session=${encodeURIComponent(before)}&step=runs`);
      state.runs = [{ ...d.sent, stored: true }];
      if (runKey(run) === runKey(d.sent)) {
        state.etag = (await api.getSessionTagged(state.id)).etag;
        return stored(root, `The job is stored with its zero run “${run.id}”: the service took it when Store was pressed before, and only its answer was lost. It is stored once.`);
      }
      // Changed since it was sent: what was typed since corrects it.
      d.index = 0;
      d.etag = null;
      d.sent = null;
    }
    if (state.id === null) {
      const session = { ...setupJson(), runs: [run] };
      d.sent = runJson(run);
      const created = await api.createSession(session);
      written = true;
      state.id = created.id;
      history.replaceState({ step: "runs" }, "", `#session=${encodeURIComponent(created.id)}&step=runs`);
      state.runs = [{ ...runJson(run), stored: true }];
    } else {
      // Two tabs on one session: anything stored elsewhere since this page read it stops the write.
      const now = await api.getSessionTagged(state.id);
      const storedRuns = (unwrapSession(now.data) || {}).runs || [];
      if (d.sent && sentRunLanded(storedRuns, d.sent)) {
        // The last Store reached the service and only its answer was lost:
        // the run is there as sent, stored once. It is not another tab's.
        state.runs = storedRuns.map((r) => ({ ...runJson(r), stored: true }));
        state.etag = now.etag;
        if (runKey(run) === runKey(d.sent)) {
          return stored(root, `The run “${run.id}” is stored: the service took it when Store was pressed before, and only its answer was lost. It is stored once.`);
        }
        // Changed since it was sent: what was typed since corrects it.
        d.index = state.runs.findIndex((r) => r.id === d.sent.id);
        d.etag = null;
        d.sent = null;
      } else if (now.etag !== state.etag) {
        // A tag this page missed (its read after a store was lost) is no
        // change made elsewhere when the stored runs are the ones it knows.
        if (!sameRuns(storedRuns, state.runs.filter((r) => r.stored))) return conflict(root, rerender);
        state.etag = now.etag;
      }
      d.sent = runJson(run);
      if (d.index === null) {
        await api.addRun(state.id, run);
        written = true;
        state.runs.push({ ...runJson(run), stored: true });
      } else {
        await api.putRunIfMatch(state.id, state.runs[d.index].id, run, d.etag);
        written = true;
        state.runs[d.index] = { ...runJson(run), stored: true };
      }
    }
    state.etag = (await api.getSessionTagged(state.id)).etag;
  } catch (err) {
    if (written) {
      // The run is stored; only the session's tag was not read back (the
      // next Store reads it, and sees that nothing else changed).
      return stored(root, `The run “${run.id}” was stored. The service stopped answering just after; start it again (the command fieldbal serve) before the next run if it is away.`);
    }
    const uncertain = !!d.sent;
    if (!(err instanceof ApiError && err.code === "network")) d.sent = null;
    if (err instanceof ApiError && err.status === 412) return conflict(root, rerender);
    // Say what became of the run, not only that the service is away.
    if (err instanceof ApiError && err.code === "network") {
      keepNow();
      const away = "The fieldbal service does not answer, so ";
      const kept = "What you typed is kept in this browser: start the service (the command fieldbal serve), then press Store again";
      const lost = "the service may have taken it before its answer was lost";
      if (!uncertain) return banner(root, "error", `${away}the run was not stored. ${kept}.`);
      if (state.id === null) {
        return banner(root, "error", `${away}this page cannot tell whether the job was stored with its zero run: ${lost}. ${kept}; the form looks for the job among the stored sessions first, and stores it only if it is not there.`);
      }
      return banner(root, "error", `${away}this page cannot tell whether the run was stored: ${lost}. ${kept}; the form looks at what is stored first, and stores the run only if it is not there.`);
    }
    const prefix = state.id === null ? "" : `runs[${k}].`;
    if (!markServerError(err, prefix)) banner(root, "error", err.message);
    else banner(root, "error", "The service did not accept the run; the field is marked.");
    return;
  }
  stored(root, "");
}

/**
 * The run being typed's first empty field, in the order Tab walks them: the
 * weights, then the cells (the run name is filled in already); null when
 * every one is filled.
 */
export function firstEmptyField(root) {
  return [...root.querySelectorAll(".draft .weights input.num, td.cell input")].find((e) => !e.disabled && e.value.trim() === "") || null;
}

function weightsEditor(d, k, rerender) {
  const planes = state.setup.planes.map((p) => [p.id, p.id]);
  const prev = previousTrial();
  return h(
    "div",
    { class: "weights" },
    h("h4", {}, `Weights on the rotor for this run (angles ${angleWords()})`),
    // A check run lists every weight on the rotor (the trial weights are
    // off): "still on" asked whether to add the last trial's weights to it.
    prev && d.index === null && !d.check
      ? h("label", { class: "carry" },
          h("input", { type: "checkbox", class: "carry-tick", checked: d.carry, onchange: (e) => { d.carry = e.target.checked; rerender(); } }),
          ` Weights of “${prev.id}” are still on the rotor`,
          d.carry ? h("span", { class: "carried" }, ` — carried: ${weightsText(prev.weights)}`) : "")
      : "",
    h("table", { class: "edit" },
      h("thead", {}, h("tr", {}, h("th", {}, "Plane"), h("th", {}, "Mass, g"), h("th", {}, "Angle, °"), h("th", {}))),
      h("tbody", {}, d.weights.map((w, j) => h("tr", {},
        h("td", {}, selectInput({ field: `runs[${k}].weights[${j}].plane`, value: w.plane, choices: planes, label: `Weight ${j + 1} plane`, onValue: (v) => (w.plane = v) })),
        h("td", {}, numberInput({ field: `runs[${k}].weights[${j}].mass_g`, kind: "mass", value: w.mass_g, label: `Weight ${j + 1} mass, g`, onValue: (v) => (w.mass_g = v) })),
        h("td", {}, numberInput({ field: `runs[${k}].weights[${j}].angle_deg`, kind: "angle", value: w.angle_deg, label: `Weight ${j + 1} angle, degrees`, onValue: (v) => (w.angle_deg = v) })),
        h("td", {}, h("button", { type: "button", class: "small remove-weight", onclick: () => { d.weights.splice(j, 1); rerender(); } }, "Remove")),
      ))),
    ),
    h("button", { type: "button", class: "small add-weight", onclick: () => { d.weights.push({ plane: state.setup.planes[0].id, mass_g: null, angle_deg: null }); rerender(); } }, "+ Add weight"),
  );
}

function grid(rerender) {
  const d = state.draft;
  const k = d ? draftPosition() : -1;
  const columns = state.runs.map((run, i) => ({ run, i, editing: d && d.index === i }));
  if (d && d.index === null) columns.push({ run: null, i: k, editing: true });
  const phaseWords = state.setup.conventions.phase === "lead" ? "(lead)" : "(lag)";
  const sensorsById = new Map(state.setup.sensors.map((x) => [x.id, x]));
  const kinds = runKinds();
  return h("div", { class: "scroll grid-wrap" }, h("table", { class: "grid" },
    // The runs' weights in the headers ("inboard: 30.0 g at 0.0°") and the
    // phases below: their conventions said once, above them.
    h("caption", { class: "grid-caption" }, `Weight angles ${angleWords()} from the mark; phases ${state.setup.conventions.phase === "lead" ? "lead" : "lag"}.`),
    h("thead", {},
      h("tr", {}, h("th", { rowspan: 2 }, "Speed, rpm"), h("th", { rowspan: 2 }, "Sensor"),
        columns.map((c) => h("th", { colspan: 2, class: c.editing ? "run editing" : "run", dataset: { run: c.editing ? d.id || "" : c.run.id } },
          h("div", { class: "run-name" }, c.editing ? d.id || "(new run)" : c.run.id),
          h("div", { class: "run-weights" }, c.editing ? (d.zero ? "no weights (as found)" : "being typed") : weightsText(c.run.weights)),
          !c.editing && c.run.weights.length ? h("div", { class: "run-kind" }, kinds.get(c.run.id) === "check" ? "check run" : "trial run") : "",
          !d && c.run && c.run.stored ? h("button", { type: "button", class: "small correct", onclick: async () => { await editDraft(c.i); rerender(); } }, "Correct") : ""))),
      h("tr", {}, columns.map(() => [h("th", { class: "sub" }, "Amplitude"), h("th", { class: "sub" }, `Phase, ° ${phaseWords}`)]))),
    h("tbody", {}, rows().map((row, r) => h("tr", {},
      h("th", { class: "speed" }, fmt(row.speed, 0)),
      h("th", { class: "sensor" }, row.sensor, h("small", {}, unitLabel((sensorsById.get(row.sensor) || {}).unit))),
      columns.map((c) => {
        if (c.editing) {
          const cell = d.cells[r];
          return [
            h("td", { class: "cell" }, numberInput({ field: `runs[${k}].readings[${r}].amplitude`, kind: "amplitude", value: cell.amplitude, label: `${row.sensor} at ${row.speed} rpm, amplitude`, onValue: (v) => (cell.amplitude = v) }),
              cell.samples && cell.samples.length ? h("small", { class: "samples" }, `mean of ${cell.samples.length}: a new value replaces them`) : ""),
            h("td", { class: "cell" }, numberInput({ field: `runs[${k}].readings[${r}].phase_deg`, kind: "phase", value: cell.phase_deg, label: `${row.sensor} at ${row.speed} rpm, phase`, onValue: (v) => (cell.phase_deg = v) })),
          ];
        }
        const reading = readingFor(c.run, row);
        // As typed (fmtReading: the stored number, up to six significant digits), not
        // rounded to four: the technician compares them with the analyser.
        // A mean of repeated samples says so: the 95 % figures take their scatter from them.
        const n = reading && Array.isArray(reading.samples) ? reading.samples.length : 0;
        return [h("td", { class: "value amp" }, reading ? fmtReading(reading.amplitude) : "–", n ? h("small", { class: "samples" }, `mean of ${n}`) : ""), h("td", { class: "value phase" }, reading ? fmtReading(reading.phase_deg) : "–")];
      }),
    ))),
  ));
}

/**
 * A block copied from a spreadsheet or an analyser's table (cells split by
 * tabs, rows by line breaks) pasted into a cell of the run being typed: its
 * values go into that cell and the ones after it in Tab order (amplitude,
 * phase, the next row's amplitude, …), each checked as if typed.
 */
function pasteAcross(e, root) {
  const cell = e.target;
  if (!cell.matches || !cell.matches("td.cell input")) return;
  const text = e.clipboardData ? e.clipboardData.getData("text/plain") : "";
  if (!/[\t\n]/.test(text.replace(/\s+$/, ""))) return;
  e.preventDefault();
  const values = text.replace(/\s+$/, "").split(/\r?\n/).flatMap((line) => line.split("\t")).map((v) => v.trim());
  const cells = [...cell.closest("tbody").querySelectorAll("td.cell input")];
  const from = cells.indexOf(cell);
  const room = cells.length - from;
  values.slice(0, room).forEach((v, i) => {
    const input = cells[from + i];
    input.value = v;
    input.dispatchEvent(new Event("input", { bubbles: true }));
  });
  cells[from + Math.min(values.length, room) - 1].focus();
  // More values than cells left: said above the run (a mark on a cell would
  // move the layout under the pointer at its blur).
  const extra = values.length - room;
  banner(root, "error", extra > 0 ? `${values.length} values were pasted and ${room} cell${room === 1 ? "" : "s"} of this run were left from the one pasted into: ${extra === 1 ? "the last value" : `the last ${extra}`} (${values.slice(room).join(", ")}) ${extra === 1 ? "was" : "were"} not used. Check that the block was copied from the right place.` : "");
}

const rowKey = (row) => `${row.speed}|${row.sensor}`;

/** Keep typed cells with their speed and sensor when the set-up changed the rows. */
function reshapeDraft(d) {
  const now = rows();
  const before = d.rows || now;
  if (before.map(rowKey).join("\n") === now.map(rowKey).join("\n") && d.cells.length === now.length) return;
  const old = new Map(before.map((row, i) => [rowKey(row), d.cells[i]]));
  d.cells = now.map((row) => old.get(rowKey(row)) || { amplitude: null, phase_deg: null });
  d.rows = now;
}

/** Render the runs step into `root`; `solve` goes on to step 3. */
export function renderRuns(root, solve) {
  const typing = keepFocus(root);
  if (state.draft === undefined || (state.draft === null && !referenceRun())) newDraft();
  if (state.draft) reshapeDraft(state.draft);
  const rerender = () => renderRuns(root, solve);
  const d = state.draft;
  // Planes tried, not runs with weights: check runs carry weights too.
  const tried = state.setup.planes.filter((p) => triedPlanes().has(p.id)).length;
  const planes = state.setup.planes.length;
  const k = d ? draftPosition() : -1;
  replace(
    root,
    h("h2", {}, "2 · Runs"),
    h("p", { class: "lead" }, d && d.zero && d.index === null
      ? "Zero run: the rotor as found, with no weights. Type the analyser's 1X amplitude and phase for every sensor; Tab moves to the next cell, Enter stores the run."
      : d && d.check
        ? state.setup.trim
          // A trim job had no trial weights, and its check runs test the
          // coefficients it is solved with rather than sharpen them.
          ? `Check run: with the corrections fitted (the weights below), run the machine and type the readings. They also show whether ${trimWords()} still hold for this rotor.`
          : "Check run: with every trial weight off and the corrections fitted (the weights below), run the machine and type the readings. They also sharpen the influence coefficients for a trim solve."
        : !d && lastKind() === "check"
          ? `Check run “${state.runs[state.runs.length - 1].id}” stored: solve again, and the answer says what remains and what to add to the rotor as it is in this run.${state.setup.trim ? "" : ` Every plane has had its trial weight (${tried} of ${planes}).`}`
        : state.setup.trim && referenceRun()
          ? `Trim job from ${trimWords()}: no trial runs are needed. Solve now.`
          : tried < planes
            ? `Trial runs: one per plane at least (${tried} of ${planes} plane${planes === 1 ? "" : "s"} tried). List every weight that is on the rotor during the run.`
            : `Every plane has had its trial weight (${tried} of ${planes}). Solve, or add a run: list every weight that is on the rotor during it.`),
    d ? h("div", { class: "draft", onkeydown: (e) => {
      // Enter in the run name or a weight goes on to the first field still
      // empty (the readings), or stores the run when all are typed.
      if (e.key !== "Enter" || !e.target.matches("input[type=text]")) return;
      e.preventDefault();
      const next = firstEmptyField(root);
      if (next) next.focus();
      else store(root, rerender);
    } },
      h("div", { class: "run-head" }, h("label", { class: "run-id" }, h("span", {}, "Run name"), textInput({ field: `runs[${k}].id`, value: d.id, required: true, label: "Run name", size: 18, maxlength: 64, onValue: (v) => { d.id = v; const head = $("th.run.editing .run-name", root); if (head) head.textContent = v || "(new run)"; } })),
      // What the run is, stored with it: the name may be anything.
      d.zero ? "" : h("label", { class: "run-purpose" }, h("span", {}, "This run is"), selectInput({ field: `runs[${k}].purpose`, value: d.check ? "check" : "trial", choices: PURPOSES, label: "This run is", onValue: (v) => { d.check = v === "check"; if (d.check) d.carry = false; rerender(); } }))),
      d.zero ? "" : [suggestionBox(d, k, rerender), weightsEditor(d, k, rerender)]) : "",
    d ? h("p", { class: "hint decimal-rule" }, DECIMAL_RULE, " ", csvImportButton(root, rerender)) : "",
    d ? h("p", { class: "hint csv-shapes" }, CSV_SHAPES) : "",
    h("div", { onpaste: (e) => pasteAcross(e, root), onkeydown: (e) => { if (e.key === "Enter" && d && e.target.matches("input")) { e.preventDefault(); store(root, rerender); } } }, grid(rerender)),
    h("div", { class: "actions sticky" },
      d ? [
        h("button", { type: "button", class: "primary store", onclick: () => store(root, rerender) },
          d.index !== null ? "Store the corrected run" : d.zero ? "Store zero run" : "Store run"),
        state.runs.some((r) => r.stored) ? h("button", { type: "button", class: "cancel", onclick: () => { state.draft = null; rerender(); } }, "Cancel") : "",
      ] : [
        h("button", { type: "button", class: "add-trial", onclick: () => { newDraft(); rerender(); $(`[data-field="runs[${state.runs.length}].weights[0].mass_g"]`, root)?.focus(); } }, state.setup.trim ? "+ Add a run" : "+ Add trial run"),
        h("button", { type: "button", class: "primary go-solve", disabled: tried < planes && !state.setup.trim, onclick: solve }, "Solve →"),
      ],
    ),
  );
  typing();
}

