"""The break-up event log (stressThresholdCoeffs: eventLog true;
doc/eventLog.md) of a running cloud and its replay by breakupReplay:
agglomerates of 2-12 primaries in laminar shear above their critical
shear rate, with all three mechanisms, beta-distributed fragment sizes
and the stochastic rate, so that they break over several steps. The log
holds exactly the break-ups that the statistics count, by mechanism;
each record keeps the primaries, the mass and the momentum of its
parent; the run's kernel replayed reproduces every fragment bit for
bit; a stronger variant breaks exactly the logged break-ups whose
stress/strength exceeds its factor; a restart from a middle write
neither repeats nor loses a break-up; a corrupt or altered record is
caught."""

import json
import shutil

import numpy as np
import pytest

from aggloTools import boxcase, breakuplog
from aggloTools.runner import CommandError, foam_bin, run
from aggloTools.stats import stats_rows
from aggloTools.foamfile import edit
from breakupCases import (GAMMA_CRIT, H, L_C, N_C, NU_F, RHO_F, breakup,
                          kernel, size_density, tensile_strength)

STEPS, WRITE = 6, 2


def shear_case(case):
    """432 agglomerates of 2-12 CSM primaries in shear at 3 times the
    critical shear rate of N = 2 (the bonds weakened to give it), in
    |y - h/2| < 2 mm (a displacement per step below 2 mm), spinning at
    0.5-4 times gamma/2: most break by rotation first, their fragments
    then by turbulence (a share deferred by the stochastic rate, dt = t_K)
    and by drag, over six steps (2350 break-ups: 312 turbulence, 400
    drag, 1638 rotation)."""
    gamma = 3 * GAMMA_CRIT
    rng = np.random.default_rng(3)
    parts = []
    for i in range(12):
        for j in range(12):
            for k in range(3):
                n = int(rng.integers(2, 13))
                da, rho = size_density(n, "CSM")
                y = 3e-3 + 0.36e-3 * j
                parts.append(dict(
                    x=(0.4e-3 + 0.8e-3 * i, y, 0.8e-3 + 1.6e-3 * k),
                    U=(gamma * (y - L_C[1] / 2) + 1e-3 * rng.normal(),
                       0, 0), d=da, rho=rho, nPrimary=n,
                    omega=(0, 0, -gamma / 2 * rng.uniform(0.5, 4))))
    h_weak = H * GAMMA_CRIT * NU_F * RHO_F / tensile_strength(2, "CSM")
    brk = breakup({"mechanisms": ("turbulence", "drag", "rotation"),
                   "dissipation": "total", "Cv": 1, "Ci": 1, "Cd": 1,
                   "rotationFactor": 0.0625},
                  {"mode": "beta", "betaAlpha": 0.5}, drag=True,
                  rate={"model": "stochastic", "timeScale": "kolmogorov"},
                  eventLog=True)
    dt = 1 / gamma
    uw = gamma * L_C[1] / 2
    boxcase.box_case(case, L=L_C, n=N_C,
                     kinds=("cyclic", "wall", "cyclic"), particles=parts,
                     dt=dt, end_time=STEPS * dt, write_interval=WRITE,
                     nu=NU_F, rho_f=RHO_F,
                     wall_velocity={"yMin": (-uw, 0, 0),
                                    "yMax": (uw, 0, 0)},
                     hard_sphere=kernel(h_weak), cloud=brk,
                     write_format="binary")
    boxcase.write_internal_U(case, L_C, N_C,
                             lambda x, y, z: (gamma * (y - L_C[1] / 2), 0,
                                              0))
    return case


def mass(ev, k):
    return ev[f"rho_{k}"] * np.pi / 6 * ev[f"d_{k}"] ** 3


