"""aggloTools.stages: a driver's options refused in the Allrun words with
exit status 1; a failing command or a solver whose log lacks End raises;
the pool runs every item, up to jobs at a time, and returns the failed
ones; SIGINT to a driver stops its whole process tree and exits 130
without running what follows."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import shutil

import pytest

from aggloTools import stages
from aggloTools.cloud import read_cloud
from aggloTools.runner import foam_bin, run
from aggloTools.times import time_dirs
from aggloTools.runner import CommandError


def parse(argv):
    p = stages.Parser("t", "doc")
    p.add_argument("-preset", default="small")
    p.add_argument("-j", type=stages.positive("-j"), default=1)
    return p.parse_args(argv)


@pytest.mark.parametrize("argv, words", [
    (["-preset"], "Allrun: -preset needs a value"),
    (["-j", "0"], "-j '0' is not a positive number"),
    (["-j", "x"], "-j 'x' is not a positive number"),
    (["-bogus"], "unknown option -bogus"),
])
def test_refused_options(argv, words, capsys):
    with pytest.raises(SystemExit) as e:
        parse(argv)
    assert e.value.code == 1
    assert words in capsys.readouterr().err


def test_accepted_options():
    a = parse(["-preset", "ci", "-j", "3"])
    assert (a.preset, a.j) == ("ci", 3)


def test_run_logged_and_solver(tmp_path):
    stages.run_logged([sys.executable, "-c", "print('hello')"], tmp_path,
                      "log.hello")
    assert (tmp_path / "log.hello").read_text() == "hello\n"
    with pytest.raises(CommandError, match="failed"):
        stages.run_logged([sys.executable, "-c", "raise SystemExit(3)"],
                          tmp_path, "log.fail")
    # a solver log without End: did not finish
    with pytest.raises(CommandError, match="did not finish"):
        stages.run_solver(tmp_path, [sys.executable, "-c", "print(1)"],
                          "x", lambda c: "", 60)
    lines = []
    wall = stages.run_solver(
        tmp_path, [sys.executable, "-c",
                   "import time; time.sleep(1.2); print('End')"],
        "x", lambda c: lines.append(c) or "p", 0.5, append=True)
    assert 1 <= wall < 30
    assert len(lines) >= 1            # at least one progress line
    assert (tmp_path / "log.aggloPimpleFoam").read_text().endswith(
        "1\nEnd\n")                   # appended to the first run's log


@pytest.mark.parametrize("options", [[], ["--oversubscribe"]])
def test_solver_on_ranks_named(tmp_path, capsys, options):
    """A solver run through mpirun is announced by its name and ranks,
    with or without mpirun's own options before it (with them, the
    option was taken for the solver's name)."""
    mpirun = tmp_path / "mpirun"
    mpirun.write_text("#!/bin/sh\necho End\n")
    mpirun.chmod(0o755)
    stages.run_solver(tmp_path, [str(mpirun), "-np", "2", *options,
                                 "/opt/bin/aggloPimpleFoam", "-parallel"],
                      "x", lambda c: "", 60)
    assert f"Running aggloPimpleFoam (2 processes) on {tmp_path}" in \
        capsys.readouterr().out


def test_pool_collects_the_failures():
    done = []

    def work(i):
        if i % 3 == 0:
            raise CommandError("no")
        done.append(i)
    assert sorted(stages.pool(range(7), work, 2)) == [0, 3, 6]
    assert sorted(done) == [1, 2, 4, 5]


def test_sigint_stops_the_tree_and_exits_130(tmp_path):
    marker = tmp_path / "after"
    child = tmp_path / "child.pid"
    driver = tmp_path / "driver.py"
    driver.write_text(textwrap.dedent(f"""
        import sys
        from aggloTools import stages
        def main():
            stages.run_logged(["bash", "-c",
                               "echo $$ > {child}; sleep 60 & wait"],
                              "{tmp_path}", "log.sleep")
            open("{marker}", "w").write("ran")
            return 0
        sys.exit(stages.interruptible(main))
    """))
    proc = subprocess.Popen([sys.executable, str(driver)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    t0 = time.time()
    while not child.exists() or not child.read_text().strip():
        assert time.time() - t0 < 30
        time.sleep(0.1)
    bash = int(child.read_text())
    os.kill(proc.pid, signal.SIGINT)      # the driver only, not its group
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, out + err
    assert "interrupted" in err
    assert not marker.exists()
    time.sleep(0.5)
    with pytest.raises(ProcessLookupError):
        os.kill(bash, 0)


def test_decompose_takes_the_latest_folder_by_name(raised_digits, case_dir):
    """A case branched at a folder OpenFOAM v1912 does not find by itself
    (16.333317, timePrecision 2) decomposes onto 2 ranks with its fields
    and every particle; plain decomposePar writes none of them and
    succeeds."""
    case = case_dir / "branch"
    shutil.copytree(raised_digits, case)
    for t in time_dirs(case):
        if t.name != "16.333317":
            shutil.rmtree(t)
    for entry, value in (("numberOfSubdomains", "2"), ("coeffs/n", "(2 1 1)")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/decomposeParDict"], case, "log.foamDictionary")
    run([foam_bin("decomposePar"), "-force"], case, "log.plain")
    assert not (case / "processor0" / "16.333317").exists()
    stages.decompose(case)
    ids = []
    for proc in ("processor0", "processor1"):
        assert (case / proc / "16.333317" / "U").is_file(), proc
        if (case / proc / "16.333317" / "lagrangian").is_dir():
            ids += list(read_cloud(case / proc, "16.333317",
                                   names=["origId"])["origId"])
    assert sorted(ids) == [0, 1, 2]


def test_decomposition_cut_off_is_done_again(raised_digits, case_dir):
    """A decomposePar killed half-way leaves processor0 behind: the
    driver took the folders for complete and never decomposed again
    ('1077 particles read, but 2100 were written'). A case counts as
    decomposed only by the marker written after decomposePar succeeded;
    a failed decomposition removes it."""
    case = case_dir / "cut"
    shutil.copytree(raised_digits, case)
    for entry, value in (("numberOfSubdomains", "2"), ("coeffs/n", "(2 1 1)")):
        run([foam_bin("foamDictionary"), "-entry", entry, "-set", value,
             "system/decomposeParDict"], case, "log.foamDictionary")
    (case / "processor0").mkdir()            # what the kill left
    assert not stages.decomposed(case)
    stages.decompose(case)
    assert stages.decomposed(case)
    assert (case / stages.DECOMPOSED).read_text() == "2\n"
    run([foam_bin("foamDictionary"), "-entry", "numberOfSubdomains", "-set",
         "3", "system/decomposeParDict"], case, "log.foamDictionary")
    with pytest.raises(CommandError):
        stages.decompose(case)                # 3 subdomains, (2 1 1)
    assert not stages.decomposed(case)
