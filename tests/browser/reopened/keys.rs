//! The keyboard alone: keys pressed into whatever has the focus (WebDriver
//! key actions, no element picked, no click), and where the focus is.

use fantoccini::actions::{InputSource, KeyAction, KeyActions};
use serde_json::Value;

use crate::harness::steps::js;
use crate::harness::Browser;

pub const TAB: char = '\u{e004}';
pub const ENTER: char = '\u{e007}';
pub const DOWN: char = '\u{e015}';

/// Press each key of `keys` in turn (characters type themselves).
pub async fn press(b: &Browser, keys: &str) {
    let mut actions = KeyActions::new("keyboard".into());
    for c in keys.chars() {
        actions = actions
            .then(KeyAction::Down { value: c })
            .then(KeyAction::Up { value: c });
    }
    b.client
        .perform_actions(actions)
        .await
        .expect("keys pressed");
}

/// The focused element in words: its field path, else its tag, class and text.
pub async fn focused(b: &Browser) -> String {
    let v: Value = js(
        b,
        "const e = document.activeElement; if (!e || e === document.body) return 'body'; \
         return e.dataset.field ? `[${e.dataset.field}]` : `${e.tagName.toLowerCase()}.${e.className} ${(e.textContent || e.value || '').trim().slice(0, 40)}`",
    )
    .await;
    v.as_str().unwrap_or_default().to_string()
}

/// Whether the focused element matches `css`.
pub async fn focus_is(b: &Browser, css: &str) -> bool {
    let script = format!(
        "return !!document.activeElement && document.activeElement.matches({})",
        serde_json::to_string(css).unwrap()
    );
    js(b, &script).await == Value::Bool(true)
}

/// Press Tab until the focus is on `css`; the number of presses. Fails
/// after `most` presses, naming where the focus went.
pub async fn tab_to(b: &Browser, css: &str, most: usize) -> usize {
    let mut path = Vec::new();
    for n in 0..=most {
        if focus_is(b, css).await {
            return n;
        }
        path.push(focused(b).await);
        press(b, &TAB.to_string()).await;
    }
    panic!("{css} not reached in {most} presses of Tab: {path:?}");
}

/// The focused element is wholly inside the viewport and not under a sticky bar.
pub async fn focus_in_view(b: &Browser) -> Value {
    js(
        b,
        "const e = document.activeElement; const r = e.getBoundingClientRect(); \
         const bar = document.querySelector('.step:not([hidden]) .actions.sticky'); \
         const foot = bar && bar !== e.closest('.actions.sticky') ? bar.getBoundingClientRect().top : innerHeight; \
         const head = e.closest('table.grid tbody') ? e.closest('table.grid').querySelector('thead').getBoundingClientRect().bottom : 0; \
         return r.top >= Math.max(0, head) - 1 && r.bottom <= Math.min(innerHeight, foot) + 1 && r.left >= 0 && r.right <= innerWidth",
    )
    .await
}
