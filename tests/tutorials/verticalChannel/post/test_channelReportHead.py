"""tutorials/verticalChannel: the report's head computed from the run's own
numbers (channel.post.report.resolves: sim/paper factors against Table D.6,
the share of the window's contacts at the walls, the verdict by the
regime study's factor 2), the near-wall share of a window's contacts
(channel.post.contacts), and the comparison's line on the ranks of the run and
of the reference."""
import numpy as np
import pytest

from channelTestRuns import script

reg = script("channel.post.report")
contacts = script("channel.post.contacts")
D6 = reg.TABLE_D6["C1"]


def run(m, fcol_factor, alpha_factor, near=None):
    """A run whose C1 values are the given factors of Table D.6's."""
    fcol = D6["fcol"][m]
    alpha = D6["fagg"][m] / fcol
    return {"f_col_scaled": fcol_factor * fcol,
            "alpha_f": alpha_factor * alpha if alpha_factor else None,
            "nearWallShare": near}


def preset(name):
    return {"name": name}


def test_factors_and_verdict_far_from_the_paper():
    res = {("C1", "EAM"): run("EAM", 0.04, 48.0, 0.12),
           ("C1", "MAM"): run("MAM", 0.055, 44.0, 0.2)}
    text = reg.resolves(preset("small"), res)
    assert "C1 f_col x s^2 0.04-0.055 of Table D.6" in text
    assert "alpha_f 44-48 times" in text
    assert "12-20 % of the window's collisions within 0.02 delta" in text
    assert "worst factor 48, so not the paper's regime" in text


def test_verdict_near_the_paper():
    res = {("C1", "EAM"): run("EAM", 0.61, 2.0 * 0.999, 0.83),
           ("C1", "MAM"): run("MAM", 0.62, 1.5, 0.82)}
    text = reg.resolves(preset("regime64"), res)
    assert "within a factor 2 of the paper on all of them" in text
    # one quantity just outside the factor: the verdict turns
    res[("C1", "EAM")] = run("EAM", 0.61, 2.0 * 1.001, 0.83)
    text = reg.resolves(preset("regime64"), res)
    assert "worst factor 2, outside the factor 2" in text


def test_without_agglomeration_or_log_not_judged():
    res = {("C2", "EAM"): run("EAM", 0.2, None)}
    res[("C2", "EAM")]["f_col_scaled"] = 0.2 * reg.TABLE_D6["C2"]["fcol"][
        "EAM"]
    text = reg.resolves(preset("small"), res)
    assert text.startswith("C2 f_col x s^2 0.2 of Table D.6")
    assert "no agglomeration in a window" in text
    assert "no event log" in text
    assert text.endswith("not judged against the paper's regime")
    assert reg.resolves(preset("small"), {("R80", "EAM"): {}}) == \
        "no configuration with published values has run"


def test_near_wall_share_against_a_count():
    rng = np.random.default_rng(3)
    yw = rng.uniform(0, 1, 400)
    share, sigma = contacts.near_wall_share({"n": 400, "_yw": yw})
    k = int((yw < contacts.NEAR_WALL).sum())
    assert share == k / 400
    assert sigma == pytest.approx(np.sqrt(max(share * (1 - share),
                                              1 / 400) / 400))
    assert contacts.near_wall_share({"n": 0}) == (None, None)
    assert contacts.near_wall_share(None) == (None, None)


def test_ranks_line():
    serial = {"C1 EAM": {"nProcs": 1}, "C1 MAM": {"nProcs": 1}}
    two = {"C1 EAM": {"nProcs": 2}}
    assert reg.ranks(serial) == "serial" and reg.ranks(two) == "2 ranks"
    assert reg.ranks({"C1 EAM": {}}) == "unknown ranks"
    assert reg.ranks({**serial, **{"C2 EAM": {"nProcs": 2}}}) == \
        "mixed ranks 1/2"
    line = reg.same_run_line(reg.ranks(two), reg.ranks(serial))
    assert "This run: 2 ranks; the reference: serial." in line
    assert "another sample" in line
    assert "repeat exactly" in reg.same_run_line("serial", "serial")
