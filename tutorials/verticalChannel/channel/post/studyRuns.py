"""verticalChannel: the regime study's C1 as a configuration of a
preset's report. The study (channel.regime, results/regime/regime.json)
ran C1 of its variants and committed their window's numbers; where a
preset's runs hold no C1 of their own (the study's folders were not
kept), its report takes C1's rows from the study's record of the same
preset, if that record was made with the settings the preset has now
(grid, step, particles, phases, window). What the record lacks is said,
not made up: no time histories or profiles (the runs' files), no
conservation check (done in the study's run), no binomial sigma of the
cumulative alpha at the end (its collision count is not recorded).

    res.update(study_runs(p, res))      # C1 of the study, where missing
"""

import json

from channel import TUTORIAL
from channel.case import settings
from channel.post import contacts
from aggloTools import uncertainty

#: The study's committed record
STUDY = TUTORIAL / "results" / "regime" / "regime.json"
MODELS = ("EAM", "MAM")


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
    the preset p's C1 runs would be now ([] if none)."""
    now = {"grid": list(p["n"]), "dtStar": p["dtStar"],
           "nParticles": p["nParticles"],
           "phases": [p[k] for k in ("unladen", "release", "dispersion",
                                     "agglomeration")],
           "window": [float(w) for w in p["window"]]}
    return sorted(k for k, v in now.items()
                  if [float(x) for x in _list(result.get(k))]
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
