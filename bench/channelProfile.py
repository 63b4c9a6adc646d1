"""Where the channel step's time goes: the samples of a `perf record` of
a solver run by part of the step (fluid, LES model, cloud, start-up and
writes) and by function, and their Markdown table
(bench/results/channelProfile.md). bench/channelCosts.py --perf records
the serial runs of each stage and calls these."""

import re
import subprocess


#: The part of the step that a sample belongs to: the first whose
#: function (or else library) pattern matches. The solver binary holds
#: template code of the fluid and of the cloud; start-up (reading and
#: locating the particles, loading libraries) and writes are apart.
PARTS = (
    ("start-up and writes", "sym",
     r"printf_fp|strto|hack_digit|istream|ISstream|OSstream|Istream|"
     r"Ostream|_dl_|do_lookup|clear_page|findTet|findCell|calcCellBb|"
     r"treeDataCell|indexedOctree"),
    ("cloud", "sym",
     r"Cloud|Parcel|particle::|tetIndices|interpolationCellPoint|"
     r"Injection|PairSearch|sweptBoxGrid"),
    ("cloud", "dso", r"agglomerationHardSphere|liblagrangian"),
    ("LES model", "sym", r"FaceCellWave|wallPoint|Smagorinsky|vanDriest"),
    ("LES model", "dso", r"TurbulenceModels|turbulenceModels"),
    ("fluid", "dso",
     r"libfiniteVolume|libOpenFOAM|libmeshTools|aggloPimpleFoam"),
)


def part_of(dso, sym):
    """The part of the step of a sample in dso, function sym."""
    for name, where, pattern in PARTS:
        if re.search(pattern, sym if where == "sym" else dso):
            return name
    return "other"


def profile(case, top=12):
    """Shares of the samples of a perf.data by part of the step and the
    top functions: {part: %}, [(%, library, function)]."""
    out = subprocess.run(["perf", "report", "-i", "perf.data", "--stdio",
                          "--no-children", "--sort", "dso,sym"], cwd=case,
                         capture_output=True, text=True).stdout
    rows = []
    for ln in out.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+(\S+)\s+\[.\]\s+(.*)$", ln)
        if m:
            rows.append((float(m.group(1)), m.group(2), m.group(3).strip()))
    parts = {}
    for pct, dso, sym in rows:
        part = part_of(dso, sym)
        parts[part] = parts.get(part, 0) + pct
    return parts, rows[:top]


def profile_table(res):
    """The profile of each stage as Markdown."""
    lines = ["# Where the channel step's time goes (perf, serial runs)", "",
             "Written by `bench/channelCosts.py --perf`: the samples of"
             " `perf record` of each serial stage run (40 steps of small,"
             " 12 of medium, start-up and the final write included) by part"
             " of the step, then the top functions.", ""]
    for r in res:
        for s in ("unladen", "laden1", "laden2"):
            prof = r.get("np1", {}).get(s, {}).get("profile")
            if not prof:
                continue
            parts, top = prof
            lines += [f"## {r['preset']} ({r['cells']:,} cells, "
                      f"{r['particles']:,} particles), {s}: "
                      f"{r['np1'][s]['step_s']:.3g} s/step under perf", "",
                      "| part | % of samples |", "|---|---|"]
            lines += [f"| {k} | {v:.1f} |" for k, v in
                      sorted(parts.items(), key=lambda kv: -kv[1])]
            lines += ["", "| % | part | library | function |",
                      "|---|---|---|---|"]
            lines += [f"| {p:.1f} | {part_of(d, f)} | {d} | `{f[:60]}` |"
                      for p, d, f in top]
            lines.append("")
    return "\n".join(lines)
