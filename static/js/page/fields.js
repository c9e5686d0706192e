// Inputs that check themselves as they are typed into, and the marks that put
// a message (the form's own or the server's `error.field`) next to the field.

import { h, $, $$, replace } from "./dom.js";
import { check } from "./num.js";
import { keepPage } from "../job/keep.js";

const INCOMPLETE = /^([+-]?[.,]?|[+-]?\d+([.,]\d*)?[eE][+-]?)$/;

function wrap(input, extraClass) {
  const msg = h("span", { class: "msg", role: "alert" });
  return h("span", { class: `field ${extraClass || ""}` }, input, msg);
}

/** Put `message` next to the input and mark it bad; an empty message clears it. */
export function mark(input, message) {
  const wrapper = input.closest(".field");
  const msg = wrapper && $(".msg", wrapper);
  if (message) {
    input.setAttribute("aria-invalid", "true");
    if (wrapper) wrapper.classList.add("bad");
    if (msg) msg.textContent = message;
  } else {
    input.removeAttribute("aria-invalid");
    if (wrapper) wrapper.classList.remove("bad");
    if (msg) msg.textContent = "";
  }
}

/**
 * A number input (type=text so that a decimal comma and partial input are kept
 * as typed). `onValue` gets the number, or null while the text is empty or bad.
 */
export function numberInput({ field, kind, value, required = true, onValue, label, placeholder, disabled, size }) {
  const input = h("input", {
    type: "text",
    inputmode: "decimal",
    autocomplete: "off",
    spellcheck: "false",
    class: `num ${kind}`,
    dataset: { field, kind },
    "aria-label": label,
    placeholder,
    disabled,
    size: size || 7,
    value: value === null || value === undefined ? "" : String(value),
  });
  const validate = (showRequired) => {
    const r = check(input.value, kind, required);
    mark(input, r.error && (showRequired || !r.empty) ? r.error : "");
    return r;
  };
  input.addEventListener("input", () => {
    // A sign, a point or an exponent just typed is a number being written, not a bad one.
    const r = INCOMPLETE.test(input.value.trim()) ? { empty: true } : validate(false);
    if (INCOMPLETE.test(input.value.trim())) mark(input, "");
    onValue(r.error || r.empty ? null : r.value);
  });
  // Leaving a cell keeps a "required" mark that a check put there until it is filled.
  input.addEventListener("blur", () => validate(input.getAttribute("aria-invalid") === "true"));
  input.validateNow = () => !validate(true).error;
  return wrap(input, "num-field");
}

/** A text input; `required` ones are marked when left empty at a check. */
export function textInput({ field, value, required = false, onValue, label, placeholder, disabled, size, maxlength = 200 }) {
  const input = h("input", {
    type: "text",
    autocomplete: "off",
    dataset: { field },
    "aria-label": label,
    placeholder,
    disabled,
    size: size || 14,
    maxlength,
    value: value || "",
  });
  const validate = (showRequired) => {
    const empty = input.value.trim() === "";
    mark(input, required && empty && showRequired ? "required" : "");
    return !(required && empty);
  };
  input.addEventListener("input", () => {
    validate(false);
    onValue(input.value.trim());
  });
  input.validateNow = () => validate(true);
  return wrap(input, "text-field");
}

/** A select of `[value, text]` choices. */
export function selectInput({ field, value, choices, onValue, label, disabled }) {
  const select = h(
    "select",
    { dataset: { field }, "aria-label": label, disabled, onchange: () => onValue(select.value) },
    choices.map(([v, text]) => h("option", { value: v, selected: v === value }, text)),
  );
  return wrap(select, "select-field");
}

/** Run every self-check under `root`; focus the first bad field. True when all pass. */
export function validateAll(root) {
  let first = null;
  for (const input of $$("input, select", root)) {
    if (input.validateNow && !input.validateNow() && !first) first = input;
  }
  if (first) first.focus();
  return first === null;
}

export function clearMarks(root) {
  for (const input of $$("[aria-invalid]", root)) mark(input, "");
}

