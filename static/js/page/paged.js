// A list the service gives a page at a time (newest first), shown with
// "Show N more" under it while the service holds more: the sessions and the
// machines pages.

import { h, replace } from "./dom.js";
import { banner } from "./fields.js";

/**
 * Fill `list` (a tbody) a page at a time, the "Show N more" button in `more`.
 * `fetchPage(limit, offset)` answers `{ found, total }`; `what` names the
 * items in the button's class and the errors ("sessions": `more-sessions`),
 * `shownAs` in the hint; `empty` is said, over `columns` cells, when there
 * are none. Errors of a later page go to a banner in `root`.
 */
export async function pagedList({ root, list, more, pageSize, fetchPage, row, what, shownAs, empty, columns }) {
  let shown = 0;
  const page = async () => {
    const { found, total } = await fetchPage(pageSize, shown);
    shown += found.length;
    return { found, total: typeof total === "number" ? total : shown };
  };
  const moreOrNot = (total) => replace(more, shown < total ? [
    h("span", { class: "hint" }, `The ${shown} newest of ${total} ${shownAs}. `),
    h("button", { type: "button", class: `small more-${what}`, onclick: async () => {
      try {
        const next = await page();
        list.append(...next.found.map(row));
        moreOrNot(next.total);
      } catch (err) {
        banner(root, "error", `Could not list more ${what}: ${err.message}`);
      }
    } }, `Show ${Math.min(pageSize, total - shown)} more`),
  ] : "");
  try {
    const first = await page();
    replace(list, first.found.length === 0 ? h("tr", {}, h("td", { colspan: columns }, empty)) : first.found.map(row));
    moreOrNot(first.total);
  } catch (err) {
    replace(list, h("tr", {}, h("td", { colspan: columns }, `Could not list ${what}: ${err.message}`)));
  }
}
