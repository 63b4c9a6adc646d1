"""verticalChannel: the regime study's C1 as a configuration of a
preset's report. The study (channel.regime, results/regime/regime.json)
ran C1 of its variants and committed their window's numbers; where a
preset's runs hold no C1 of their own (the study's folders were not
kept), its report takes C1's rows from the study's record of the same
preset, if that record was made with the settings the preset has now
(grid, step, particles, phases, window, the velocity tolerance). What
the record lacks is said, not made up: no time histories or profiles
(the runs' files), no conservation check (done in the study's run), no
binomial sigma of the cumulative alpha at the end (its collision count
is not recorded).

    res.update(study_runs(p, res))      # C1 of the study, where missing
    rows += record_rows(R, p, res)      # C1's own run against the record

Where the preset has a C1 run of its own and the study a record of it
made with the same settings, the report compares the two (record_rows):
the same physics and settings repeat the study's numbers (a one-way
cloud's run is deterministic, and so is the LES it sees).
"""

import json
import math

from channel import TUTORIAL
from channel.case import settings
from channel.post import contacts
from aggloTools import regression as reg
from aggloTools import uncertainty

#: The study's committed record
STUDY = TUTORIAL / "results" / "regime" / "regime.json"
MODELS = ("EAM", "MAM")
#: The velocity solver's tolerance of a record that does not name its own:
#: every run of the study solved U to 1e-8 (README.md, 'The regime study';
#: its presets' UTolerance), and its first records predate the entry
STUDY_U_TOLERANCE = 1e-8


def study_record(name, path=STUDY):
    """The study's result of the variant `name` (None where the study has
    none or has not finished it)."""
    if not path.is_file():
        return None
    for v in json.loads(path.read_text()).get("variants", []):
        if v.get("name") == name and v.get("result"):
            return v
    return None


def same_settings(p, result):
    """The entries in which the study's result was made otherwise than
    the preset p's C1 runs would be now ([] if none). The velocity
    solver's tolerance counts: a run at another tolerance is another
    flow, so another run (a record without the entry was made at the
    study's STUDY_U_TOLERANCE)."""
    now = {"grid": list(p["n"]), "dtStar": p["dtStar"],
           "nParticles": p["nParticles"],
           "phases": [p[k] for k in ("unladen", "release", "dispersion",
                                     "agglomeration")],
           "window": [float(w) for w in p["window"]],
           "UTolerance": p["UTolerance"]}
    made = dict(result)
    made.setdefault("UTolerance", STUDY_U_TOLERANCE)
    return sorted(k for k, v in now.items()
                  if [float(x) for x in _list(made.get(k))]
                  != [float(x) for x in _list(v)])


def _list(v):
    return v if isinstance(v, list) else [v]


def from_study(p, variant, m):
    """A run's record (postprocess.analyse_run's keys the regression and
    the summary read) of model m of the study's C1 of `variant`."""
    res = variant["result"]
    x = res["models"][m]
    s2 = res["scale_s2"]
    r = {"case": f"{STUDY.relative_to(TUTORIAL)} (the regime study's C1"
                 f" of {variant['name']}; its run folder not kept)",
         "cloud": m, "fromStudy": True,
         "nParticles": res["nParticles"], "scale": s2,
         "f_col_scaled": x["f_col_scaled"],
         "f_agg_scaled": x["f_agg_scaled"],
         "f_col": x["f_col_scaled"] / s2, "f_agg": x["f_agg_scaled"] / s2,
         "sigma_col": x["sigma_col"], "sigma_agg": x["sigma_agg"],
         "events_col": x["events_col"], "events_agg": x["events_agg"],
         "alpha_f": x["alpha_f"],
         # the window ends with the stage at the study's presets
         "alpha_end": x["alpha_end_of_phase"], "N_col_end": None,
         "nProcs": None}
    near = (x.get("contacts") or {}).get("byWallDistance")
    if near and near["edges"][1] == contacts.NEAR_WALL and sum(near["n"]):
        n = sum(near["n"])
        r["nearWallShare"] = near["n"][0] / n
        r["nearWallSigma"] = uncertainty.binomial_sigma(near["n"][0], n)
    ut = (res.get("u_tau_over_U_B") or {}).get("agglomeration")
    if ut:
        r["uTau"] = ut * p["Ubar"]
    return r


def study_runs(p, have, path=STUDY):
    """(C1, model) -> record from the study for the models of p whose C1
    is not in `have` (the preset's own runs); {} where the study has no
    finished C1 of this preset. A record made with other settings than
    the preset's is refused (SystemExit naming the entries): its numbers
    would pass for this preset's."""
    missing = [m for m in p["models"] if ("C1", m) not in have]
    variant = study_record(p["name"], path) if missing else None
    if variant is None:
        return {}
    pc = settings.preset(p["name"], "C1")
    differ = same_settings(pc, variant["result"])
    if differ:
        raise SystemExit(
            f"channel.post: {path} holds C1 of {p['name']} made with other"
            f" {' '.join(differ)} than presets/{p['name']} has now: run"
            f" C1 (./Allrun -preset {p['name']} -configs C1) or restore"
            " the preset")
    return {("C1", m): from_study(pc, variant, m) for m in missing
            if m in variant["result"]["models"]}


def record_rows(R, p, res, path=STUDY):
    """Rows comparing the preset's own C1 runs in res with the study's
    record of the preset (f_col x s^2, f_agg x s^2, per model): PASS
    where they agree within 2 sigma (identical, or the note gives z),
    FAIL beyond; n/r where the record was made with other settings than
    the preset has now (not comparable); no rows without an own C1 run
    or a record."""
    own = {m: res[("C1", m)] for m in MODELS if ("C1", m) in res
           and not res[("C1", m)].get("fromStudy")}
    variant = study_record(p["name"], path) if own else None
    if variant is None:
        return []
    differ = same_settings(settings.preset(p["name"], "C1"),
                           variant["result"])
    rows = []
    for m, r in sorted(own.items()):
        x = variant["result"]["models"].get(m)
        if x is None:
            continue
        for q in ("col", "agg"):
            name = f"C1 {m} f_{q} x s^2: own run / the study's record"
            if differ:
                rows.append(R(name, None, None, None, None, reg.NR,
                              "the record was made with other "
                              f"{' '.join(differ)}: not comparable"))
                continue
            a, b = r[f"f_{q}_scaled"], x[f"f_{q}_scaled"]
            sa = r[f"sigma_{q}"] * r["scale"]
            sb = x[f"sigma_{q}_scaled"]
            s = math.hypot(sa, sb)
            if a == b:
                status, note = reg.PASS, "identical: the record repeated"
            else:
                z = (a - b) / s if s > 0 else math.inf
                status = reg.status(abs(z) <= 2)
                note = (f"{a:.6g} against {b:.6g}, z {z:+.2f} (within 2 "
                        "sigma: the same statistics, not the same run)"
                        if abs(z) <= 2 else f"{a:.6g} against {b:.6g}, "
                        f"z {z:+.2f}: the physics or the settings changed"
                        " since the record was made")
            ratio = a / b if b else None
            sr = (ratio * math.hypot(sa / a if a else 0, sb / b)
                  if ratio is not None else None)
            rows.append(R(name, ratio, sr, None, None, status, note))
    return rows
