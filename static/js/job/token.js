// The access-token prompt: a small modal dialog, shown when the service answers
// 401. The token is typed into a password field and kept in sessionStorage,
// so it lasts for this tab only and never reaches the page's text.

import { h } from "../page/dom.js";

const KEY = "fieldbal.token";

export function storedToken() {
  try {
    return sessionStorage.getItem(KEY);
  } catch (e) {
    return null;
  }
}

export function storeToken(token) {
  try {
    if (token) sessionStorage.setItem(KEY, token);
    else sessionStorage.removeItem(KEY);
  } catch (e) {
    // Storage refused (private mode): the token lasts for this page only.
  }
}

let asking = null;

/** Ask for a token; resolves to it, or to null when cancelled. One dialog at a time. */
export function askToken(message) {
  if (asking) return asking;
  asking = new Promise((resolve) => {
    const input = h("input", { type: "password", id: "token-input", autocomplete: "off", spellcheck: "false" });
    let dialog = null;
    const done = (value) => {
      if (!dialog) return;
      dialog.close();
      dialog.remove();
      dialog = null;
      asking = null;
      resolve(value);
    };
    const ok = h("button", { type: "button", id: "token-ok", onclick: () => done(input.value.trim() || null) }, "Use token");
    const cancel = h("button", { type: "button", id: "token-cancel", onclick: () => done(null) }, "Cancel");
    input.addEventListener("keydown", (e) => {
      if (e.key === "Enter") ok.click();
    });
    dialog = h("dialog", { id: "token-dialog", class: "token-dialog", "aria-labelledby": "token-title" },
      h("p", { id: "token-title" }, message),
      h("label", {}, "Access token ", input),
      h("p", { class: "hint" }, "Kept for this browser tab only."),
      h("div", { class: "actions" }, ok, cancel));
    dialog.addEventListener("cancel", (e) => {
      e.preventDefault();
      done(null);
    });
    document.body.append(dialog);
    dialog.showModal();
    input.focus();
  });
  return asking;
}
