"""Regression tables: rows (dicts) with a status PASS, FAIL, n/r (the band
cannot fail at this size: the reason goes with the row) or INFO
(reported, not judged), a fixed-width text table whose columns a
tutorial declares, and the counts behind its summary line.

    rows = [regression.row(check="K_first/K_ST", value=1.01, expected=1,
                           tolerance=0.1, ok=True)]
    cols = [regression.Column("check", "check", width=20),
            regression.Column("value", "value", 10, ">", number)]
    text = "\\n".join(regression.table(rows, cols))
"""

PASS, FAIL, NR, INFO = "PASS", "FAIL", "n/r", "INFO"


def status(ok, nr=None):
    """PASS/FAIL from ok; INFO when ok is None; n/r when a reason nr says
    why the band cannot fail."""
    return NR if nr else INFO if ok is None else PASS if ok else FAIL


def row(ok=None, nr=None, **fields):
    """A row: the fields in the given order, then its status (and the
    reason of an n/r row)."""
    out = dict(fields)
    out["status"] = status(ok, nr)
    if nr:
        out["reason"] = nr
    return out


def counts(rows):
    """Number of rows per status."""
    out = {PASS: 0, FAIL: 0, NR: 0, INFO: 0}
    for r in rows:
        out[r["status"]] += 1
    return out


class Column:
    """One column of a text table: its title, the row key it shows, its
    width and alignment ('<' or '>'), how a value is formatted, and the
    gap written before it (none before the first column)."""

    def __init__(self, title, key, width=0, align="<", fmt=str, gap=" "):
        self.title, self.key, self.width = title, key, width
        self.align, self.fmt, self.gap = align, fmt, gap

    def cell(self, text):
        return f"{text:{self.align}{self.width}}"


def table(rows, columns):
    """The header line and one line per row."""
    def line(cells):
        return "".join((c.gap if i else "") + c.cell(t)
                       for i, (c, t) in enumerate(zip(columns, cells)))
    out = [line([c.title for c in columns])]
    for r in rows:
        out.append(line([c.fmt(r.get(c.key)) for c in columns]))
    return out
