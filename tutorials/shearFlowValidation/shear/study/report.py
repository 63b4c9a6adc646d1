"""shearFlowValidation: the sensitivity study's report (the result of
study.post): study.txt, the runs' counts and alphas, the paper's
statements per variant, the diagnosis of where the models part, and
study.png."""

import numpy as np

from aggloTools import regression as reg

from shear.post import statements


def _f(v, fmt=".3g"):
    return "-" if v is None else format(v, fmt)


def study_table(res, models, diagnosed):
    """study.txt from post's result; models: the runs' models in
    order, diagnosed: the variant of each diagnosis tag."""
    a_th = res["alpha_th"]
    runs = [dict(variant=v["name"], model=m, **v[m]) for v in
            res["variants"] for m in models]
    cols = [reg.Column("variant", "variant", 24),
            reg.Column("model", "model", 5),
            reg.Column("N_col", "N_col", 7, ">", lambda x: f"{x:.0f}"),
            reg.Column("first", "N_col_first", 6, ">", str),
            reg.Column("repeat", "N_col_repeat", 7, ">", str),
            reg.Column("ovlStart", "N_col_overlapStart", 8, ">", str),
            reg.Column("N_agg", "N_agg", 6, ">", lambda x: f"{x:.0f}"),
            reg.Column("first", "N_agg_first", 5, ">", str),
            reg.Column("repeat", "N_agg_repeat", 6, ">", str),
            reg.Column("ovlStart", "N_agg_overlapStart", 8, ">", str),
            reg.Column("a_all/a_th", "alpha_all_over_alpha_th", 10, ">", _f),
            reg.Column("a_first/a_th", "alpha_first_over_alpha_th", 12,
                       ">", _f),
            reg.Column("Np/Np0", "Np_final_over_Np0", 7, ">",
                       lambda x: f"{x:.4f}"),
            reg.Column("time s", "run_time_s", 6, ">", lambda x: _f(x, ".0f"))]
    lines = [f"shearFlowValidation study, preset {res['preset']}: "
             f"alpha_th = {a_th:.4g} (van de Ven & Mason); baseline "
             f"{res['baseline']} (the readings before the study), the "
             f"tutorial's default {res['default']}", ""]
    lines += reg.table(runs, cols)
    srows = []
    for v in res["variants"]:
        s = v["settings"]
        u = v["undisturbedAlphaFirst"]
        srows.append(dict(
            variant=v["name"],
            reading=(f"vE {s['impactVelocityEAM']}/{s['impactVelocityMAM']}"
                     f", torque {s['fluidTorque']}, dt*g {s['dtGamma']:g}"
                     f", tp {s['tangentialProjection']}"
                     f", ovl {s['overlapTreatment']}"),
            **v["statements"],
            uE=u["EAM"] / a_th, uM=u["MAM"] / a_th,
            n=v["undisturbedFirstContacts"]))
    cols = [reg.Column("variant", "variant", 24),
            reg.Column("reading", "reading", 72),
            *[reg.Column(k, k, 4) for k in statements.IDS],
            reg.Column("undisturbed a_first/a_th EAM", "uE", 29, ">", _f),
            reg.Column("MAM", "uM", 6, ">", _f),
            reg.Column("of", "n", 5, ">", str)]
    lines += ["", "The paper's statements (shear.post.statements) and alpha "
              "per first contact on the undisturbed ensemble (the ghost "
              "run's first contacts replayed through the variant's "
              "kernels)", ""] + reg.table(srows, cols)
    for tag, cats in res.get("diagnosis", {}).items():
        run = diagnosed[tag]
        lines += ["", f"Diagnosis {tag} ({run}/EAM, its contacts replayed;"
                  " shear.study.diagnosis): per category the agglomerating"
                  " fraction under each kernel, and Eq. 21 with and without"
                  " its spin term (EAM, v_E = |u_n|)"]
        drows = [dict(cat=c, **r) for c, r in cats.items()]
        dcols = [reg.Column("category", "cat", 12),
                 reg.Column("events", "events", 7, ">", str),
                 reg.Column("EAM |u_n|", "alpha_EAMnormal", 10, ">", _f),
                 reg.Column("EAM |u_r|", "alpha_EAMfull", 10, ">", _f),
                 reg.Column("MAM", "alpha_MAM", 8, ">", _f),
                 reg.Column("Eq21 no spin", "EAMnormal_translationOnly", 13,
                            ">", _f),
                 reg.Column("Eq21", "EAMnormal_withSpin", 8, ">", _f),
                 reg.Column("spin>0", "EAMnormal_spinTermPositive", 7, ">",
                            _f),
                 reg.Column("med |u_n|", "median_abs_un", 10, ">", _f),
                 reg.Column("med |u_t|", "median_utCentres", 10, ">", _f),
                 reg.Column("med |w|", "median_omega", 8, ">", _f)]
        lines += reg.table(drows, dcols)
    lines += ["", "Statements and tolerances (the tolerances of the first"
              " variant; each variant's are in study.json):"]
    for r in res["variants"][0]["statementRows"]:
        lines.append(f"  {r['statement']}: {r['check']} "
                     f"(tolerance {r['tolerance']})")
    return "\n".join(lines)


def plots(res, out, models):
    """study.png: alpha over alpha_th and N_agg of every variant."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    a_th = res["alpha_th"]
    names = [v["name"] for v in res["variants"]]
    x = np.arange(len(names))
    fig, axs = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True)
    ax = axs[0]
    for k, m in enumerate(models):
        c = "C0" if m == "EAM" else "C3"
        a = [v[m]["alpha_all_over_alpha_th"] for v in res["variants"]]
        f = [v[m]["alpha_first_over_alpha_th"] for v in res["variants"]]
        u = [v["undisturbedAlphaFirst"][m] / a_th for v in res["variants"]]
        ax.plot(x + 0.1 * (k - 0.5), a, "o", color=c,
                label=f"{m}: all contacts")
        ax.plot(x + 0.1 * (k - 0.5), f, "s", mfc="none", color=c,
                label=f"{m}: first contacts")
        ax.plot(x + 0.1 * (k - 0.5), u, "x", color=c,
                label=f"{m}: first contacts, undisturbed ensemble")
    ax.axhline(1, color="k", lw=0.8)
    ax.axhspan(*statements.S1_BAND, color="0.9", zorder=0,
               label="S1 band")
    ax.set_yscale("log")
    ax.set_ylabel(r"$\alpha/\alpha_{th}$")
    ax.legend(fontsize=7, ncol=3)
    ax = axs[1]
    for k, m in enumerate(models):
        c = "C0" if m == "EAM" else "C3"
        ax.bar(x + 0.4 * (k - 0.5), [v[m]["N_agg"] for v in
                                     res["variants"]], 0.4, color=c,
               label=f"{m}: N_agg")
    ax.set_ylabel(r"$N_{agg}$")
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=40, ha="right", fontsize=8)
    ax.legend(fontsize=8)
    fig.suptitle(f"shearFlowValidation study, {res['preset']}: "
                 r"$\alpha_{th}$ = " f"{100 * a_th:.2f} %")
    fig.tight_layout()
    fig.savefig(out / "study.png", dpi=110)
    plt.close(fig)
