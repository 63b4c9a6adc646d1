"""shearFlowValidation: the runs of the tutorial and the entries of their
system/caseSettings, what the set-up (shear.case.settings) writes and
the post-processing (shear.post, shear.post.replay, shear.study) reads."""

from aggloTools import casesettings, eventlog

from shear import theory

#: The runs of a preset: detect (ghost contacts), EAM, MAM and the optional
#: bounce (physical rebounds without agglomeration)
RUNS = ("detect", "EAM", "MAM", "bounce")

#: The entries of a run's caseSettings
SETTINGS_KEYS = {"preset", "run", "gammaDot", "delta", "yMin", "uWall",
                 "uLower", "Lx", "Lz", "nx", "ny", "nz", "nParticles",
                 "dParticle", "seed", "deltaT", "endTime", "writeInterval",
                 "countFrom", "agglomerationModel", "collisionResponse",
                 "eventLog", "rotationModel", "overlapTreatment",
                 "kernelCoeffs"}


def read_settings(case):
    """The caseSettings of a run, every entry checked; kernelCoeffs holds
    only the <model>Coeffs of the run's own model (the set-up writes no
    other: an entry such as agglomerationModel there would override the
    run's model unseen)."""
    s = casesettings.read_settings(case, SETTINGS_KEYS)
    kc = s.get("kernelCoeffs", {})
    allowed = {f"{s['agglomerationModel']}Coeffs"}
    if not isinstance(kc, dict) or set(kc) - allowed:
        raise SystemExit(f"{case}/system/caseSettings: kernelCoeffs may "
                         f"hold only {' '.join(sorted(allowed))}, not "
                         f"{' '.join(sorted(set(kc) - allowed)) or kc!r}")
    return s


def logged_runs(runs_dir, script):
    """The runs under runs_dir that have a collision-event log, the
    settings of the first and van de Ven & Mason's alpha_th for them;
    None (and a line saying so) without logs."""
    runs = [r for r in RUNS if eventlog.folder(runs_dir / r).is_dir()]
    if not runs:
        print(f"{script}: no collision event logs under {runs_dir}")
        return None
    s = read_settings(runs_dir / runs[0])
    a_th = float(theory.alpha_th(float(s["dParticle"]),
                                    float(s["gammaDot"])))
    return runs, s, a_th
