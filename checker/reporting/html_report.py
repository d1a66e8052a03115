"""The class report in the browser: `python -m checker submissions/ --html report.html`.

One self-contained HTML file (inline CSS and a few lines of vanilla JS, the
pictures inlined as data: URIs; no network): a histogram per check (how many
files passed, failed, erred or were skipped there, so the step the class
struggled with stands out), the mistakes named per check (how many files fail it, each named mistake with its
count and the files that made it, so an instructor knows what to reteach), the summary table (click a heading to sort by
file, lab, score, status or first problem), and each file's checks with their
messages, hints and pictures (checker/replay/pictures.py).
"""
import html

from checker.reporting.outputs import submission_names
from checker.reporting.report import (SYMBOL, NotGraded, _summary_line, check_label, class_mistakes, lab_means,
                                      message_of, reason, write_atomic)

STATUS_ORDER = ("pass", "fail", "error", "skip")
COLOURS = {"pass": "#3a9a5b", "fail": "#d0453a", "error": "#7d1d17", "skip": "#b9bcc4"}

CSS = """
body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222;background:#fbfbf9}
h1{font-size:1.5em;margin:0 0 .2em}h2{font-size:1.2em;margin:1.4em 0 .4em}
table{border-collapse:collapse}th,td{padding:3px 8px;border-bottom:1px solid #ddd;text-align:left;vertical-align:top}
#summary th{cursor:pointer;user-select:none;background:#eef0f4}#summary th:after{content:" \\2195";color:#999}
#summary th.asc:after{content:" \\25b2";color:#333}#summary th.desc:after{content:" \\25bc";color:#333}
td.num{text-align:right;font-variant-numeric:tabular-nums}
.pass{color:#2b7a45}.fail,.error{color:#b3261e}.skip{color:#777}
.bar{display:flex;width:360px;height:16px;border:1px solid #bbb;background:#f3f3f3}
.bar span{display:block;height:100%}
.legend span{display:inline-block;width:11px;height:11px;margin:0 3px 0 12px;vertical-align:-1px}
details{margin:.4em 0;border:1px solid #ddd;background:#fff;padding:.3em .6em}summary{cursor:pointer;font-weight:600}
.check{margin:.35em 0 .35em .4em}.msg{margin-left:1.8em;white-space:pre-wrap}.hint{margin-left:1.8em;color:#5a4a00}
.pic{margin:.3em 0 .3em 1.8em}.pic img{max-width:100%;border:1px solid #ccc}
#mistakes td.files{font-size:.9em;color:#555}#mistakes td.num{white-space:nowrap}#mistakes tr.check td{border-top:2px solid #bbb;font-weight:600}
"""

JS = """
(function () {
  var table = document.getElementById("summary");
  var heads = table.tHead.rows[0].cells;
  function key(row, col, numeric) {
    var cell = row.cells[col];
    var v = cell.getAttribute("data-sort");
    if (v === null) v = cell.textContent;
    return numeric ? parseFloat(v) : v.toLowerCase();
  }
  function sortBy(col) {
    var th = heads[col], numeric = th.getAttribute("data-type") === "number";
    var dir = th.classList.contains("asc") ? -1 : 1;
    for (var i = 0; i < heads.length; i++) heads[i].classList.remove("asc", "desc");
    th.classList.add(dir === 1 ? "asc" : "desc");
    var body = table.tBodies[0], rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = key(a, col, numeric), y = key(b, col, numeric);
      if (x < y) return -dir;
      if (x > y) return dir;
      return (parseInt(a.getAttribute("data-index"), 10) - parseInt(b.getAttribute("data-index"), 10));
    });
    rows.forEach(function (r) { body.appendChild(r); });
  }
  for (var i = 0; i < heads.length; i++) {
    (function (col) { heads[col].addEventListener("click", function () { sortBy(col); }); })(i);
  }
  window.sortSummary = sortBy;
})();
"""


def _e(text):
    return html.escape(str(text), quote=True)


def _first_problem(row):
    """The row's reason (report.reason): why it was not graded, or its first failed check with its message."""
    if isinstance(row, NotGraded):
        return f"not graded: {reason(row)}"
    return "" if row.passed else reason(row)


