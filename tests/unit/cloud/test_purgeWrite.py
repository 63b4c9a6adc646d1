"""purgeWrite N keeps the last N writes across restarts too: OpenFOAM
v1912 forgets at a restart the times written before it, so a run resumed
every session kept every write (purgeWriteQueue.H). The run's own start
folder stays, as in an uninterrupted run."""

from aggloTools.runner import foam_bin, run
from aggloTools.times import time_dirs
from cloudBoxCases import primaries_gas as gas


def _set(c, entry, value):
    run([foam_bin("foamDictionary"), "system/controlDict", "-entry", entry,
         "-set", value], c, "log.foamDictionary")


def test_restart_purges_the_earlier_writes(case_dir, foam_env):
    c = gas(case_dir / "gas", log=False, end=6e-4, write=1)
    run([foam_bin("blockMesh")], c, "log.blockMesh")
    _set(c, "purgeWrite", "2")
    run([foam_bin("aggloPimpleFoam")], c, "log.first")
    assert [t.name for t in time_dirs(c)] == ["0", "0.0005", "0.0006"]
    _set(c, "endTime", "0.001")
    run([foam_bin("aggloPimpleFoam")], c, "log.second")
    assert [t.name for t in time_dirs(c)] == ["0", "0.0009", "0.001"]
