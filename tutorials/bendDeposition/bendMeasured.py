"""The bend's efficiency against the measurements of Pui, Romay-Novas &
Liu (1987) (bendDeposition; doc/bendDeposition.md, section 2): their
laminar expression of the deposition efficiency of a 90-degree bend
against the Stokes number, the band a row must keep to it, and each
row's verdict.

The comparison is a result, not a gate: a row outside the band prints
FAIL in its own column (`measured`), and the driver's exit status stays
that of the gates (bendEfficiency.judge, the serial comparison)."""

import math

#: Where the expression holds (doc/bendDeposition.md, 2): the flow
#: Reynolds number and the curvature ratio R/a of Pui et al.'s laminar
#: bends
RE = 1000
CURVATURE = 5.6
#: The bend's angle the expression is taken at [rad]
ANGLE = math.pi / 2
#: A row agrees when |eta - eta_Pui| <= BAND + 3 sigma [rec]
BAND = 0.1


def eta_pui(st, angle=ANGLE):
    """Pui et al.'s laminar expression: the deposition efficiency
    1 - P of a bend of `angle` radians at the Stokes number `st` (St =
    rho_p d_p^2 U / (9 mu D)), P = [1 + x^(0.452 x + 2.242)]^(-2 angle /
    pi), x = St / 0.171."""
    if not st >= 0:
        raise ValueError(f"St {st} must be >= 0")
    x = st / 0.171
    return 1.0 - (1.0 + x ** (0.452 * x + 2.242)) ** (-2.0 * angle
                                                      / math.pi)


def not_applicable(re, curvature):
    """Why the expression does not hold for a bend (a text), or None
    where it does."""
    if re != RE:
        return f"n/r (Re {re:g}; the expression is for Re {RE})"
    if curvature != CURVATURE:
        return (f"n/r (R/a {curvature:g}; the expression is for "
                f"R/a {CURVATURE:g})")
    return None


def compare(rows, re, curvature):
    """Each row (St, eta, sigma) against the expression: etaPui and the
    verdict `measured`, PASS where |eta - etaPui| <= BAND + 3 sigma,
    FAIL beyond, n/r with the reason where the expression does not hold
    for the bend. Returns the rows."""
    why = not_applicable(re, curvature)
    for r in rows:
        if why:
            r["measured"] = why
            continue
        r["etaPui"] = eta_pui(r["St"])
        ok = abs(r["eta"] - r["etaPui"]) <= BAND + 3 * r["sigma"]
        r["measured"] = "PASS" if ok else "FAIL"
    return rows


def summary(rows):
    """The table's lines on the comparison (None where no row has one)."""
    judged = [r for r in rows if r.get("measured") in ("PASS", "FAIL")]
    if not judged:
        return None
    out = [r for r in judged if r["measured"] == "FAIL"]
    return ("Pui87: the laminar expression of Pui et al. (1987) at the "
            "row's St (doc/bendDeposition.md); measured: PASS where "
            f"|eta - Pui87| <= {BAND:g} + 3 sigma, FAIL beyond. "
            f"{len(judged) - len(out)} of {len(judged)} within"
            + ("; outside: St " + ", ".join(f"{r['St']:g}" for r in out)
               if out else "")
            + " (a result, not part of the exit status).")