def _check_ids(rows):
    """Every check id in the rows, in the order the labs list them (a lab's order, labs one after another)."""
    ids = []
    for row in rows:
        for result in row.results:
            key = (row.lab.id if row.lab is not None else "", result.id, check_label(result))
            if key not in ids:
                ids.append(key)
    return ids


def histogram(rows):
    """HTML: one stacked bar per check, the files passing, failing, erring and skipped there."""
    labs = {row.lab.id: row.lab.title for row in rows if row.lab is not None}
    several = len(labs) > 1
    out = ['<p class="legend">' + "".join(f'<span style="background:{COLOURS[s]}"></span>{s}' for s in STATUS_ORDER)
           + "</p>", '<table id="histogram"><thead><tr><th>check</th><th>files by result</th><th>passed</th>'
           '<th>mean points</th></tr></thead><tbody>']
    for lab_id, check_id, shown in _check_ids(rows):
        results = [r for row in rows if row.lab is not None and row.lab.id == lab_id
                   for r in row.results if r.id == check_id]
        counts = {s: sum(1 for r in results if r.status == s) for s in STATUS_ORDER}
        total = max(len(results), 1)
        bar = "".join(f'<span class="{s}-bar" style="width:{100 * counts[s] / total:.1f}%;background:{COLOURS[s]}" '
                      f'title="{counts[s]} {s}"></span>' for s in STATUS_ORDER if counts[s])
        mean = sum(r.score for r in results) / total
        top = max((r.max_score for r in results), default=0)
        label = f"{labs.get(lab_id, lab_id)}: {shown}" if several else shown
        out.append(f'<tr data-check="{_e(check_id)}"><td>{_e(label)}</td><td><div class="bar">{bar}</div></td>'
                   f'<td class="num">{counts["pass"]}/{len(results)}</td><td class="num">{mean:.2g}/{top:g}</td></tr>')
    out.append("</tbody></table>")
    return "\n".join(out)


def mistakes_table(rows, names):
    """HTML: per check some file failed, how many files fail it of how many graded, then each named mistake with
    its count and the files that made it (most made first), then those failing it with no mistake named."""
    found = class_mistakes(rows)
    if not found:
        return "<p>No file fails a check.</p>"
    several = len({title for title, *_ in found}) > 1
    index = {row.path: k for k, row in enumerate(rows)}
    out = ['<table id="mistakes"><thead><tr><th>check / mistake</th><th>files</th><th>who</th></tr></thead><tbody>']
    for title, label, failing, graded, named, unnamed in found:
        shown = f"{title}: {label}" if several else label
        out.append(f'<tr class="check"><td>{_e(shown)}</td><td class="num">{failing} of {graded}</td><td></td></tr>')
        lines = [(text, mid, paths) for mid, text, paths in named] + ([("not named", "", unnamed)] if unnamed else [])
        for text, mid, paths in lines:
            who = ", ".join(f'<a href="#file-{index[p]}">{_e(names[p])}</a>' for p in paths)
            tag = f' <code>{_e(mid)}</code>' if mid else ""
            out.append(f'<tr data-mistake="{_e(mid)}"><td>{_e(text)}{tag}</td><td class="num">{len(paths)}</td>'
                       f'<td class="files">{who}</td></tr>')
    out.append("</tbody></table>")
    return "\n".join(out)


def picture_id(index, check_id, number=0):
    """The HTML id of a file's picture of a check (the summary table and the check's line link to it)."""
    return f"pic-{index}-{check_id}-{number}"


def _picture_links(index, pictures):
    """HTML: a link to the picture of each failed check that has one ("" when none has)."""
    return " ".join(f'<a href="#{picture_id(index, check_id)}">{_e(check_id)}</a>'
                    for check_id, shown in (pictures or {}).items() if shown)


