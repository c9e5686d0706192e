// Free decay: natural frequency and damping from a record of a free decay (a
// tap test), by `POST /api/v1/identify/free-decay` (method §7), the samples
// pasted as a column or a row; the service says what it could not tell.

import { h, replace, $ } from "../page/dom.js";
import { numberInput, selectInput, mark, clearMarks, banner, sendAndShow, keptForm } from "../page/fields.js";
import { parseNumber, sig, isHeading } from "../page/num.js";
import { api } from "../job/api.js";
import { keptPage } from "../job/keep.js";

const LAWS = [
  ["viscous", "Viscous — damping force ∝ velocity: the amplitude decays exponentially (oil film, material)"],
  ["turbulent", "Turbulent — damping force ∝ velocity²: the amplitude decays as 1/(1 + λt) (air, fluid drag)"],
];

const EMPTY = { samples: "", dt_s: null, damping: "viscous", offset: null, answer: null, stale: false };

// What was typed and its answer, kept across steps and reloads until "Start over".
const typed = keptPage("decay", EMPTY);
if (!LAWS.some(([v]) => v === typed.damping)) typed.damping = EMPTY.damping;

/**
 * The samples of pasted text, or `{ error }` naming the first bad one. A
 * column (one a line) or a row separated by tabs, spaces or ";" takes a
 * decimal comma as the runs grid does (2,5); text with no such separators,
 * or with ", " between numbers, is split at its commas. A heading is passed
 * over; a table of columns (a time column beside the samples) is refused.
 */
export function parseSamples(text) {
  const t = String(text || "").trim();
  if (t === "") return { error: "paste the samples, one a line or separated by commas, spaces or tabs" };
  const lines = t.split(/\r?\n/).map((l, k) => ({ k: k + 1, text: l.trim() })).filter((l) => l.text !== "");
  if (lines.length > 1 && isHeading(lines[0].text)) lines.shift();
  const body = lines.map((l) => l.text).join("\n");
  const commaSeparated = !/[\s;]/.test(body) || /,\s/.test(body);
  const split = (line) => line.split(commaSeparated ? /[\s,;]+/ : /[\s;]+/).filter((x) => x !== "");
  // 2 to 4 on every line; a row wrapped over lines is read in order.
  const widths = new Set(lines.map((l) => split(l.text).length));
  const n = lines.length > 1 && widths.size === 1 ? [...widths][0] : 1;
  if (n >= 2 && n <= 4) {
    return { error: `${n} columns pasted (line ${lines[0].k}: ${lines[0].text}): paste the samples' column alone (no time column: its step is dt_s)` };
  }
  const tokens = lines.flatMap((l) => split(l.text));
  if (!tokens.length) return { error: "paste the samples, one a line or separated by commas, spaces or tabs" };
  const values = [];
  for (const [k, token] of tokens.entries()) {
    const r = parseNumber(token);
    if (r.error) return { error: `sample ${k + 1} (${token}): ${r.error}` };
    values.push(r.value);
  }
  return { values };
}

// Never in exponent form ("5.9e-8"): to `k` decimals; a size under the last reads "< 0.001".
const fixed = (x, k) => (Number(x.toFixed(k)) || 0).toFixed(k);
const size = (x, k) => (x < 10 ** -k ? `< ${(10 ** -k).toFixed(k)}` : fixed(x, k));

/** `x ± r`, both to `r`'s second significant digit, at most `most` decimals. */
function withResolution(x, r, unit = "", most = 3) {
  const u = unit ? ` ${unit}` : "";
  if (!Number.isFinite(r)) return `${sig(x, 5)}${u}`;
  const k = Math.min(most, Math.max(0, 1 - Math.floor(Math.log10(r))));
  return `${fixed(x, k)}${u} ± ${size(r, k)}${u}`;
}

function answerTable(a) {
  const undamped = a.undamped_frequency_hz ?? a.frequency_hz;
  const rows = [
    ["undamped-hz", "Undamped natural frequency", withResolution(undamped, a.frequency_resolution_hz, "Hz")],
    ["undamped-rpm", "… in rpm (× 60)", withResolution(undamped * 60, a.frequency_resolution_hz * 60, "rpm", 1)],
    ["damped-hz", "Damped frequency (what a spectrum shows)", `${sig(a.damped_frequency_hz, 5)} Hz`],
    ["damped-rpm", "… in rpm (× 60)", `${sig(a.damped_frequency_hz * 60, 5)} rpm`],
  ];
  if (Number.isFinite(a.damping_ratio)) {
    const zeta = a.damping_ratio_bound === "upper"
      ? `≤ ${sig(a.damping_ratio, 3)} (not resolved from zero)`
      : withResolution(a.damping_ratio, a.damping_ratio_resolution, "", 4);
    rows.push(["zeta", "Damping ratio ζ", zeta]);
  } else {
    rows.push(["decrement", "Initial decrement δ₀ (turbulent: no single ζ)", fixed(a.decrement, 4)]);
  }
  rows.push(["offset", "Offset (samples' unit)", fixed(a.offset, 4)]);
  rows.push(["fit-rms", "Fit RMS (samples' unit)", size(a.fit_rms, 4)]);
  return h("table", { class: "decay-answer" },
    h("tbody", {}, rows.map(([cls, label, value]) => h("tr", { class: cls }, h("th", { scope: "row" }, label), h("td", {}, value)))));
}

