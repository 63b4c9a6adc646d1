"""aggloTools.regression (status vocabulary, fixed-width tables, counts)
and aggloTools.progress (the progress line of a running solver) against
hand-made inputs with known answers."""

import pytest

from aggloTools import progress, regression as reg


def test_status_and_counts():
    rows = [reg.row(True, check="a"), reg.row(False, check="b"),
            reg.row(None, check="c"), reg.row(True, "3 sigma reach 0",
                                              check="d")]
    assert [r["status"] for r in rows] == ["PASS", "FAIL", "INFO", "n/r"]
    assert rows[3]["reason"] == "3 sigma reach 0" and "reason" not in rows[0]
    assert reg.counts(rows) == {"PASS": 1, "FAIL": 1, "n/r": 1, "INFO": 1}
    assert list(rows[0]) == ["check", "status"]


def test_table_columns():
    cols = [reg.Column("name", "q", 6),
            reg.Column("value", "v", 8, ">", lambda v: f"{v:.3g}"),
            reg.Column("note", "n", gap="  ")]
    lines = reg.table([{"q": "abc", "v": 1.23456, "n": "x"},
                       {"q": "toolongname", "v": 2e-7, "n": ""}], cols)
    assert lines == ["name      value  note",
                     "abc        1.23  x",
                     "toolongname    2e-07  "]


def write_log(path, times, clock, restart_at=None):
    """A solver log whose steps end at the wall-clock times `clock`; the
    CPU time (ExecutionTime) is a third of it, as on a loaded machine."""
    text = "Starting time loop\n"
    for i, (t, c) in enumerate(zip(times, clock)):
        if restart_at is not None and i == restart_at:
            text += "End\n\nStarting time loop\n"
        text += (f"Time = {t:g}\n\nExecutionTime = {c / 3:g} s  "
                 f"ClockTime = {c:g} s\n")
    path.write_text(text)


def test_solver_progress_fraction_and_eta(tmp_path):
    log = tmp_path / "log.aggloPimpleFoam"
    assert progress.solver_progress(log, 1.0, 0.1) is None
    # 4 of 10 steps done in 8 s of the clock: 6 steps left at 2 s each
    # (the CPU time would say 4 s)
    write_log(log, [0.1, 0.2, 0.3, 0.4], [2, 4, 6, 8])
    t, frac, eta = progress.solver_progress(log, 1.0, 0.1)
    assert t == pytest.approx(0.4) and frac == pytest.approx(0.4)
    assert eta == pytest.approx(12.0)
    assert progress.line(frac, eta) == "(40 % of this run, ETA 0m12s)"
    # a restarted run counts from its own start (t = 0.2 -> 1.0)
    write_log(log, [0.1, 0.2, 0.3, 0.4, 0.5, 0.6], [2, 4, 1, 2, 3, 4],
              restart_at=2)
    t, frac, eta = progress.solver_progress(log, 1.0, 0.1)
    assert frac == pytest.approx(0.5) and eta == pytest.approx(4.0)
    assert progress.hms(3725) == "1h02m"