def test_log_replay_restart_and_corruption(case_dir, foam_env):
    case = shear_case(case_dir / "run")
    boxcase.run_case(case)
    ev = breakuplog.read_breakup_events(case)
    head = breakuplog.header(case)
    ratio = breakuplog.values(ev, head)["ratio"]

    # The header names the model, its mechanisms and its values
    assert head == {"mechanisms": ("turbulence", "drag", "rotation",
                                   "wallImpact"),
                    "model": ("stressThreshold",),
                    "fields": ("ratio", "sigmaT")}
    assert np.all(ev["values"][:, 2:] == 0)

    # The log holds the counted break-ups, by mechanism, over several steps
    last = stats_rows(case)[-1]                     # counts since start
    for m, name in enumerate(("Turbulence", "Drag", "Rotation",
                              "WallImpact")):
        assert np.sum(ev["mechanism"] == m) == last[f"nBreakup{name}"], name
    assert len(ev) > 100
    assert len(np.unique(ev["timeIndex"])) >= 3
    assert np.sum(ev["mechanism"] == 0) > 0

    # Each record: the parent's primaries, mass and momentum in the
    # fragments, a fragment id handed out once, a stress above strength
    assert np.all(ev["nPrimary_a"] + ev["nPrimary_b"] == ev["nPrimary_p"])
    assert np.all((ev["nPrimary_a"] >= 1) & (ev["nPrimary_b"] >= 1))
    m_p, m_a, m_b = mass(ev, "p"), mass(ev, "a"), mass(ev, "b")
    assert np.allclose(m_a + m_b, m_p, rtol=1e-12, atol=0)
    P = m_a[:, None] * ev["U_a"] + m_b[:, None] * ev["U_b"]
    scale = sum(m * np.linalg.norm(ev[f"U_{k}"], axis=1)
                for m, k in ((m_p, "p"), (m_a, "a"), (m_b, "b")))
    assert np.all(np.linalg.norm(P - m_p[:, None] * ev["U_p"], axis=1)
                  <= 1e-12 * scale)
    assert np.all(ev["newProc"] == -2)
    assert len(np.unique(ev["newId"])) == len(ev)
    assert np.all(ratio > 1)

    # The run's kernel reproduces every logged break-up; a variant whose
    # stresses are all halved breaks exactly those with stress/strength
    # > 2 (halving is exact in floating point; the mechanism of the
    # largest ratio stays, so do the rate's keyed draws)
    k = 2
    half = {"Cv": 0.5, "Ci": 0.5, "Cd": 0.5, "rotationFactor": 0.03125}
    res = breakuplog.replay_breakups(
        case, {"halfStress": {"stresses": half}}, check=True)
    run_, strong = res["configurations"]
    assert res["events"] == len(ev)
    assert run_["reproduced"] == len(ev) and run_["breaks"] == len(ev)
    assert run_["byMechanism"] == [int(np.sum(ev["mechanism"] == m))
                                   for m in range(4)]
    assert strong["breaks"] == int(np.sum(ratio > k))
    assert 0 < strong["breaks"] < len(ev)

    # Variants that switch a mode or a mechanism off, dropping the run's
    # entries that only the mode or mechanism accepts (both aborted the
    # replay): binary sizes break the same parents (sizes do not enter
    # the verdict); without drag, the others keep their mechanism and
    # the drag break-ups break by another mechanism or not at all
    n_drag = int(np.sum(ev["mechanism"] == 1))
    assert n_drag > 0
    res = breakuplog.replay_breakups(case, {
        "binary": {"fragmentation": {"mode": "binary"},
                   "remove": "(fragmentation.betaAlpha)"},
        "noDrag": {"stresses": {"mechanisms": "(turbulence rotation)"},
                   "remove": "(stresses.Cd)"}})
    _, binary, no_drag = res["configurations"]
    assert binary["breaks"] == len(ev)
    assert binary["byMechanism"] == run_["byMechanism"]
    assert no_drag["byMechanism"][1] == 0
    assert no_drag["breaks"] - no_drag["mechanismChanged"] \
        == len(ev) - n_drag
    # a path the run's coefficients do not have is refused, naming the
    # variants file
    with pytest.raises(CommandError):
        breakuplog.replay_breakups(
            case, {"bad": {"remove": "(fragmentation.betaAlfa)"}})
    text = (case / "log.breakupReplay").read_text()
    assert "remove names fragmentation.betaAlfa" in text
    assert "variants" in text

    # A restart from the middle write: the log cut back to it and
    # continued gives the same records, byte for byte
    log = breakuplog.folder(case) / "events0.bin"
    whole = log.read_bytes()
    again = case_dir / "restart"
    shutil.copytree(case, again)
    for t in sorted((p for p in again.iterdir()
                     if p.name.replace(".", "").replace("e-", "")
                     .isdigit()), key=lambda p: float(p.name)):
        if float(t.name) > 2.5 / (3 * GAMMA_CRIT):
            shutil.rmtree(t)
    run([foam_bin("aggloPimpleFoam")], again, "log.restart")
    assert "events after it removed" in (again / "log.restart").read_text()
    assert (breakuplog.folder(again) / "events0.bin").read_bytes() == whole

    def edited(edit):
        """The log's records after edit(records), resealed: read as a
        run's records (the checksum matches)."""
        recs = np.frombuffer(whole, breakuplog.DTYPE,
                             offset=breakuplog.HEADER_BYTES).copy()
        edit(recs)
        return whole[:breakuplog.HEADER_BYTES] \
            + breakuplog.seal(recs).tobytes()

    # Any altered byte of a record is caught by its checksum: the last
    # bit of U_a.x, a time step, a drag force the rotation verdict does
    # not use, a strain rate 6 % off (each passed -check before)
    for field, index, factor in (("U_a", 0, None), ("dt", None, 2.0),
                                 ("dragForce", 0, 1.5), ("S", 1, 1.06)):
        recs = np.frombuffer(whole, breakuplog.DTYPE,
                             offset=breakuplog.HEADER_BYTES).copy()
        col = recs[field]
        k = int(np.argmax(np.abs(col if index is None else col[:, index])
                          > 0))
        if factor is None:
            raw = bytearray(recs.tobytes())
            raw[k * breakuplog.DTYPE.itemsize
                + breakuplog.DTYPE.fields[field][1]] ^= 0x01
            data = whole[:breakuplog.HEADER_BYTES] + bytes(raw)
        else:
            at = k if index is None else (k, index)
            col[at] = col[at] * factor if col[at] != 0 else 1e-15
            data = whole[:breakuplog.HEADER_BYTES] + recs.tobytes()
        log.write_bytes(data)
        with pytest.raises(ValueError, match=f"record {k}: checksum"):
            breakuplog.read_breakup_events(case)
        res = run([foam_bin("breakupReplay"), "-check"], case,
                  "log.breakupReplay.check", check=False)
        assert res.returncode == 1, field
        assert f"record {k}: checksum" in res.stdout, res.stdout[-1500:]

    # An altered fragment in a resealed record: the replay reports it
    # as not reproduced, and -check fails
    def flip(recs):
        recs["U_a"][0, 0] = np.nextafter(recs["U_a"][0, 0], np.inf)
    log.write_bytes(edited(flip))
    with pytest.raises(CommandError):
        breakuplog.replay_breakups(case, check=True)
    res = breakuplog.replay_breakups(case)
    assert res["configurations"][0]["reproduced"] == len(ev) - 1

    # A corrupt mechanism code: both readers refuse the file, naming it
    rec = bytearray(whole)
    rec[breakuplog.HEADER_BYTES + 4] = 7
    log.write_bytes(bytes(rec))
    with pytest.raises(ValueError, match="mechanism 7"):
        breakuplog.read_breakup_events(case)
    with pytest.raises(CommandError):
        breakuplog.replay_breakups(case)
    assert "record 0: mechanism 7 (valid: 0-3)" in \
        (case / "log.breakupReplay").read_text()
    out = json.loads((breakuplog.folder(case)
                      / "breakupReplay.json").read_text())
    assert out["configurations"][0]["reproduced"] == len(ev) - 1

    # A log with more or fewer events than the run recorded is refused:
    # two runs appending to one log, a log emptied to its header
    for bad, words in ((whole + whole[breakuplog.HEADER_BYTES:],
                        "more than one run appended"),
                       (whole[:breakuplog.HEADER_BYTES],
                        "cut back or emptied")):
        log.write_bytes(bad)
        res = run([foam_bin("breakupReplay"), "-check"], case,
                  "log.breakupReplay.count", check=False)
        assert res.returncode == 1, res.stdout[-1500:]
        n = (len(bad) - breakuplog.HEADER_BYTES) // breakuplog.DTYPE.itemsize
        assert f"holds {n} events, but the run recorded {len(ev)}" \
            in res.stdout
        assert words in res.stdout
    log.write_bytes(whole)
    assert run([foam_bin("breakupReplay"), "-check"], case,
               "log.breakupReplay.count").returncode == 0

    # -json onto a file that is not an earlier replay output (another
    # log: a collision event log) is refused and leaves it as it was
    other = case / "events0.bin"
    other.write_bytes(b"aggloCollisionEvents 2 recordBytes 220" + bytes(300))
    res = run([foam_bin("breakupReplay"), "-json", str(other)], case,
              "log.breakupReplay.json", check=False)
    assert res.returncode == 1
    assert "is not an earlier output of -json" in res.stdout
    assert other.read_bytes().startswith(b"aggloCollisionEvents 2")
    assert len(other.read_bytes()) == 338

    # Finite but absurd load values, resealed, are refused by name
    # (breakupReplay died by SIGFPE, rc 136, on eps, nu or a strain rate
    # of 1e300), and so is a value in a slot the header does not name
    for field, index, value in (("epsilon", None, 1e300),
                                ("nu", None, 1e300), ("nu", None, 1e-300),
                                ("S", 1, 1e300), ("S", 0, 3e296),
                                ("dt", None, 1e300), ("values", 2, 0.5)):
        def put(recs):
            if index is None:
                recs[field][0] = value
            else:
                recs[field][0, index] = value
        log.write_bytes(edited(put))
        res = run([foam_bin("breakupReplay")], case,
                  "log.breakupReplay.bounds", check=False)
        assert res.returncode == 1, (field, res.returncode)
        assert "record 0:" in res.stdout, res.stdout[-1500:]
        assert {"dt": "time step", "values": "the model's values"}.get(
            field, "load:") in res.stdout
    log.write_bytes(whole)

    # With the log switched off, a restart from the first write is
    # refused: the log holds this run's later break-ups
    from aggloTools.times import time_dirs
    off = case_dir / "logOff"
    shutil.copytree(case, off)
    first = time_dirs(off)[1].name
    for t in time_dirs(off)[2:]:
        shutil.rmtree(t)
    later = int((ev["timeIndex"] > WRITE).sum())
    assert 0 < later < len(ev)
    f = off / "constant" / "kinematicCloudProperties"
    edit(f, " eventLog true;", "", 1)
    res = run([foam_bin("aggloPimpleFoam")], off, "log.logOff",
              check=False)
    assert res.returncode != 0, res.stdout[-1500:]
    assert f"holds {later} events after time {first}" in res.stdout
    assert "break-up-event log" in res.stdout


def test_variants_named_twice_or_wrong(case_dir, foam_env):
    """breakupReplay -variants: a variant name given twice is refused
    (the later one replaced the earlier silently); a variant's bad entry
    is reported under the variants file's name, not the cloud's."""
    case = shear_case(case_dir / "run")
    boxcase.run_case(case)
    v = case / "variants"
    v.write_text('a { strength { rumpfPrefactor 1.0; } }\n'
                 'a { strength { rumpfPrefactor 1.1; } }\n')
    res = run([foam_bin("breakupReplay"), "-variants", str(v)], case,
              "log.twice", check=False)
    assert res.returncode == 1
    assert "duplicate entry: a" in res.stdout
    assert f"{v} at line 2" in res.stdout
    v.write_text('b { strength { rumpfPrefactor 5; } }\n')
    res = run([foam_bin("breakupReplay"), "-variants", str(v)], case,
              "log.range", check=False)
    assert res.returncode == 1
    fatal = (res.stdout).split("FOAM FATAL", 1)[1]
    assert "rumpfPrefactor" in fatal and str(v) in fatal, fatal[:1500]
