// Work not yet stored on the service, kept in this browser's local storage so
// that a reload (or a closed tab) loses nothing: the set-up before the zero run
// is stored, the run being typed, the report's reason and signer, and the
// step shown. Cleared piece by piece as the service stores it.

import { state } from "./state.js";

const KEY = "fieldbal.unsaved";

/** What is kept: only what the service does not hold yet. */
function snapshot(step) {
  return {
    id: state.id,
    setup: state.id === null ? state.setup : null,
    draft: state.draft,
    options: state.options,
    report: state.report,
    step,
  };
}

let timer = null;
let lastStep = "setup";

/** Keep the job now (or soon, when typing fast). */
export function keep(step) {
  if (step) lastStep = step;
  clearTimeout(timer);
  timer = setTimeout(() => keepNow(), 150);
}

export function keepNow(step) {
  if (step) lastStep = step;
  clearTimeout(timer);
  try {
    localStorage.setItem(KEY, JSON.stringify(snapshot(lastStep)));
  } catch (e) {
    // Storage refused or full: the work lasts for this page only.
  }
}

/** What was kept, or null. */
export function kept() {
  try {
    const text = localStorage.getItem(KEY);
    return text ? JSON.parse(text) : null;
  } catch (e) {
    return null;
  }
}

/** Forget what was kept (a new job). */
export function forget() {
  clearTimeout(timer);
  try {
    localStorage.removeItem(KEY);
  } catch (e) {
    // Nothing kept.
  }
}

// A stand-alone page's input (free decay, residual check) in a slot of its
// own, null to forget it; read back over the page's defaults, by type.
export function keepPage(name, typed) {
  try {
    if (typed) localStorage.setItem(`${KEY}.${name}`, JSON.stringify(typed));
    else localStorage.removeItem(`${KEY}.${name}`);
  } catch (e) {
    // Storage refused or full: the input lasts for this page only.
  }
}

export function keptPage(name, defaults) {
  const out = { ...defaults };
  try {
    const saved = JSON.parse(localStorage.getItem(`${KEY}.${name}`)) || {};
    for (const [k, d] of Object.entries(defaults)) {
      const v = saved[k];
      if (v === null || (v !== undefined && (d === null || typeof v === typeof d))) out[k] = v;
    }
  } catch (e) {
    // Nothing readable kept.
  }
  return out;
}

// Every keystroke in the form is kept (the inputs update the state first: their
// own listeners run before this one, which the document hears last).
document.addEventListener("input", () => keep());
document.addEventListener("change", () => keep());
window.addEventListener("pagehide", () => keepNow());