/**
 * Show a server error at the field it names. `prefix` turns a path relative to
 * the posted body (a run's `readings[3].phase_deg`) into the form's path
 * (`runs[2].readings[3].phase_deg`). Returns true when a field was found.
 */
export function markServerError(err, prefix = "") {
  if (!err.field) return false;
  let path = err.field.replace(/^session\./, "").replace(/^run\./, "");
  const candidates = [path];
  if (prefix && !path.startsWith("runs[")) candidates.unshift(prefix + path);
  for (const candidate of candidates) {
    // Walk up the path so that `planes[1]` still finds `planes[1].id`, but not
    // above the prefix: `runs[0].planes[1]` is no field of the run being typed.
    const floor = candidate.startsWith(prefix) && prefix ? prefix.length : 0;
    let p = candidate;
    while (p && p.length > floor) {
      const input = document.querySelector(`[data-field="${CSS.escape(p)}"]`) ||
        document.querySelector(`[data-field^="${CSS.escape(p)}."]`);
      if (input && !input.disabled) {
        mark(input, err.message);
        // A set-up field named while the runs step is shown: bring its step into view first.
        const section = input.closest("section.step");
        if (section && section.hidden) {
          document.dispatchEvent(new CustomEvent("fieldbal:reveal", { detail: section.id.replace(/^step-/, "") }));
        }
        input.focus();
        return true;
      }
      const cut = Math.max(p.lastIndexOf("."), p.lastIndexOf("["));
      p = cut > 0 ? p.slice(0, cut) : "";
    }
  }
  return false;
}

/** A banner for messages that belong to no single field. */
export function banner(container, kind, text) {
  const el = $(".banner", container) || container.insertBefore(h("div", { class: "banner" }), container.firstChild);
  el.className = `banner ${kind}`;
  el.textContent = text || "";
  el.hidden = !text;
  el.setAttribute("role", kind === "error" ? "alert" : "status");
}

/**
 * The field being typed in under `root`, and a function that puts the focus
 * and caret back in its new copy after a re-render (the trial-weight
 * suggestion arriving while a cell is typed in).
 */
export function keepFocus(root) {
  const el = document.activeElement;
  const field = el && root.contains(el) && el.dataset ? el.dataset.field : null;
  if (!field) return () => {};
  const [start, end] = [el.selectionStart, el.selectionEnd];
  return () => {
    const again = $(`[data-field="${CSS.escape(field)}"]`, root);
    if (!again || again === el) return;
    again.focus();
    if (typeof start === "number") again.setSelectionRange(start, end);
  };
}

// Send a stand-alone page's request (`send`) from its `run` button (off while
// out): the answer into `typed.answer`, shown by `view` in `result`; a refusal
// at the field it names, else in a banner on `root`.
export async function sendAndShow({ root, run, result, typed, send, view }) {
  run.disabled = true;
  try {
    typed.answer = await send();
    replace(result, view(typed.answer));
  } catch (err) {
    typed.answer = null;
    replace(result);
    if (!markServerError(err)) banner(root, "error", err.message);
  } finally {
    run.disabled = false;
  }
}

// A stand-alone page's input and answer kept (keep.js) as its form changes;
// the kept answer drawn again, greyed (stale) after a change until sent again;
// "Start over", asking first if anything is typed.
export function keptForm(name, typed, empty, view, question, redraw) {
  let out = null;
  const save = (stale) => {
    typed.stale = stale && !!typed.answer;
    if (out) out.classList.toggle("stale", typed.stale);
    keepPage(name, typed);
  };
  let shown = null;
  try {
    shown = typed.answer ? view(typed.answer) : null;
  } catch (e) {
    typed.answer = null;
  }
  const again = h("button", { type: "button", class: "start-over", onclick: () => {
    if (Object.keys(empty).some((k) => typed[k] !== empty[k]) && !window.confirm(question)) return;
    Object.assign(typed, empty);
    keepPage(name, null);
    redraw();
  } }, "Start over");
  const watch = (form, result) => {
    out = result;
    result.classList.toggle("stale", !!typed.stale);
    form.addEventListener("input", () => save(true));
    form.addEventListener("change", () => save(true));
    return form;
  };
  return { save: () => save(false), shown, again, watch };
}