def summary_table(rows, names, pictures=None):
    """HTML: the sortable table, one row per file (the file name links to its checks below, and each failed
    check's picture is linked). pictures: {row path: {check id: [Picture]}}."""
    pictures = pictures or {}
    out = ['<table id="summary"><thead><tr><th data-type="text">file</th><th data-type="text">lab</th>'
           '<th data-type="number">score</th><th data-type="text">status</th><th data-type="text">first problem</th>'
           '<th data-type="number">flagged</th><th data-type="text">pictures</th></tr></thead><tbody>']
    for k, row in enumerate(rows):
        name = names[row.path]
        title = row.lab.title if row.lab is not None else ""
        out.append(f'<tr data-index="{k}"><td><a href="#file-{k}">{_e(name)}</a></td><td>{_e(title)}</td>'
                   f'<td class="num" data-sort="{row.score:g}">{row.score:g}/{row.max_score:g}</td>'
                   f'<td class="{row.status}">{row.status}</td><td>{_e(_first_problem(row))}</td>'
                   f'<td class="num">{len(getattr(row, "flags", ()) or ())}</td>'
                   f'<td>{_picture_links(k, pictures.get(row.path))}</td></tr>')
    out.append("</tbody></table>")
    return "\n".join(out)


def submission(row, index, pictures, name):
    """HTML: one file's checks, each with its message, hint and pictures."""
    title = f" - {row.lab.title}" if row.lab is not None else ""
    opened = "" if row.passed else " open"
    out = [f'<details id="file-{index}" class="file"{opened}><summary>{_e(name)}{_e(title)}: '
           f'<span class="{row.status}">{row.score:g}/{row.max_score:g} {row.status}</span></summary>']
    if isinstance(row, NotGraded):
        out.append(f'<div class="check error">:( could not be graded: {_e(message_of(row))}</div>')
    flags = getattr(row, "flags", ()) or ()
    if flags:   # what the step rules flagged: for the instructor to read (checker/README.md, threat model)
        out.append('<div class="check flags"><b>flagged in the steps</b> (constructs that reach around the '
                   'exercise):<ul>' + "".join(f'<li>line {f["line"]} (step {f["step"]}): {_e(f["what"])}: '
                                              f'<code>{_e(f["text"])}</code></li>' for f in flags) + '</ul></div>')
    for r in row.results:
        out.append(f'<div class="check" data-check="{_e(r.id)}"><span class="{r.status}">{_e(SYMBOL[r.status])}</span> '
                   f'<b>{_e(r.id)}</b> {_e(r.name)} <span class="num">({r.score:g}/{r.max_score:g})</span>')
        if r.message:
            out.append(f'<div class="msg">{_e(r.message)}</div>')
        if r.hint:
            out.append(f'<div class="hint">hint {_e(r.hint)}</div>')
        for number, picture in enumerate((pictures or {}).get(r.id, ())):
            out.append(f'<div class="pic" id="{picture_id(index, r.id, number)}"><img alt="{_e(r.id)}: scene '
                       f'{_e(picture.scene)}" src="{picture.data_url}"></div>')
        out.append("</div>")
    out.append("</details>")
    return "\n".join(out)


def html_text(rows, pictures=None, title="Lesson 11 lab checker: class report"):
    """The whole report as one HTML document (str). pictures: {row path: {check id: [Picture]}}.

    Each file is named by its path below the files' common folder (as for --gradescope-dir).
    """
    pictures = pictures or {}
    names = submission_names([r.path for r in rows])
    graded = [r for r in rows if not isinstance(r, NotGraded)]
    means = "; ".join(f"{title}: {files} file(s), mean {100 * fraction:.0f} % of its points"
                      for title, (files, fraction) in lab_means(rows).items())
    parts = [
        "<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width,initial-scale=1">',
        f"<title>{_e(title)}</title><style>{CSS}</style></head><body>",
        f"<h1>{_e(title)}</h1>",
        f"<p>{len(rows)} file(s), {len(graded)} graded. {_e(_summary_line(rows))}</p>",
        f"<p>{_e(means or 'No lab files.')}</p>",
        "<h2>Where the class struggled: results per check</h2>", histogram(rows),
        "<h2>What the class got wrong: the mistakes named per check</h2>", mistakes_table(rows, names),
        "<h2>Files</h2><p>Click a heading to sort; click a file to see its checks, a check under pictures to see "
        "its picture.</p>", summary_table(rows, names, pictures),
        "<h2>Checks of each file</h2>",
    ]
    parts += [submission(row, k, pictures.get(row.path), names[row.path]) for k, row in enumerate(rows)]
    parts += [f"<script>{JS}</script>", "</body></html>", ""]
    return "\n".join(parts)


def write_html(rows, path, pictures=None):
    """Write html_text(rows, pictures) to path (atomically)."""
    write_atomic(path, html_text(rows, pictures))