function answerView(a) {
  const warnings = Array.isArray(a.warnings) ? a.warnings : [];
  return h("div", { class: "decay-result", role: "status" },
    h("h3", {}, "Answer"),
    answerTable(a),
    Number.isFinite(a.frequency_resolution_hz) || Number.isFinite(a.damping_ratio_resolution)
      ? h("p", { class: "hint decay-pm" }, "± is the 95 % half-width of the figure, from the fit and the samples' scatter about it.")
      : null,
    warnings.length
      ? h("div", { class: "warnings decay-warnings", role: "alert" },
        h("ul", {}, warnings.map((w) => h("li", { class: String(w.code || "").replace(/_/g, "-") }, `⚠ ${w.message || w.code}`))))
      : null);
}

/** Draw the free-decay page in `root`. */
export function renderDecay(root) {
  const samples = h("textarea", {
    rows: 8, cols: 28, spellcheck: "false", autocomplete: "off",
    dataset: { field: "samples" }, "aria-label": "Samples",
    placeholder: "0.95\n0.31\n-0.62\n…",
    oninput: () => { typed.samples = samples.value; mark(samples, ""); },
  });
  samples.value = typed.samples;
  const kept = keptForm("decay", typed, EMPTY, answerView, "Empty this page: the samples, the sampling step, the offset and the answer? Cancel to keep them.", () => {
    renderDecay(root);
    $('[data-field="samples"]', root).focus();
  });
  const result = h("div", { class: "decay-out" }, kept.shown);
  const run = h("button", { type: "submit", class: "primary identify" }, "Identify");
  const form = kept.watch(h("form", { class: "decay-form", novalidate: true, onsubmit: (e) => { e.preventDefault(); identify(); } },
    h("div", { class: "decay-fields" },
      h("label", {}, h("span", {}, "Samples (a column pasted from a spreadsheet, or separated by commas, spaces or tabs)"),
        h("span", { class: "field samples-field" }, samples, h("span", { class: "msg", role: "alert" }))),
      h("div", { class: "decay-side" },
        h("label", {}, h("span", {}, "Sampling step dt_s, seconds"),
          numberInput({ field: "dt_s", kind: "dt", value: typed.dt_s, label: "Sampling step, seconds", placeholder: "0.005", size: 9, onValue: (v) => { typed.dt_s = v; } })),
        h("label", {}, h("span", {}, "Damping law"),
          selectInput({ field: "damping", value: typed.damping, choices: LAWS.map(([v, text]) => [v, text.split(" — ")[0]]), label: "Damping law", onValue: (v) => { typed.damping = v; explain(); } })),
        h("p", { class: "hint law" }),
        h("label", {}, h("span", {}, "Offset (optional, samples' unit; empty: fitted)"),
          numberInput({ field: "offset", kind: "offset", value: typed.offset, required: false, label: "Offset, optional", size: 9, onValue: (v) => { typed.offset = v; } })),
        h("div", { class: "actions decay-actions" }, run, kept.again))),
  ), result);
  const explain = () => { $(".law", form).textContent = LAWS.find(([v]) => v === typed.damping)[1]; };
  explain();

  async function identify() {
    clearMarks(root);
    mark(samples, "");
    banner(root, "error", "");
    const parsed = parseSamples(samples.value);
    if (parsed.error) {
      mark(samples, parsed.error);
      return samples.focus();
    }
    const dt = $('[data-field="dt_s"]', root);
    if (!dt.validateNow()) return dt.focus();
    const off = $('[data-field="offset"]', root);
    if (!off.validateNow()) return off.focus();
    const body = { samples: parsed.values, dt_s: typed.dt_s, damping: typed.damping };
    if (typed.offset !== null) body.offset = typed.offset;
    await sendAndShow({ root, run, result, typed, send: () => api.identifyFreeDecay(body), view: answerView });
    kept.save();
  }

  replace(root,
    h("h2", {}, "Free decay: natural frequency and damping"),
    h("p", { class: "note" }, "From a record of a free decay (tap the machine, or let a shaft swing out) at a constant sampling step: the natural frequency and damping the service fits to it (method §7). Works offline; nothing is stored on the service."),
    form,
    result);
}
