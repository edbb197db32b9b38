"""What the served page does in the browser itself, so that it can say what the kernel cannot: that
the results on the screen are not (or no longer) those of the fields.

Each control row carries its key path (``data-key`` on its label) and the results carry the field
texts they were computed for (``data-inputs``, :meth:`calc.review.panel.DesignReview.refresh`). The
script compares them: results whose inputs differ from the fields, or asked for and not yet
arrived, are greyed and marked out of date; a lost connection to the kernel (the server stopped,
a tunnel dropped) greys them too and says how to get back. It keeps the changed values in the
page's address (``#…``), so a reload or a shared link types them in again, and asks before a
reload or a switch of case drops changes; a click on a candidate's row forces that part (its
control set as a reviewer would set it). The moves' edits (entries added or removed) and the unit
system, where it is not the file's, go into the address too; a link's are handed back to the kernel
through a hidden field (``dr-edits``). Voilà runs it from the page's notebook
(``design-review.ipynb``); in JupyterLab the kernel is beside the notebook and it is not needed.
"""

from __future__ import annotations

from html import escape

STYLE = """<style>
.design-review .dr-state { font-size: 13px; padding: 3px 8px; border-radius: 3px; margin: 0 0 4px;
  background: #eef6ee; color: #1b5e20; }
.design-review.dr-stale .dr-state, .design-review.dr-busy .dr-state { background: #fff4d6; color: #6d4c00; }
.design-review.dr-lost .dr-state { background: #b2222a; color: #fff; }
.design-review.dr-stale .dr, .design-review.dr-lost .dr, .design-review.dr-busy .dr {
  opacity: 0.42; filter: grayscale(1); }
.design-review.dr-stale .dr-figures, .design-review.dr-lost .dr-figures, .design-review.dr-busy .dr-figures {
  opacity: 0.42; }
.design-review .dr-refused input { border: 2px solid #b2222a !important; background: #fff0f0 !important; }
.design-review .dr-message { color: #b2222a; font-size: 12px; margin: -2px 0 4px 15.5em; line-height: 1.2; }
.design-review .dr-idle { color: #666; font-size: 12px; margin: -2px 0 4px 15.5em; line-height: 1.2; }
.design-review > .widget-vbox:last-child { overflow-x: auto; }  /* a wide table scrolls in its column, never cut */
.design-review tr[data-force] { cursor: pointer; }
.design-review .dr-print-head { display: none; }
.design-review tr[data-force]:hover td { background: #eef3fb; }
.design-review .dr-changed { color: #1f5fbf; border-left: 4px solid #1f5fbf; padding-left: 4px; margin-left: -8px; }
.design-review .dr-top { flex-wrap: wrap; row-gap: 2px; } .design-review .dr-top .dr-case { min-width: 16em; }
/* a table's words wrap, its numbers do not: no long text widens the results beyond their column (a note under it
   would be as wide, and cut) */
.design-review .dr td, .design-review .dr th { white-space: normal; } .design-review .dr td.n { white-space: nowrap; }
.design-review .dr td:first-child { white-space: nowrap; }
.design-review .dr.dr-variants td:first-child { white-space: normal; }
.design-review .dr span.open { display: inline-block; max-width: 22em; }  /* a check not made: why, in a column */
@media (max-width: 1180px) {
  /* a narrow screen: the controls' column narrows so that the verdict stays beside them */
  .design-review > .widget-vbox:first-child { flex: 0 0 430px !important; width: 430px !important; }
  .design-review .dr-label { flex: 0 0 12em !important; width: 12em !important; }
  .design-review .dr-message, .design-review .dr-idle { margin-left: 12em; }
  .design-review > .widget-vbox:last-child { min-width: 420px !important; flex: 1 1 420px !important; }
  /* the tables wrap their words, not their numbers, so that the verdict column stays on the screen */
  .design-review .dr { font-size: 12px; }
  .design-review .dr td, .design-review .dr th { padding-right: 5px; }
  .design-review .dr td:first-child { white-space: normal; }
  .design-review .dr .bar { width: 28px; }
}
@media print {
  @page { size: A4; margin: 14mm 12mm;
          @bottom-right { content: "page " counter(page) " of " counter(pages); font: 8pt sans-serif; color: #333; } }
  /* Voilà's page scrolls inside fixed-height boxes: printed, every box takes its content's height */
  html, body, body * { overflow: visible !important; }
  /* and is as wide as the screen was (Lumino sets its panels' widths): printed, as wide as the paper, so no text
     runs past its right edge */
  html, body, .jp-LabShell, .lm-BoxPanel, .lm-BoxPanel-child { width: auto !important; min-width: 0 !important; }
  /* JupyterLab keeps an output on one page: the review, taller than a page, was pushed to the second (a blank
     first page) */
  .jp-OutputArea-child { break-inside: auto !important; }
  /* the title block and the verdict first, then the inputs they were computed from */
  .design-review > .widget-vbox:last-child { order: -1; }
  html, body, .lm-Widget, .jp-OutputArea, .jp-Cell {
    height: auto !important; max-height: none !important; contain: none !important; }
  .lm-Widget { position: relative !important; top: auto !important; left: auto !important; }
  .design-review { flex-flow: column !important; }
  .design-review > .widget-vbox { width: 100% !important; min-width: 0 !important; flex: 1 1 auto !important; }
  .design-review .dr table { font-size: 9px; } .design-review .dr td, .design-review .dr th { white-space: normal; }
  .design-review img { max-width: 100% !important; }
  .design-review .dr-keep, .design-review button { display: none !important; }
  /* the title block: which case, when, by which version */
  .design-review .dr-print-head { display: block !important; font-size: 9px; color: #333; margin: 0 0 4px; }
}
</style>"""

