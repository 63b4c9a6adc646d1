"""aggloTools.runtimes: README.md's 'Run times' as the one statement of
each job's run time, the drivers' closing line against it, and the
READMEs kept free of a second statement, commit hashes and dates."""
import re

import pytest

from aggloTools import runner, runtimes

ROOT = runner.project_dir()

#: The jobs whose ids the drivers build at their defaults (the main job
#: on 2 cores, the tutorials' default and test presets, the test suite)
DRIVER_JOBS = ["verticalChannel small C1 -np 2",
               "verticalChannel small C1 -np 1",
               "verticalChannel smoke C1 C2 -np 1",
               "shearFlowValidation ci", "shearFlowValidation small",
               "shearFlowValidation small study",
               "breakupShear default", "breakupShear ci",
               "Alltest", 'Alltest -m "not legacy"']


def readme(tmp_path, rows):
    p = tmp_path.joinpath("README.md")
    p.write_text("# x\n\n## Run times\n\n| job | what | time |\n"
                 "|---|---|---|\n" + "".join(rows) + "\n## Next\n"
                 "| `ignored` | after the section | 1 h |\n")
    return p


def test_readme_table_states_every_driver_job():
    t = runtimes.table()
    missing = [j for j in DRIVER_JOBS if j not in t]
    assert not missing, f"README.md 'Run times' lacks {missing}"
    # the main job's figure is minutes, not seconds or hours
    assert 5 <= t["verticalChannel small C1 -np 2"] <= 60


def test_units_and_section_bounds(tmp_path):
    p = readme(tmp_path, ["| `a` | x | 25 s |\n", "| `b` | y | about"
                          " 3.5 min |\n", "| `c` | z | 14 h |\n"])
    assert runtimes.table(p) == {"a": 25 / 60, "b": 3.5, "c": 840.0}
    assert runtimes.stated("ignored", p) is None


@pytest.mark.parametrize("row,word", [
    ("| `a` | x | soon |\n", "no time"),
    ("| `a` | x | 3 weeks |\n", "no time"),
    ("| `a` | x | 1 h |\n| `a` | y | 2 h |\n", "twice")])
def test_bad_rows_are_errors(tmp_path, row, word):
    with pytest.raises(ValueError, match=word):
        runtimes.table(readme(tmp_path, [row]))


def test_verdict_bounds():
    f = runtimes.FACTOR
    assert "within" in runtimes.verdict(f * 10.0, 10.0)
    assert "out of date" in runtimes.verdict(f * 10.0 * 1.01, 10.0)
    assert "within" in runtimes.verdict(10.0 / f, 10.0)
    assert "faster" in runtimes.verdict(10.0 / f / 1.01, 10.0)
    with pytest.raises(ValueError):
        runtimes.verdict(0.0, 10.0)


def test_closing_line(tmp_path):
    p = readme(tmp_path, ["| `job` | x | 10 min |\n"])
    ok = runtimes.line("job", 12 * 60, readme=p)
    assert "12.0 min" in ok and "states 10.0 min" in ok \
        and "within" in ok
    assert "out of date" in runtimes.line("job", 40 * 60, readme=p)
    kept = runtimes.line("job", 40 * 60, whole=False, readme=p)
    assert "not compared" in kept and "out of date" not in kept
    assert "states no figure" in runtimes.line("other", 60, readme=p)


# --------------------------------------------- the READMEs' one statement

TIME = re.compile(r"(?i)(about|~|≈)\s*[0-9]+(\.[0-9]+)?\s*"
                  r"(s|min|minutes|h|hours)\b")


def sh_blocks(text):
    return re.findall(r"```sh\n(.*?)```", text, re.S)


def tutorial_readmes():
    """Each tutorial's README, by path."""
    return sorted(d.joinpath("README.md")
                  for d in ROOT.joinpath("tutorials").iterdir()
                  if d.joinpath("README.md").is_file())


def test_commands_state_no_second_run_time():
    """The tutorials' command blocks and every Allrun's header refer to
    'Run times' instead of stating a time of their own."""
    found = []
    for f in tutorial_readmes():
        for block in sh_blocks(f.read_text()):
            found += [f"{f.relative_to(ROOT)}: {m.group(0)}"
                      for m in TIME.finditer(block)]
    for f in [ROOT / "Allrun", *sorted(ROOT.glob("tutorials/*/Allrun"))]:
        head = [ln for ln in f.read_text().splitlines()[:30]
                if ln.startswith("#")]
        found += [f"{f.relative_to(ROOT)}: {m.group(0)}"
                  for ln in head for m in TIME.finditer(ln)]
    assert not found, found


HASH = re.compile(r"(?<![.\w])(?![0-9]+e[0-9]+\b)(?=[0-9a-f]*[0-9])"
                  r"(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}\b")
DATE = re.compile(r"\b20[0-9]{2}-[0-9]{2}-[0-9]{2}\b")


def test_hash_and_date_patterns():
    assert HASH.search("at commit 5877529a")
    assert HASH.search("(b1b0a97, 2 ranks)")
    assert not HASH.search("1316 s, 2,613 s, deadbee, 1234567, 1.1719e10,"
                           " 12345e10")
    assert DATE.search("sessions (2026-11-27 and 28)")


def test_readmes_hold_no_history():
    """README.md, the README.md of bench and the tutorials' READMEs state the
    current state: no commit hash, no date (CHANGELOG.md holds the
    history)."""
    files = [ROOT.joinpath("README.md"), ROOT.joinpath("bench", "README.md"),
             *tutorial_readmes()]
    found = []
    for f in files:
        for n, ln in enumerate(f.read_text().splitlines(), 1):
            found += [f"{f.relative_to(ROOT)}:{n}: {m.group(0)}"
                      for m in (*HASH.finditer(ln), *DATE.finditer(ln))]
    assert not found, found
    assert (ROOT / "CHANGELOG.md").is_file()
