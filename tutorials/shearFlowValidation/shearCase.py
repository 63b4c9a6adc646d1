"""shearFlowValidation: the runs of the tutorial and the entries of their
system/caseSettings, what the set-up (shearFlow.py) writes and the
post-processing (shearPost.py, shearReplay.py, shearStudy.py) reads."""

from aggloTools import casesettings

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
    """The caseSettings of a run, every entry checked."""
    return casesettings.read_settings(case, SETTINGS_KEYS)