SCRIPT = r"""<script>
(() => {
  if (window.designReviewClient) return;
  window.designReviewClient = true;
  const panel = () => document.querySelector('.design-review');
  const results = () => document.querySelector('.design-review .dr[data-generation]');
  // An option's text as written (the widgets write its spaces as no-break spaces).
  const optionText = o => o.text.replace(/\u00a0/g, ' ').trim();
  // When the page loaded, or a link's case was asked for: what a link carries is waited for that long.
  let loadedAt = Date.now();
  const PATIENCE = 60000;
  let askedAfter = null, askedAt = 0, restoring = null;  // the results' generation when a value was last asked for
  // The text each control shows, by key path: a field's text, a choice's option.
  function shown() {
    const out = {};
    for (const label of document.querySelectorAll('.design-review [data-key]')) {
      const row = label.closest('.dr-row');
      if (!row) continue;
      const field = row.querySelector('input[type=text]'), choice = row.querySelector('select');
      if (field) out[label.dataset.key] = field.value.trim();
      else if (choice && choice.selectedIndex >= 0)
        out[label.dataset.key] = optionText(choice.options[choice.selectedIndex]);
    }
    return out;
  }
  function current() {
    const r = results();
    if (!r || !r.dataset.inputs) return false;
    const stamp = JSON.parse(r.dataset.inputs), now = shown();
    return Object.keys(now).every(k => stamp[k] === undefined || stamp[k] === now[k]);
  }
  // A kernel restarted (killed, then started again by the server) holds none of the page's controls:
  // what it computed is lost for good, and only a reload gives a working page.
  let restarted = false, watched = null;
  function kernelOf() {
    const app = window.jupyterapp, manager = app && (app.widgetManager || app._widgetManager);
    return manager && (manager.kernel || manager._kernel);
  }
  function connection() {
    const kernel = kernelOf();
    if (kernel && watched !== kernel && kernel.statusChanged) {
      watched = kernel;
      kernel.statusChanged.connect((_, status) => {
        if (['restarting', 'autorestarting', 'dead'].includes(status)) { restarted = true; show(); }
      });
    }
    if (kernel && ['restarting', 'autorestarting', 'dead'].includes(kernel.status)) restarted = true;
    return kernel ? kernel.connectionStatus : null;  // null: not in a served page (JupyterLab)
  }
  // Each control named for assistive technology by its row's label; the state line a live region; a candidate's
  // row reachable and forced by the keyboard (Enter or Space), as a click forces it.
  function accessible(p) {
    for (const row of p.querySelectorAll('.dr-row')) {
      const label = row.querySelector('[data-key]');
      if (!label) continue;
      const name = label.textContent.replace(/\s+/g, ' ').trim();
      const kinds = [['input[type=text]', ': value typed'], ['select', ''], ['[role=slider]', ': slider']];
      for (const [sel, what] of kinds) {
        for (const c of row.querySelectorAll(sel)) if (c.getAttribute('aria-label') !== name + what) {
          c.setAttribute('aria-label', name + what);
        }
      }
    }
    for (const c of p.querySelectorAll('.dr-case select, .dr-moves select, .dr-written select')) {
      if (!c.getAttribute('aria-label')) c.setAttribute('aria-label', c.closest('.widget-dropdown')?.textContent.trim()
                                                          .split('\n')[0] || 'choice');
    }
    const state = p.querySelector('.dr-state');
    if (state && state.getAttribute('role') !== 'status') { state.setAttribute('role', 'status');
                                                             state.setAttribute('aria-live', 'polite'); }
    for (const tr of p.querySelectorAll('tr[data-force]:not([tabindex])')) {
      tr.setAttribute('tabindex', '0'); tr.setAttribute('role', 'button');
      tr.setAttribute('aria-label', 'force ' + tr.dataset.part);
    }
  }
  // What can wait until the results are painted: the controls' names, and the address (history.replaceState
  // waits on the browser's own process, at times 15 ms, while the new results stay unpainted). Run once after
  // the next frame, with the latest page; a hidden page, which draws no frame, within 200 ms.
  let later = null;
  function afterPaint(work) {
    const first = later === null;
    later = work;
    if (!first) return;
    const run = () => { const w = later; later = null; if (w) w(); };
    requestAnimationFrame(() => setTimeout(run, 0));
    setTimeout(run, 200);
  }
  function show() {
    const p = panel(), r = results();
    if (!p || !r) return;
    if (restoring !== false && restoring !== 'case') restore();
    const state = p.querySelector('.dr-state'), link = connection();
    const lost = restarted || (link !== null && link !== 'connected');
    const same = current();
    const waiting = askedAfter !== null && Number(r.dataset.generation) <= askedAfter && Date.now() - askedAt < 3000;
    const stale = !same || waiting || p.classList.contains('dr-busy');  // dr-busy: the kernel computing a change
    p.classList.toggle('dr-lost', lost);
    p.classList.toggle('dr-stale', stale && !lost);
    if (state) {
      const text = restarted
        ? 'The server restarted this page’s computation (its kernel): the results shown are not those of the fields, '
          + 'and no change is computed any more. Reload the page; the changed values, typed ones too, are kept in '
          + 'its address.'
        : lost
        ? 'Connection to the server lost: the results shown are not those of the fields. '
          + 'Start the server again (make review) and reload the page; the changed values are kept in its address.'
        : stale ? 'Out of date: computing the results of the values changed '
          + '(a value typed counts once Enter is pressed or the field is left).'
        : 'Current: the results are those of the values shown'
          + (modified(r) ? ' (changed values marked)' : ' (the case file’s values)') + '.';
      // Written only when it changes: the observer below sees every write.
      if (state.textContent !== text) state.textContent = text;
      const word = restarted ? 'restarted' : lost ? 'lost' : stale ? 'stale' : 'current';
      if (state.dataset.state !== word) state.dataset.state = word;
    }
    const keep = restoring === false && (lost || same);  // not before the address was read
    afterPaint(() => { accessible(p); if (keep) keepInAddress(r, lost); });
  }
  // Whether the screen differs from the case file: a value changed, or the moves edited.
  const edited = r => r.dataset.edits && r.dataset.edits !== '[]';
  const modified = r => (r.dataset.changed && r.dataset.changed !== '{}') || edited(r);
  // The changed values (and the moves' edits) in the page's address, so that a reload or a link types them in again.
  // Lost (``typed``): the values typed since, which no kernel took, are kept as well.
  function keepInAddress(r, typed) {
    const changed = JSON.parse(r.dataset.changed || '{}'), name = r.dataset.case || '';
    if (typed && r.dataset.inputs) {
      const stamp = JSON.parse(r.dataset.inputs), now = shown(), factors = JSON.parse(r.dataset.factors || '{}');
      for (const k of Object.keys(now)) if (stamp[k] !== undefined && stamp[k] !== now[k]) {
        // the address carries the file's units: a number typed in a field shown in another unit goes back to it
        const v = Number(now[k].replace(',', '.'));
        changed[k] = factors[k] && now[k] !== '' && Number.isFinite(v) ? String(+(v / factors[k]).toPrecision(12))
                                                                      : now[k];
      }
    }
    const state = edited(r) ? {case: name, edits: JSON.parse(r.dataset.edits), values: changed}
                            : {case: name, values: changed};
    const units = r.dataset.units !== r.dataset.fileUnits;  // the other unit system than the file's
    if (units) state.units = r.dataset.units;
    const variants = JSON.parse(r.dataset.variants || '[]');  // the variants kept, each as its edits and values
    if (variants.length) state.variants = variants;
    const some = modified(r) || Object.keys(changed).length || units || variants.length;
    const hash = some ? '#' + encodeURIComponent(JSON.stringify(state)) : '';
    if (location.hash !== hash) history.replaceState(null, '', location.pathname + location.search + hash);
  }
  function rowOf(key) {
    const label = document.querySelector(`.design-review [data-key="${CSS.escape(key)}"]`);
    return label && label.closest('.dr-row');
  }
  function type(key, text) {
    const row = rowOf(key);
    if (!row) return;
    const field = row.querySelector('input[type=text]'), choice = row.querySelector('select');
    const target = field || choice;
    if (field) field.value = text;
    else if (choice) {
      const k = [...choice.options].findIndex(o => optionText(o) === text);
      if (k < 0) return;
      choice.selectedIndex = k;
    }
    if (target) { ask(); target.dispatchEvent(new Event('change', {bubbles: true})); }
  }
  function ask() { const r = results(); askedAfter = r ? Number(r.dataset.generation) : 0; askedAt = Date.now(); }
  // Hand what a link carries (``wanted``) to the kernel through its hidden field, unless the
  // results already carry it (``has``) or say it was asked for (``asked``: the kernel says why
  // what it could not take was left out); true once so. Not forever: PATIENCE after the page loaded.
  function handOver(what, selector, wanted, has, asked) {
    const same = text => JSON.stringify(wanted) === JSON.stringify(JSON.parse(text || '[]'));
    if (same(has) || (asked !== undefined && same(asked))) return true;
    const field = document.querySelector('.design-review ' + selector);
    if (Date.now() - loadedAt > PATIENCE) { restoring = false; return false; }
    if (restoring === what || !field) return false;  // asked for and not drawn yet, or the field not drawn yet
    restoring = what; field.value = JSON.stringify(wanted); field.dispatchEvent(new Event('change', {bubbles: true}));
    return false;
  }
  function restore() {  // once, when the panel is first shown
    if (restoring === false) return;
    if (!location.hash) { restoring = false; return; }
    let wanted;
    try { wanted = JSON.parse(decodeURIComponent(location.hash.slice(1))); } catch (e) { restoring = false; return; }
    const r = results();
    if (!r) return;  // the panel not drawn yet
    if (!wanted || !wanted.values) { restoring = false; return; }
    if (wanted.case && r.dataset.case !== wanted.case) {
      if (restoring === 'case') return;  // the case asked for is being loaded
      const choice = document.querySelector('.design-review .dr-case select');
      const k = choice ? [...choice.options].findIndex(o => optionText(o).split(' · ')[0] === wanted.case) : -1;
      // The chooser is drawn after the results at times: wait for it (not forever); a case not offered is dropped.
      if (k < 0) { if (!choice && Date.now() - loadedAt < PATIENCE) return; restoring = false; return; }
      restoring = 'case'; loadedAt = Date.now();
      choice.selectedIndex = k; choice.dispatchEvent(new Event('change', {bubbles: true}));
      return;  // the values follow once the case is loaded
    }
    // The variants first (the kernel evaluates each from its case file), then the moves' edits
    // (made at once, from the file's moves), then the values.
    const variants = wanted.variants || [], asked = r.dataset.variantsAsked;
    if (!handOver('variants', '.dr-variants-asked input', variants, r.dataset.variants, asked)) return;
    if (!handOver('edits', '.dr-edits input', wanted.edits || [], r.dataset.edits)) return;
    // The controls are drawn after the results at times: wait for every row asked for (not forever).
    if (Object.keys(wanted.values).some(k => !rowOf(k)) && Date.now() - loadedAt < PATIENCE) return;
    restoring = false;
    for (const [key, text] of Object.entries(wanted.values)) type(key, text);
    if (wanted.units && wanted.units !== r.dataset.units) {  // the unit system the link was shown in
      const buttons = [...document.querySelectorAll('.design-review .widget-toggle-buttons button')];
      const button = buttons.find(b => b.textContent.trim() === wanted.units);
      if (button) { ask(); button.click(); }
    }
  }
  document.addEventListener('change', e => {
    if (!e.target.closest || !e.target.closest('.design-review .dr-row')) return;
    ask(); show();
  }, true);
  document.addEventListener('input', e => {
    if (e.target.closest && e.target.closest('.design-review')) show();
  }, true);
  document.addEventListener('keydown', e => {
    const tr = e.target.closest && e.target.closest('.design-review tr[data-force]');
    if (tr && (e.key === 'Enter' || e.key === ' ')) { e.preventDefault(); type(tr.dataset.force, tr.dataset.part); }
  }, true);
  // A click on a candidate's row forces that part: its control is set as a reviewer would set it.
  document.addEventListener('click', e => {
    const tr = e.target.closest && e.target.closest('.design-review tr[data-force]');
    if (tr) type(tr.dataset.force, tr.dataset.part);
    // an entry added or removed
    if (e.target.closest && e.target.closest('.design-review .dr-moves button')) { ask(); show(); }
  }, true);
  document.addEventListener('pointerup', e => {
    if (e.target.closest && e.target.closest('.design-review .dr-row .widget-slider')) { ask(); show(); }
  }, true);
  // A switch of case drops the changed values: asked first.
  document.addEventListener('change', e => {
    const r = results();
    if (restoring === 'case' || !e.target.closest || !e.target.closest('.design-review .dr-case') || !r) return;
    if (modified(r) && !confirm('Switch the case and drop the changed values? (Save as case file keeps them.)')) {
      e.stopImmediatePropagation();
      const choice = e.target, name = r.dataset.case;
      choice.selectedIndex = [...choice.options].findIndex(o => optionText(o).split(' · ')[0] === name);
    }
  }, true);
  window.addEventListener('beforeunload', e => {
    const r = results();
    if (r && modified(r) && !location.hash) { e.preventDefault(); e.returnValue = ''; }
  });
  new MutationObserver(() => { if (restoring === 'case') restore(); show(); })
    .observe(document.body, {subtree: true, childList: true, attributes: true,
                             attributeFilter: ['data-generation', 'data-inputs']});
  setInterval(show, 500);
})();
</script>"""


def page_html() -> str:
    """The page's style and script, as one HTML output of the served notebook.

    Returns
    -------
    str
        HTML: :data:`STYLE` then :data:`SCRIPT`.
    """
    return STYLE + SCRIPT


#: What the kernel says while it computes the results of a change (the panel is marked ``dr-busy``).
BUSY = "Out of date: computing the results of the values changed."


def state_html(busy: bool = False) -> str:
    """The line saying whether the results are current.

    The kernel writes it as it starts and ends computing a change (in JupyterLab, where no script
    of the page runs, that is what marks the results out of date); in the served page the script
    keeps it up to date with what only the browser knows (a value typed, the connection lost).

    Parameters
    ----------
    busy : bool
        Whether the kernel is computing a change (the results out of date, :data:`BUSY`).

    Returns
    -------
    str
        HTML: the line, its ``data-state`` ``"stale"`` or ``"current"``.

    Examples
    --------
    >>> state_html(busy=True)
    '<div class="dr-state" data-state="stale">Out of date: computing the results of the values changed.</div>'
    """
    word, text = ("stale", BUSY) if busy else ("current", "Current: the results are those of the values shown.")
    return f'<div class="dr-state" data-state="{word}">{escape(text)}</div>'
